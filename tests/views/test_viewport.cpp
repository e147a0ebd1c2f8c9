// The 3D viewport driven as an artist would: shown under Xvfb, dragged with the mouse, resized,
// and checked through the pixels it draws and the camera it reports.
#include "celform/model/document/document.h"
#include "celform/model/data/io_error.h"
#include "celform/model/io/mesh_io.h"
#include "celform/views/viewport/viewport.h"

// tests/CMakeLists.txt adds <caller>/common to the include path, not tests/common: reach it
// relative to this file until that is fixed.
#include "test_support.h"
#include "test_meshes.h"

#include <QApplication>
#include <QSignalSpy>
#include <QtTest/QtTest>

#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <utility>

using celform::algo::TriMesh;
using celform::model::Camera;
using celform::model::Document;
using celform::model::ProjectData;
using celform::model::Projection;
using celform::views::Viewport;

namespace {

std::shared_ptr<TriMesh> importShared(const QString& relative)
{
    const QString path = celform::test::sharedDataPath(relative);
    if (path.isEmpty())
        return nullptr;
    try {
        return std::make_shared<TriMesh>(celform::model::importMesh(path).mesh);
    } catch (const celform::model::IoError& error) {
        qWarning("%s", qPrintable(error.message()));
        return nullptr;
    }
}

/// The shared bunny, or an icosphere in a clone without ../shared.
std::shared_ptr<TriMesh> testMesh()
{
    if (auto bunny = importShared(QStringLiteral("meshes/npm_bunny.off")))
        return bunny;
    return celform::test::icosphere(3);
}

/// What the model covers in an image: pixels that differ clearly from the background, which is
/// a vertical gradient estimated from the right-hand corners (the axes triad sits bottom left).
struct Coverage {
    double fraction = 0.0;
    QPointF centroid;
};

Coverage coverage(const QImage& source)
{
    const QImage image = source.convertToFormat(QImage::Format_RGB32);
    const int w = image.width(), h = image.height();
    const QColor top = image.pixelColor(w - 1, 0), bottom = image.pixelColor(w - 1, h - 1);
    const int triad = int(0.25 * std::min(w, h));
    long long count = 0;
    double sx = 0.0, sy = 0.0;
    for (int y = 0; y < h; ++y) {
        const double t = h > 1 ? double(y) / (h - 1) : 0.0;
        const double br = top.red() + t * (bottom.red() - top.red());
        const double bg = top.green() + t * (bottom.green() - top.green());
        const double bb = top.blue() + t * (bottom.blue() - top.blue());
        const auto* row = reinterpret_cast<const QRgb*>(image.constScanLine(y));
        for (int x = 0; x < w; ++x) {
            if (x < triad && y >= h - triad)
                continue;
            const QRgb p = row[x];
            const double d = std::max({std::abs(qRed(p) - br), std::abs(qGreen(p) - bg), std::abs(qBlue(p) - bb)});
            if (d > 30.0) {
                ++count;
                sx += x;
                sy += y;
            }
        }
    }
    Coverage c;
    c.fraction = double(count) / (double(w) * h);
    if (count > 0)
        c.centroid = QPointF(sx / count / w, sy / count / h); // in [0, 1] image units
    return c;
}

/// Fraction of pixels that differ between two images of the same size.
double difference(const QImage& a, const QImage& b)
{
    const QImage x = a.convertToFormat(QImage::Format_RGB32), y = b.convertToFormat(QImage::Format_RGB32);
    if (x.size() != y.size())
        return 1.0;
    long long changed = 0;
    for (int r = 0; r < x.height(); ++r) {
        const auto* px = reinterpret_cast<const QRgb*>(x.constScanLine(r));
        const auto* py = reinterpret_cast<const QRgb*>(y.constScanLine(r));
        for (int c = 0; c < x.width(); ++c)
            changed += std::abs(qGray(px[c]) - qGray(py[c])) > 8 ? 1 : 0;
    }
    return double(changed) / (double(x.width()) * x.height());
}

bool isMostlyBlack(const QImage& image)
{
    const QImage small = image.scaled(32, 32).convertToFormat(QImage::Format_RGB32);
    int dark = 0;
    for (int y = 0; y < small.height(); ++y)
        for (int x = 0; x < small.width(); ++x)
            dark += qGray(small.pixel(x, y)) < 16 ? 1 : 0;
    return dark > small.width() * small.height() / 2;
}

/// Qt 6's QTest::mouseMove carries no buttons: a drag needs real move events.
void drag(
    QWidget* widget, Qt::MouseButton button, Qt::KeyboardModifiers modifiers, QPoint from, QPoint to, int steps = 10)
{
    QTest::mousePress(widget, button, modifiers, from);
    for (int i = 1; i <= steps; ++i) {
        const QPointF pos = QPointF(from) + (QPointF(to - from) * i) / steps;
        QMouseEvent move(QEvent::MouseMove, pos, widget->mapToGlobal(pos), Qt::NoButton, button, modifiers);
        QApplication::sendEvent(widget, &move);
    }
    QTest::mouseRelease(widget, button, modifiers, to);
}

double distance(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
    return (a - b).norm();
}

} // namespace

