// The Highlights dock driven as an artist would: a layer added with the panel's buttons, epsilon
// keyed at two frames through the timeline, the interpolated value between them, undo, key and
// layer removal; after each step the document's Look::highlights and its save/load round trip.
#include "celform/model/document/document.h"
#include "celform/model/io/project_file.h"
#include "celform/views/timeline/frame_timeline.h"
#include "celform/views/panels/highlight_panel.h"

#include "test_meshes.h"
#include "ui_test_support.h"

#include <QApplication>
#include <QDoubleSpinBox>
#include <QListWidget>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStyleFactory>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest/QtTest>

#include <cmath>
#include <memory>

using celform::algo::TriMesh;
using celform::model::Document;
using celform::model::Look;
using celform::views::FrameTimeline;
using celform::views::HighlightPanel;

using celform::test::octahedron;

class TestHighlightPanel : public QObject {
    Q_OBJECT

    std::unique_ptr<Document> m_doc;
    std::unique_ptr<HighlightPanel> m_panel;
    QTemporaryDir m_dir;

    template <typename W> W* child(const char* name)
    {
        QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete); // rows rebuilt by refresh
        auto* w = m_panel->findChild<W*>(QString::fromLatin1(name));
        if (!w)
            qFatal("no child %s", name);
        return w;
    }

    /// The look survives a save and a load unchanged.
    void checkRoundTrip()
    {
        const QString path = m_dir.filePath(QStringLiteral("round_trip.celform"));
        celform::model::saveProject(m_doc->data(), path, false);
        const Look loaded = celform::model::loadProject(path).look;
        QVERIFY(loaded == m_doc->data().look);
    }

    void setEpsilon(double value)
    {
        auto* spin = child<QDoubleSpinBox>("highlightEpsilon");
        spin->setValue(value); // keyboard tracking is off: one valueChanged, as after typing + Enter
    }

