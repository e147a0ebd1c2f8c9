// Helpers of the UI tests: the bundled sample, waiting for a frame, mouse drags with buttons held
// (QTest::mouseMove carries no buttons in Qt 6), and screenshots kept for looking at by eye.
#pragma once

#include "test_meshes.h"

#include "celform/algorithms/tri_mesh.h"
#include "celform/views/viewport/viewport.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QtTest/QtTest>

namespace celform::test {

inline QString sampleProject()
{
    return QStringLiteral(CELFORM_SOURCE_DIR "/resources/samples/elephant-plain.celform");
}

/// Asks for a frame and waits (up to 5 s) until the viewport has drawn it.
inline void waitForRender(views::Viewport* viewport)
{
    const int before = viewport->renderCount();
    viewport->update();
    QElapsedTimer timer;
    timer.start();
    while (viewport->renderCount() <= before && timer.elapsed() < 5000)
        QTest::qWait(10);
}

/// Turns the viewport to the elephant's side (a little above, along +Z, framed by its bounding box),
/// waits for the frame, and returns where its hind-leg vertex (elephantHindLegVertex) lands in the
/// widget, for a drag on it.
inline QPoint aimAtElephantHindLeg(views::Viewport* viewport, const algo::TriMesh& mesh)
{
    const Eigen::AlignedBox3d box = algo::boundingBox(mesh.vertices);
    model::Camera side;
    side.target = box.center();
    side.eye = box.center() + Eigen::Vector3d(0.0, 0.1, 2.5) * box.diagonal().norm();
    side.up = Eigen::Vector3d::UnitY();
    viewport->setCamera(side);
    waitForRender(viewport);
    const std::uint32_t leg = elephantHindLegVertex(mesh);
    return viewport->projectToWidget(mesh.vertices.row(leg).transpose().cast<double>()).toPoint();
}

/// A press, `steps` moves with the button held, and a release.
inline void drag(QWidget* w, Qt::MouseButton button, Qt::KeyboardModifiers mods, QPoint from, QPoint to, int steps = 10)
{
    QMouseEvent press(QEvent::MouseButtonPress, from, w->mapToGlobal(from), button, button, mods);
    QApplication::sendEvent(w, &press);
    for (int i = 1; i <= steps; ++i) {
        const QPoint p = from + (to - from) * i / steps;
        QMouseEvent move(QEvent::MouseMove, p, w->mapToGlobal(p), Qt::NoButton, button, mods);
        QApplication::sendEvent(w, &move);
    }
    QMouseEvent release(QEvent::MouseButtonRelease, to, w->mapToGlobal(to), button, Qt::NoButton, mods);
    QApplication::sendEvent(w, &release);
}

/// Holds a key on a control: one press, the repeats a held key sends, one release (one gesture).
inline void holdKey(QWidget* w, Qt::Key key, int repeats)
{
    QKeyEvent press(QEvent::KeyPress, key, Qt::NoModifier);
    QApplication::sendEvent(w, &press);
    for (int i = 0; i < repeats; ++i) {
        QKeyEvent repeat(QEvent::KeyPress, key, Qt::NoModifier, QString(), true);
        QApplication::sendEvent(w, &repeat);
    }
    QKeyEvent release(QEvent::KeyRelease, key, Qt::NoModifier);
    QApplication::sendEvent(w, &release);
}

/// Saves a picture of a widget when CELFORM_SCREENSHOT_DIR is set.
inline void keepScreenshot(QWidget* widget, const char* name)
{
    const QString dir = qEnvironmentVariable("CELFORM_SCREENSHOT_DIR");
    if (!dir.isEmpty())
        widget->grab().save(dir + QLatin1Char('/') + QLatin1String(name) + QStringLiteral(".png"));
}

} // namespace celform::test