class TestViewport : public QObject {
    Q_OBJECT

private:
    std::unique_ptr<Document> m_doc;
    std::unique_ptr<Viewport> m_view;

    /// Makes the widget draw, and returns the picture once it has.
    QImage frame()
    {
        const int before = m_view->renderCount();
        m_view->update();
        if (!QTest::qWaitFor([&] { return m_view->renderCount() > before; }, 5000))
            qWarning("viewport did not repaint");
        return m_view->renderedImage();
    }

    void checkModelVisible(const QImage& image, double centreTolerance)
    {
        const Coverage c = coverage(image);
        QVERIFY2(c.fraction > 0.05, qPrintable(QStringLiteral("model covers %1 of the image").arg(c.fraction)));
        QVERIFY2(std::abs(c.centroid.x() - 0.5) < centreTolerance && std::abs(c.centroid.y() - 0.5) < centreTolerance,
            qPrintable(QStringLiteral("model centroid at %1, %2").arg(c.centroid.x()).arg(c.centroid.y())));
    }

private slots:
    void initTestCase()
    {
        m_doc = std::make_unique<Document>();
        ProjectData data;
        data.baseMesh = testMesh();
        QVERIFY(data.baseMesh && data.baseMesh->faceCount() > 0);
        m_doc->reset(std::move(data));
        m_view = std::make_unique<Viewport>(m_doc.get());
        m_view->resize(400, 300);
        m_view->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_view.get()));
        QTRY_VERIFY(m_view->renderCount() > 0);
        // The first frame after show: the framed model, never black (docs/pitfalls.md, "VTK in a Qt 6 widget").
        const QImage first = m_view->renderedImage();
        QVERIFY(!isMostlyBlack(first));
        checkModelVisible(first, 0.12);
    }

    void cleanupTestCase()
    {
        m_view.reset();
        m_doc.reset();
    }

    void init()
    {
        m_view->resetView();
        QTRY_VERIFY(m_view->renderCount() > 0);
    }

    void firstFrameShowsTheModel()
    {
        // The very first picture, before any navigation: framed model, never black.
        const QImage image = m_view->renderedImage();
        QVERIFY(!image.isNull());
        QVERIFY(!isMostlyBlack(image));
        checkModelVisible(image, 0.12);
        image.save(QStringLiteral("/tmp/viewport.png"));
    }

    void orbit_data()
    {
        QTest::addColumn<Qt::MouseButton>("button");
        QTest::addColumn<Qt::KeyboardModifiers>("modifiers");
        QTest::newRow("alt+left") << Qt::LeftButton << Qt::KeyboardModifiers(Qt::AltModifier);
        QTest::newRow("middle") << Qt::MiddleButton << Qt::KeyboardModifiers(Qt::NoModifier);
    }

    void orbit()
    {
        QFETCH(Qt::MouseButton, button);
        QFETCH(Qt::KeyboardModifiers, modifiers);
        const QImage before = frame();
        const Camera start = m_view->camera();
        const double radius = distance(start.eye, m_view->pivot());
        QSignalSpy changed(m_view.get(), &Viewport::cameraChanged);

        drag(m_view.get(), button, modifiers, QPoint(200, 150), QPoint(290, 120));
        QVERIFY(changed.count() > 0);
        const Camera moved = m_view->camera();
        QVERIFY(distance(moved.eye, start.eye) > 0.1 * radius);
        QVERIFY(std::abs(distance(moved.eye, m_view->pivot()) - radius) < 1e-6 * radius);
        QVERIFY(moved.isValid());
        // Turntable: the image's horizontal axis stays level.
        QVERIFY(std::abs(moved.right().y()) < 1e-6);

        const QImage after = frame();
        QVERIFY(!isMostlyBlack(after));
        QVERIFY2(difference(before, after) > 0.02, "the picture did not change");
        checkModelVisible(after, 0.15);
        if (button == Qt::LeftButton)
            after.save(QStringLiteral("/tmp/viewport_orbit.png"));
    }

    void orbitNeverFlips()
    {
        // Dragging far down must stop just short of looking straight down, never past it.
        drag(m_view.get(), Qt::MiddleButton, Qt::NoModifier, QPoint(200, 20), QPoint(200, 290), 5);
        drag(m_view.get(), Qt::MiddleButton, Qt::NoModifier, QPoint(200, 20), QPoint(200, 290), 5);
        const Camera c = m_view->camera();
        QVERIFY(c.isValid());
        const double elevation = std::asin(-c.forward().y()) * 180.0 / M_PI;
        QVERIFY2(elevation > 80.0 && elevation < 89.5, qPrintable(QString::number(elevation)));
        QVERIFY(c.trueUp().y() > 0.0);
    }

    void pan_data()
    {
        QTest::addColumn<Qt::MouseButton>("button");
        QTest::addColumn<Qt::KeyboardModifiers>("modifiers");
        QTest::newRow("alt+middle") << Qt::MiddleButton << Qt::KeyboardModifiers(Qt::AltModifier);
        QTest::newRow("shift+middle") << Qt::MiddleButton << Qt::KeyboardModifiers(Qt::ShiftModifier);
    }

    void pan()
    {
        QFETCH(Qt::MouseButton, button);
        QFETCH(Qt::KeyboardModifiers, modifiers);
        const Camera start = m_view->camera();
        QSignalSpy changed(m_view.get(), &Viewport::cameraChanged);
        drag(m_view.get(), button, modifiers, QPoint(200, 150), QPoint(260, 150));
        QVERIFY(changed.count() > 0);
        const Camera moved = m_view->camera();
        QVERIFY(distance(moved.target, start.target) > 1e-3 * distance(start.eye, start.target));
        // A pan translates: direction and distance stay.
        QVERIFY((moved.forward() - start.forward()).norm() < 1e-9);
        QVERIFY(std::abs(distance(moved.eye, moved.target) - distance(start.eye, start.target)) < 1e-9);
        // Dragging right moves the model right, so the camera goes left.
        QVERIFY((moved.target - start.target).dot(start.right()) < 0.0);
        const Coverage c = coverage(frame());
        QVERIFY2(c.centroid.x() > 0.55, qPrintable(QString::number(c.centroid.x())));
    }

    void dolly_data()
    {
        QTest::addColumn<Qt::MouseButton>("button");
        QTest::addColumn<Qt::KeyboardModifiers>("modifiers");
        QTest::newRow("alt+right") << Qt::RightButton << Qt::KeyboardModifiers(Qt::AltModifier);
        QTest::newRow("ctrl+middle") << Qt::MiddleButton << Qt::KeyboardModifiers(Qt::ControlModifier);
    }

    void dolly()
    {
        QFETCH(Qt::MouseButton, button);
        QFETCH(Qt::KeyboardModifiers, modifiers);
        const Camera start = m_view->camera();
        const double before = distance(start.eye, m_view->pivot());
        QSignalSpy changed(m_view.get(), &Viewport::cameraChanged);
        drag(m_view.get(), button, modifiers, QPoint(150, 150), QPoint(250, 150)); // right: closer
        QVERIFY(changed.count() > 0);
        const Camera closer = m_view->camera();
        QVERIFY(distance(closer.eye, m_view->pivot()) < 0.9 * before);
        QVERIFY((closer.forward() - start.forward()).norm() < 1e-9);
        drag(m_view.get(), button, modifiers, QPoint(250, 150), QPoint(50, 150)); // left: away
        QVERIFY(distance(m_view->camera().eye, m_view->pivot()) > before);
    }

    void wheelDolly()
    {
        const double before = distance(m_view->camera().eye, m_view->pivot());
        QSignalSpy changed(m_view.get(), &Viewport::cameraChanged);
        const QPointF pos(200, 150);
        QWheelEvent wheel(pos, m_view->mapToGlobal(pos), QPoint(), QPoint(0, 240), Qt::NoButton, Qt::NoModifier,
            Qt::NoScrollPhase, false);
        QApplication::sendEvent(m_view.get(), &wheel);
        QCOMPARE(changed.count(), 1);
        const double after = distance(m_view->camera().eye, m_view->pivot());
        QVERIFY(after < 0.8 * before);
        checkModelVisible(frame(), 0.15);
    }

    void frameAllRestoresTheView()
    {
        const Camera framed = m_view->camera();
        drag(m_view.get(), Qt::MiddleButton, Qt::ShiftModifier, QPoint(200, 150), QPoint(380, 290));
        drag(m_view.get(), Qt::MiddleButton, Qt::ControlModifier, QPoint(100, 150), QPoint(300, 150));
        QVERIFY(distance(m_view->camera().target, framed.target) > 0.0);
        m_view->setFocus();
        QTest::keyClick(m_view.get(), Qt::Key_F);
        const Camera refit = m_view->camera();
        QVERIFY(distance(refit.target, framed.target) < 1e-9 * (1.0 + framed.target.norm()));
        QVERIFY(std::abs(distance(refit.eye, refit.target) - distance(framed.eye, framed.target))
            < 1e-9 * distance(framed.eye, framed.target));
        checkModelVisible(frame(), 0.12);

        // Home goes back to the front view after an orbit.
        drag(m_view.get(), Qt::LeftButton, Qt::AltModifier, QPoint(200, 150), QPoint(300, 100));
        QTest::keyClick(m_view.get(), Qt::Key_Home);
        QVERIFY((m_view->camera().forward() - Eigen::Vector3d(0, 0, -1)).norm() < 1e-9);
    }

    void cameraRoundTrip_data()
    {
        QTest::addColumn<int>("projection");
        QTest::newRow("perspective") << int(Projection::Perspective);
        QTest::newRow("orthographic") << int(Projection::Orthographic);
    }

    void cameraRoundTrip()
    {
        QFETCH(int, projection);
        Camera c = m_view->camera();
        c.eye += Eigen::Vector3d(0.3, 0.7, 0.2) * distance(c.eye, c.target);
        c.projection = Projection(projection);
        c.fovYDegrees = 40.0;
        c.orthoHeight = 1.5 * distance(c.eye, c.target);
        QSignalSpy changed(m_view.get(), &Viewport::cameraChanged);
        m_view->setCamera(c);
        QCOMPARE(changed.count(), 1);
        const Camera back = m_view->camera();
        QVERIFY(distance(back.eye, c.eye) < 1e-9);
        QVERIFY(distance(back.target, c.target) < 1e-9);
        QVERIFY((back.trueUp() - c.trueUp()).norm() < 1e-9);
        QCOMPARE(back.projection, c.projection);
        QVERIFY(std::abs(back.fovYDegrees - c.fovYDegrees) < 1e-9);
        QVERIFY(std::abs(back.orthoHeight - c.orthoHeight) < 1e-9);
        QVERIFY(!isMostlyBlack(frame()));
        m_view->setProjection(Projection::Perspective);
    }

    void orthographicFrameAll()
    {
        m_view->setProjection(Projection::Orthographic);
        m_view->frameAll();
        checkModelVisible(frame(), 0.12);
        m_view->setProjection(Projection::Perspective);
    }

    void resize()
    {
        m_view->resize(520, 260);
        QTRY_COMPARE(m_view->size(), QSize(520, 260));
        const QImage image = frame();
        const qreal dpr = m_view->devicePixelRatioF();
        QCOMPARE(image.size(), QSize(qRound(520 * dpr), qRound(260 * dpr)));
        QVERIFY(!isMostlyBlack(image));
        checkModelVisible(image, 0.12); // a framed view stays framed while resizing
        m_view->resize(400, 300);
        QTRY_COMPARE(m_view->size(), QSize(400, 300));
        QVERIFY(!isMostlyBlack(frame()));
    }

    void meshChangeRebuilds()
    {
        // Replacing the whole document frames the new model.
        ProjectData data;
        auto sphere = celform::test::icosphere(2);
        sphere->vertices.array() *= 50.0f;
        data.baseMesh = sphere;
        m_doc->reset(std::move(data));
        checkModelVisible(frame(), 0.08);
        // And a document without a mesh shows the empty scene, not black.
        m_doc->reset(ProjectData{});
        const QImage empty = frame();
        QVERIFY(!isMostlyBlack(empty));
        QVERIFY(coverage(empty).fraction < 0.05);
        ProjectData back;
        back.baseMesh = testMesh();
        m_doc->reset(std::move(back));
    }

    void largeMeshRebuilds()
    {
        // The shared dragon, 871k triangles: a document reset and a mesh edit both rebuild its
        // polydata, and the model is drawn framed. How long that takes is measured by
        // tests/benchmarks/bench_viewport (BM_DragonReset, BM_DragonResetToFirstFrame,
        // BM_DragonMeshRebuild), not asserted here.
        CELFORM_REQUIRE_SHARED(path, QStringLiteral("meshes/stanford_dragon.ply"));
        auto dragon = importShared(QStringLiteral("meshes/stanford_dragon.ply"));
        QVERIFY(dragon && dragon->faceCount() == 871414);
        ProjectData data;
        data.baseMesh = dragon;
        m_doc->reset(std::move(data)); // the viewport rebuilds on a reset
        checkModelVisible(frame(), 0.15);
        // A mesh edit alone: only the polydata is rebuilt.
        celform::model::ChangeSet meshChange = celform::model::ChangeSet::of(celform::model::Part::Mesh);
        meshChange.structure = true;
        emit m_doc->changed(meshChange);
        const QImage image = frame();
        checkModelVisible(image, 0.15);
        image.save(QStringLiteral("/tmp/viewport_dragon.png"));
        ProjectData back;
        back.baseMesh = testMesh();
        m_doc->reset(std::move(back));
    }
};

int main(int argc, char** argv)
{
    // VTK needs an OpenGL 3.2 core context; it must be the default before QApplication exists.
    QSurfaceFormat::setDefaultFormat(Viewport::defaultFormat());
    QApplication app(argc, argv);
    TestViewport test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_viewport.moc"
