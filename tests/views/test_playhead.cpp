// One playhead (DESIGN.md, "The document"): the viewport shows the document at the current frame
// exactly as the offline renderer renders that frame, its brush writes at that frame starting from
// what it shows, and a hidden viewport does no work while the document changes.
#include "celform/algorithms/image.h"
#include "celform/algorithms/shading.h"
#include "celform/model/document/document.h"
#include "celform/model/render/render_output.h"
#include "celform/views/viewport/viewport.h"
#include "celform/views/tools/brush_size.h"
#include "celform/views/tools/brush_tool.h"
#include "celform/views/viewport/viewport_display.h"

#include "test_meshes.h"
#include "ui_test_support.h"

#include <QApplication>
#include <QSignalSpy>
#include <QtTest/QtTest>

#include <cmath>
#include <memory>

using celform::algo::Positions;
using celform::model::Camera;
using celform::model::ChangeSet;
using celform::model::Document;
using celform::model::KeyViewpoint;
using celform::model::ObjectId;
using celform::model::ProjectData;
using celform::model::SparseOffsets;
using celform::views::Viewport;

namespace {

constexpr int kSize = 360;

Camera frontCamera()
{
    Camera c;
    c.eye = Eigen::Vector3d(0.0, 0.0, 5.5);
    c.target = Eigen::Vector3d::Zero();
    c.up = Eigen::Vector3d::UnitY();
    c.fovYDegrees = 30.0;
    return c;
}

int encode8(float linear)
{
    return int(std::lround(celform::algo::linearToSrgb(std::clamp(linear, 0.f, 1.f)) * 255.f));
}

/// Offsets that pull the upper half of the sphere sideways by amount (x), more near the top.
SparseOffsets pullTop(const Positions& base, float amount)
{
    SparseOffsets o;
    for (Eigen::Index v = 0; v < base.rows(); ++v)
        if (base(v, 1) > 0.3f) {
            o.indices.push_back(std::uint32_t(v));
            o.deltas.emplace_back(amount * base(v, 1), 0.f, 0.f);
        }
    return o;
}

/// Pixels that differ from the background by more than a few levels.
std::vector<char> modelMask(const QImage& image, QRgb background)
{
    std::vector<char> mask(std::size_t(image.width() * image.height()));
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QRgb p = image.pixel(x, y);
            mask[std::size_t(y * image.width() + x)] = std::abs(qRed(p) - qRed(background)) > 6
                || std::abs(qGreen(p) - qGreen(background)) > 6 || std::abs(qBlue(p) - qBlue(background)) > 6;
        }
    return mask;
}

double intersectionOverUnion(const std::vector<char>& a, const std::vector<char>& b)
{
    std::size_t both = 0, either = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        both += a[i] && b[i];
        either += a[i] || b[i];
    }
    return either ? double(both) / double(either) : 1.0;
}

} // namespace

class TestPlayhead : public QObject {
    Q_OBJECT

    std::unique_ptr<Document> m_doc;
    std::unique_ptr<Viewport> m_view;
    ObjectId m_key = 0;

    QImage frame()
    {
        celform::test::waitForRender(m_view.get());
        return m_view->renderedImage().convertToFormat(QImage::Format_RGB32);
    }

    /// What `celform render --frame F` writes through the viewport's camera (8-bit).
    QImage rendered(int frameNumber)
    {
        const ProjectData& data = m_doc->data();
        celform::model::BlendEvaluator blender;
        blender.update(data);
        const Camera camera = m_view->camera();
        Positions shape;
        blender.shape(data, blender.viewDirection(data, camera.eye, frameNumber), frameNumber, shape);
        celform::algo::RenderCache cache;
        const auto passes = celform::model::renderShape(
            data, data.look, shape, frameNumber, camera, kSize, kSize, celform::algo::StereoOutput::Off, cache);
        QImage image(kSize, kSize, QImage::Format_RGB32);
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                const float* p = passes.beauty.at(x, y);
                image.setPixel(x, y, qRgb(encode8(p[0]), encode8(p[1]), encode8(p[2])));
            }
        return image;
    }

    QRgb background() const
    {
        const Eigen::Vector3f bg = m_doc->data().look.backgroundColor;
        return qRgb(encode8(bg.x()), encode8(bg.y()), encode8(bg.z()));
    }