private slots:
    void init()
    {
        QVERIFY(m_dir.isValid());
        m_doc = std::make_unique<Document>();
        auto data = celform::model::newProject(octahedron(), QStringLiteral("octahedron.obj"));
        data.faceSets.push_back({"upper", {0, 1, 2, 3}});
        m_doc->reset(std::move(data));
        m_panel = std::make_unique<HighlightPanel>(m_doc.get());
        m_panel->resize(360, 760);
        m_panel->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_panel.get()));
    }

    void cleanup()
    {
        m_panel.reset();
        m_doc.reset();
    }

    // The key strip shows the scene's range (it said "of 48" over frames 0-47), and no number is
    // cut by a squeezed spin box.
    void followsTheSceneRangeAndShowsWholeNumbers()
    {
        QCOMPARE(child<QSpinBox>("highlightLastFrame")->value(), 47);
        QCOMPARE(child<QSpinBox>("highlightFrame")->maximum(), 47);
        celform::model::SceneTime time = m_doc->data().time;
        time.firstFrame = 10;
        time.lastFrame = 99;
        m_doc->animation().setSceneTime(time);
        QCOMPARE(child<QSpinBox>("highlightLastFrame")->value(), 99);
        QCOMPARE(child<QSpinBox>("highlightFrame")->minimum(), 10);
        QCOMPARE(child<QSpinBox>("highlightFrame")->maximum(), 99);
        m_doc->undoStack()->undo();
        QCOMPARE(child<QSpinBox>("highlightLastFrame")->value(), 47);

        QTest::mouseClick(child<QPushButton>("addHighlightLayer"), Qt::LeftButton);
        QTest::qWait(20);
        int checked = 0;
        for (QDoubleSpinBox* spin : m_panel->findChildren<QDoubleSpinBox*>()) {
            if (!spin->isVisibleTo(m_panel.get()))
                continue;
            ++checked;
            QVERIFY2(spin->width() >= spin->minimumSizeHint().width(),
                qPrintable(spin->objectName()
                    + QStringLiteral(": %1 < %2").arg(spin->width()).arg(spin->minimumSizeHint().width())));
        }
        QVERIFY(checked >= 5);
    }

    void keysThroughTheTimeline()
    {
        const auto& tracks = m_doc->data().look.highlights;
        QVERIFY(tracks.empty());
        QSignalSpy changes(m_doc.get(), &Document::changed);

        // Add a layer: one key at frame 0 with the default layer.
        QTest::mouseClick(child<QPushButton>("addHighlightLayer"), Qt::LeftButton);
        QCOMPARE(tracks.size(), std::size_t(1));
        QCOMPARE(m_panel->selectedLayer(), 0);
        QVERIFY(!tracks[0].name.isEmpty());
        QCOMPARE(tracks[0].keys.size(), std::size_t(1));
        QCOMPARE(tracks[0].keys[0].frame, 0.0);
        QCOMPARE(child<QListWidget>("highlightLayers")->item(0)->text(), tracks[0].name);
        checkRoundTrip();
        const int afterAdd = m_doc->undoStack()->index();

        // Epsilon at frame 0 replaces the key there.
        setEpsilon(0.1);
        QCOMPARE(tracks[0].keys.size(), std::size_t(1));
        QCOMPARE(tracks[0].keys[0].layer.shape.epsilon, 0.1f);
        QCOMPARE(m_doc->undoStack()->index(), afterAdd + 1); // its own undo step
        checkRoundTrip();

        // Holding the spin box's Up key (a press and its repeats) is one undo step of its own.
        celform::test::holdKey(child<QDoubleSpinBox>("highlightEpsilon"), Qt::Key_Up, 2);
        QCOMPARE(m_doc->undoStack()->index(), afterAdd + 2);
        QVERIFY(tracks[0].keys[0].layer.shape.epsilon > 0.125f); // three steps or more (Qt may accelerate)
        m_doc->undoStack()->undo(); // the whole hold at once
        QCOMPARE(tracks[0].keys[0].layer.shape.epsilon, 0.1f);
        QCOMPARE(m_doc->undoStack()->index(), afterAdd + 1);
        // Each step of the hold was one change notification.
        changes.clear();
        setEpsilon(0.1); // no change: no step, no notification
        QCOMPARE(changes.count(), 0);

        // Frame 30 through the frame spin box, then a second epsilon: a second key.
        child<QSpinBox>("highlightFrame")->setValue(30);
        QCOMPARE(m_panel->currentFrame(), 30);
        QCOMPARE(m_doc->currentFrame(), 30); // the document's playhead
        QCOMPARE(changes.count(), 1);
        QVERIFY(changes.last().at(0).value<celform::model::ChangeSet>().onlyPlayhead());
        QCOMPARE(child<QDoubleSpinBox>("highlightEpsilon")->value(), 0.1); // held after the last key
        setEpsilon(0.3);
        QCOMPARE(tracks[0].keys.size(), std::size_t(2));
        QCOMPARE(tracks[0].keys[0].frame, 0.0);
        QCOMPARE(tracks[0].keys[0].layer.shape.epsilon, 0.1f);
        QCOMPARE(tracks[0].keys[1].frame, 30.0);
        QCOMPARE(tracks[0].keys[1].layer.shape.epsilon, 0.3f);
        QCOMPARE(m_doc->undoStack()->index(), afterAdd + 2);
        checkRoundTrip();

        // Frame 15 by clicking the timeline: the panel shows the mean of the two keys.
        FrameTimeline* timeline = m_panel->timeline();
        QTest::mouseClick(timeline, Qt::LeftButton, {}, QPoint(timeline->xForFrame(15), timeline->height() / 2));
        QCOMPARE(m_panel->currentFrame(), 15);
        QCOMPARE(child<QSpinBox>("highlightFrame")->value(), 15);
        QVERIFY(std::abs(child<QDoubleSpinBox>("highlightEpsilon")->value() - 0.2) < 1e-3);
        QVERIFY(!child<QPushButton>("highlightDeleteKey")->isEnabled()); // no key at 15

        // Undo removes the second key only.
        m_doc->undoStack()->undo();
        QCOMPARE(tracks.size(), std::size_t(1));
        QCOMPARE(tracks[0].keys.size(), std::size_t(1));
        QCOMPARE(tracks[0].keys[0].layer.shape.epsilon, 0.1f);
        QVERIFY(std::abs(child<QDoubleSpinBox>("highlightEpsilon")->value() - 0.1) < 1e-6);
        checkRoundTrip();
        m_doc->undoStack()->redo();
        QCOMPARE(tracks[0].keys.size(), std::size_t(2));

        // Key at 15 writes the interpolated layer; Delete Key removes it again.
        QTest::mouseClick(child<QPushButton>("highlightKey"), Qt::LeftButton);
        QCOMPARE(tracks[0].keys.size(), std::size_t(3));
        QCOMPARE(tracks[0].keys[1].frame, 15.0);
        QVERIFY(std::abs(tracks[0].keys[1].layer.shape.epsilon - 0.2f) < 1e-6f);
        checkRoundTrip();
        QVERIFY(child<QPushButton>("highlightDeleteKey")->isEnabled());
        QTest::mouseClick(child<QPushButton>("highlightDeleteKey"), Qt::LeftButton);
        QCOMPARE(tracks[0].keys.size(), std::size_t(2));
        QCOMPARE(tracks[0].keys[1].frame, 30.0);
        checkRoundTrip();

        // Delete Key at 30, then the last key stays.
        child<QSpinBox>("highlightFrame")->setValue(30);
        QTest::mouseClick(child<QPushButton>("highlightDeleteKey"), Qt::LeftButton);
        QCOMPARE(tracks[0].keys.size(), std::size_t(1));
        QCOMPARE(tracks[0].keys[0].frame, 0.0);
        checkRoundTrip();
        child<QSpinBox>("highlightFrame")->setValue(0);
        QVERIFY(!child<QPushButton>("highlightDeleteKey")->isEnabled());
        QTest::mouseClick(child<QPushButton>("highlightDeleteKey"), Qt::LeftButton);
        QCOMPARE(tracks[0].keys.size(), std::size_t(1));

        // Remove the layer; undo brings it back with its key.
        const Look before = m_doc->data().look;
        QTest::mouseClick(child<QPushButton>("removeHighlightLayer"), Qt::LeftButton);
        QVERIFY(tracks.empty());
        QCOMPARE(child<QListWidget>("highlightLayers")->count(), 0);
        checkRoundTrip();
        m_doc->undoStack()->undo();
        QVERIFY(m_doc->data().look == before);
        QCOMPARE(child<QListWidget>("highlightLayers")->count(), 1);
    }

    void operationsAndCombinations()
    {
        QTest::mouseClick(child<QPushButton>("addHighlightLayer"), Qt::LeftButton);
        QTest::mouseClick(child<QPushButton>("addHighlightLayer"), Qt::LeftButton);
        const auto& tracks = m_doc->data().look.highlights;
        m_panel->selectLayer(0);
        setEpsilon(0.08);
        child<QSpinBox>("highlightFrame")->setValue(24);
        setEpsilon(0.15);
        QCOMPARE(tracks[0].keys.size(), std::size_t(2));
        auto trigger = [this](const QString& text) {
            for (QAction* a : m_panel->findChildren<QAction*>())
                if (a->text() == text) {
                    a->trigger();
                    return;
                }
            QFAIL("no such action");
        };
        trigger(QStringLiteral("Translate"));
        trigger(QStringLiteral("Square"));
        for (const auto& k : tracks[0].keys) { // structure changes reach every key
            QCOMPARE(k.layer.shape.operations.size(), std::size_t(2));
            QCOMPARE(k.layer.shape.operations[1].type, celform::algo::HighlightOperationType::Squaring);
        }
        // An operation parameter keys the current frame only.
        child<QDoubleSpinBox>("highlightOperation0a")->setValue(0.4);
        QCOMPARE(tracks[0].keys[1].layer.shape.operations[0].a, 0.4f);
        QCOMPARE(tracks[0].keys[0].layer.shape.operations[0].a, 0.f);
        child<QSpinBox>("highlightFrame")->setValue(12);
        QVERIFY(std::abs(child<QDoubleSpinBox>("highlightOperation0a")->value() - 0.2) < 1e-3);
        QTest::mouseClick(child<QPushButton>("addHighlightCombination"), Qt::LeftButton);
        QCOMPARE(tracks[0].combineWith.size(), std::size_t(1));
        QCOMPARE(tracks[0].combineWith[0].second, tracks[1].name);
        checkRoundTrip();
        // Removing the other layer drops the combination with it.
        m_panel->selectLayer(1);
        QTest::mouseClick(child<QPushButton>("removeHighlightLayer"), Qt::LeftButton);
        QCOMPARE(tracks.size(), std::size_t(1));
        QVERIFY(tracks[0].combineWith.empty());
        m_doc->undoStack()->undo();
        QCOMPARE(tracks.size(), std::size_t(2));
        m_panel->selectLayer(0);
        const QString shot = qEnvironmentVariable("CELFORM_HIGHLIGHT_PANEL_SHOT");
        if (!shot.isEmpty())
            QVERIFY(m_panel->grab().save(shot));
    }

    void renameAndVisibility()
    {
        QTest::mouseClick(child<QPushButton>("addHighlightLayer"), Qt::LeftButton);
        QTest::mouseClick(child<QPushButton>("addHighlightLayer"), Qt::LeftButton);
        const auto& tracks = m_doc->data().look.highlights;
        QCOMPARE(tracks.size(), std::size_t(2));
        QCOMPARE(m_panel->selectedLayer(), 1);
        QListWidgetItem* item = child<QListWidget>("highlightLayers")->item(1);
        item->setText(QStringLiteral("rim"));
        QCOMPARE(tracks[1].name, QStringLiteral("rim"));
        item->setText(tracks[0].name); // a duplicate name is refused
        QCOMPARE(tracks[1].name, QStringLiteral("rim"));
        QCOMPARE(item->text(), QStringLiteral("rim"));
        item->setCheckState(Qt::Unchecked);
        QVERIFY(!tracks[1].visible);
        checkRoundTrip();
    }
};

int main(int argc, char** argv)
{
    // Plain widgets: the offscreen platform needs no X server.
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    QApplication::setStyle(QStyleFactory::create(QStringLiteral("Fusion")));
    TestHighlightPanel test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_highlight_panel.moc"