private slots:
    void init()
    {
        // A sphere with one key seen from the front, deformed at frames 0 (not at all) and 10
        // (the top pulled sideways): between them the shape moves with the frame.
        auto sphere = celform::test::icosphere(4);
        ProjectData data = celform::model::newProject(sphere, QStringLiteral("sphere.obj"));
        data.look.showLines = false;
        KeyViewpoint key;
        key.id = data.nextId++;
        key.name = QStringLiteral("front");
        key.camera = frontCamera();
        key.direction = Eigen::Vector3d::UnitZ();
        key.offsetsByFrame[0] = SparseOffsets{};
        key.offsetsByFrame[10] = pullTop(sphere->vertices, 0.8f);
        data.keys.push_back(key);
        m_key = key.id;
        m_doc = std::make_unique<Document>();
        m_doc->reset(std::move(data));
        m_view = std::make_unique<Viewport>(m_doc.get());
        m_view->display().setLightGizmoVisible(false);
        m_view->resize(kSize, kSize);
        m_view->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_view.get()));
        m_view->setCamera(frontCamera());
        frame();
    }

    void cleanup()
    {
        m_view.reset();
        m_doc.reset();
    }

    void viewportAtFrameShowsWhatTheRendererRenders_data()
    {
        QTest::addColumn<bool>("preview");
        QTest::newRow("preview (the blend)") << true;
        QTest::newRow("the key itself") << false;
    }

    void viewportAtFrameShowsWhatTheRendererRenders()
    {
        QFETCH(bool, preview);
        if (preview)
            m_view->setPreview(true);
        else
            m_view->setDisplayedKey(m_key);
        const QImage atZero = rendered(0);
        m_doc->setCurrentFrame(5);
        const QImage viewport = frame();
        const QImage atFive = rendered(5);
        viewport.save(QStringLiteral("/tmp/playhead_viewport_5.png"));
        atFive.save(QStringLiteral("/tmp/playhead_render_5.png"));
        // The frames differ where it matters: the top is pulled half way at 5.
        const double moved = intersectionOverUnion(modelMask(atZero, background()), modelMask(atFive, background()));
        QVERIFY2(moved < 0.97, qPrintable(QStringLiteral("frames 0 and 5 overlap %1").arg(moved)));
        // The viewport at 5 is the render at 5: same silhouette, same colours inside.
        const auto maskView = modelMask(viewport, background());
        const auto maskRender = modelMask(atFive, background());
        const double overlap = intersectionOverUnion(maskView, maskRender);
        QVERIFY2(overlap > 0.995, qPrintable(QStringLiteral("viewport vs render at 5: overlap %1").arg(overlap)));
        double difference = 0.0;
        int count = 0;
        for (int y = 1; y < kSize - 1; ++y)
            for (int x = 1; x < kSize - 1; ++x) {
                // Inside the model on both, away from the silhouette.
                bool inside = true;
                for (int d = -1; d <= 1 && inside; ++d)
                    inside = maskView[std::size_t((y + d) * kSize + x)] && maskRender[std::size_t(y * kSize + x + d)];
                if (!inside)
                    continue;
                const QRgb a = viewport.pixel(x, y), b = atFive.pixel(x, y);
                difference
                    += std::abs(qRed(a) - qRed(b)) + std::abs(qGreen(a) - qGreen(b)) + std::abs(qBlue(a) - qBlue(b));
                ++count;
            }
        QVERIFY(count > 1000);
        const double mean = difference / (3.0 * count);
        QVERIFY2(mean < 2.0, qPrintable(QStringLiteral("mean difference %1 levels").arg(mean)));
    }

    void brushWritesAtThePlayheadFromWhatItShows()
    {
        // Paper 1, section 4.2: at frame 5 the key shows the offsets interpolated between 0 and 10.
        m_doc->setCurrentFrame(5);
        m_view->setDisplayedKey(m_key);
        m_view->setTool(Viewport::Tool::Brush);
        m_view->tool<celform::views::BrushTool>().size().setRadius(0.6);
        frame();
        const KeyViewpoint before = *m_doc->data().key(m_key);
        const Positions shown = m_view->displayedShape();
        QVERIFY(shown == m_doc->data().keyShape(before, 5));
        const ProjectData::FrameOffsets interpolated = ProjectData::offsetsAt(before, 5, m_doc->data().blend.time);
        const int steps = m_doc->undoStack()->count();
        celform::test::drag(m_view.get(), Qt::LeftButton, Qt::NoModifier, QPoint(kSize / 2, kSize / 2),
            QPoint(kSize / 2 + 30, kSize / 2), 6);
        QCOMPARE(m_doc->undoStack()->count(), steps + 1); // one stroke, one step
        const KeyViewpoint& after = *m_doc->data().key(m_key);
        // The stroke wrote a keyed frame at 5, and left 0 and 10 alone.
        QCOMPARE(after.offsetsByFrame.size(), std::size_t(3));
        QVERIFY(after.offsetsByFrame.count(5) == 1);
        QVERIFY(after.offsetsByFrame.at(0) == before.offsetsByFrame.at(0));
        QVERIFY(after.offsetsByFrame.at(10) == before.offsetsByFrame.at(10));
        // Every vertex the brush did not reach keeps exactly the offset it showed; the ones it
        // reached moved from there, along the camera's right (+x here).
        const SparseOffsets& stored = after.offsetsByFrame.at(5);
        const SparseOffsets* seen = interpolated.get();
        int moved = 0;
        for (Eigen::Index v = 0; v < shown.rows(); ++v) {
            const Eigen::Vector3f was = seen->at(std::uint32_t(v)), now = stored.at(std::uint32_t(v));
            if (now == was)
                continue;
            ++moved;
            QVERIFY((now - was).x() > 0.f);
            QVERIFY(std::abs((now - was).z()) < 1e-5f); // depth kept for this camera
        }
        QVERIFY(moved > 0);
        // The view shows the new shape at 5; undo takes the keyed frame away again.
        QVERIFY(m_view->displayedShape() == m_doc->data().keyShape(after, 5));
        m_doc->undoStack()->undo();
        QVERIFY(*m_doc->data().key(m_key) == before);
        QVERIFY(m_view->displayedShape() == shown);
    }

    void brushStepIsOneNotificationOfItsVertices()
    {
        m_view->setDisplayedKey(m_key);
        m_view->setTool(Viewport::Tool::Brush);
        m_view->tool<celform::views::BrushTool>().size().setRadius(0.5);
        frame();
        QSignalSpy changes(m_doc.get(), &Document::changed);
        const QPoint centre(kSize / 2, kSize / 2);
        QMouseEvent press(QEvent::MouseButtonPress, centre, m_view->mapToGlobal(centre), Qt::LeftButton, Qt::LeftButton,
            Qt::NoModifier);
        QApplication::sendEvent(m_view.get(), &press);
        QCOMPARE(changes.count(), 0); // a press selects, it changes nothing
        for (int i = 1; i <= 3; ++i) {
            const QPoint p = centre + QPoint(4 * i, 0);
            QMouseEvent move(
                QEvent::MouseMove, p, m_view->mapToGlobal(p), Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
            QApplication::sendEvent(m_view.get(), &move);
            QCOMPARE(changes.count(), i); // one notification per step
            const auto change = changes.last().at(0).value<ChangeSet>();
            QVERIFY(change.offsetsOnly);
            QVERIFY(!change.structure || i == 1);
            QVERIFY(change.touches(m_key));
            QVERIFY(!change.vertices.empty());
            QVERIFY(change.vertices.size() < std::size_t(m_doc->data().baseMesh->vertexCount()));
        }
        QMouseEvent release(QEvent::MouseButtonRelease, centre, m_view->mapToGlobal(centre), Qt::LeftButton,
            Qt::NoButton, Qt::NoModifier);
        QApplication::sendEvent(m_view.get(), &release);
        // The view's partial update gives exactly the full shape.
        QVERIFY(m_view->displayedShape() == m_doc->data().keyShape(*m_doc->data().key(m_key), 0));
    }

    void hiddenViewportDoesNoWork()
    {
        Viewport observer(m_doc.get());
        observer.setObserved(m_view.get());
        observer.resize(200, 160);
        observer.show();
        QVERIFY(QTest::qWaitForWindowExposed(&observer));
        celform::test::waitForRender(&observer);
        observer.hide();
        const int renders = observer.renderCount();
        const int updates = observer.shapeUpdates();
        // The main view orbits, the playhead moves and the key is brushed: nothing for the observer.
        m_view->setDisplayedKey(m_key);
        m_view->setTool(Viewport::Tool::Brush);
        celform::test::drag(m_view.get(), Qt::LeftButton, Qt::AltModifier, QPoint(100, 100), QPoint(160, 120), 5);
        m_doc->setCurrentFrame(3);
        celform::test::drag(m_view.get(), Qt::LeftButton, Qt::NoModifier, QPoint(kSize / 2, kSize / 2),
            QPoint(kSize / 2 + 20, kSize / 2), 5);
        QTest::qWait(50);
        QCOMPARE(observer.renderCount(), renders);
        QCOMPARE(observer.shapeUpdates(), updates);
        // Shown again, it catches up in one update and shows the blend at the playhead.
        observer.show();
        celform::test::waitForRender(&observer);
        QCOMPARE(observer.shapeUpdates(), updates + 1);
        Positions expected;
        m_doc->blender().shape(m_doc->data(), m_view->viewDirection(), 3, expected);
        QVERIFY(observer.displayedShape() == expected);
    }
};

int main(int argc, char** argv)
{
    QSurfaceFormat::setDefaultFormat(Viewport::defaultFormat());
    QApplication app(argc, argv);
    TestPlayhead test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_playhead.moc"
