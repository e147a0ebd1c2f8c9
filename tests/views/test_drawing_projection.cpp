// The convention of algo::projectToImage (RasterCamera::project) holds in the viewport whatever the
// window's shape: a drawing's height spans the camera's vertical field of view (orthographic: its
// height), its centre on the view axis, square pixels. The viewport letterboxes the drawing and
// widens its view angle to match; here a model point projected by VTK (what the viewport renders)
// and mapped to drawing pixels by the DrawingOverlay lands where RasterCamera puts it, for a tall
// and a wide viewport, perspective and orthographic. And the outline mode shows the extracted
// outline (Fit to Drawing's target), or says why there is none.
#include "celform/algorithms/raster.h"
#include "celform/algorithms/tri_mesh.h"
#include "celform/model/document/document.h"
#include "celform/model/render/render_output.h"
#include "celform/views/overlays/drawing_overlay.h"
#include "celform/views/overlays/outline_cache.h"
#include "celform/views/viewport/viewport.h"

#include "test_meshes.h"

#include <QApplication>
#include <QLabel>
#include <QtTest/QtTest>

#include <memory>

using namespace celform;

namespace {

/// A drawing of a size, white paper with a black disc in the middle (an outline to extract).
model::Drawing paperDrawing(int width, int height, bool touchingBorder = false)
{
    QImage image(width, height, QImage::Format_RGB32);
    image.fill(Qt::white);
    const int r = std::min(width, height) * (touchingBorder ? 6 : 2) / 10;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            if ((x - width / 2) * (x - width / 2) + (y - height / 2) * (y - height / 2) < r * r)
                image.setPixel(x, y, qRgb(0, 0, 0));
    model::Drawing d;
    d.name = QStringLiteral("paper");
    d.image = image;
    d.imageFormat = QStringLiteral("png");
    return d;
}

} // namespace

class TestDrawingProjection : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        m_doc = std::make_unique<model::Document>();
        model::ProjectData data;
        data.baseMesh = test::icosphere(3);
        m_doc->reset(std::move(data));
        m_drawing = m_doc->drawings().addDrawing(paperDrawing(480, 640));
        m_view = std::make_unique<views::Viewport>(m_doc.get());
        m_view->resize(400, 300);
        m_view->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_view.get()));
        QTRY_VERIFY(m_view->renderCount() > 0);
    }

    void cleanupTestCase()
    {
        m_view.reset();
        m_doc.reset();
    }

    void sameDrawingPixel_data()
    {
        QTest::addColumn<QSize>("size");
        QTest::addColumn<bool>("orthographic");
        QTest::newRow("tall, perspective") << QSize(300, 700) << false;
        QTest::newRow("wide, perspective") << QSize(900, 300) << false;
        QTest::newRow("tall, orthographic") << QSize(300, 700) << true;
        QTest::newRow("wide, orthographic") << QSize(900, 300) << true;
    }

    void sameDrawingPixel()
    {
        QFETCH(QSize, size);
        QFETCH(bool, orthographic);
        m_view->resize(size);
        QTRY_COMPARE(m_view->size(), size);
        views::DrawingOverlay& overlay = m_view->drawingOverlay();
        overlay.setDrawing(m_drawing);
        model::Camera camera;
        camera.eye = Eigen::Vector3d(3.0, 1.5, 5.0);
        camera.target = Eigen::Vector3d(0.1, -0.1, 0.0);
        camera.up = Eigen::Vector3d(0.1, 1.0, 0.0);
        camera.fovYDegrees = 32.0;
        camera.orthoHeight = 3.4;
        camera.projection = orthographic ? model::Projection::Orthographic : model::Projection::Perspective;
        m_view->setCamera(camera);
        QApplication::processEvents();
        // The viewport's camera reads back as the drawing's camera (the letterbox undone).
        const model::Camera shown = m_view->camera();
        QVERIFY(std::abs(shown.fovYDegrees - camera.fovYDegrees) < 1e-6);
        QVERIFY(std::abs(shown.orthoHeight - camera.orthoHeight) < 1e-9);

        const model::Drawing& drawing = *m_doc->data().drawing(m_drawing);
        const algo::RasterCamera raster = model::rasterCamera(camera, drawing.image.width(), drawing.image.height());
        const auto& vertices = m_doc->data().baseMesh->vertices;
        double worst = 0.0;
        int compared = 0;
        for (Eigen::Index v = 0; v < vertices.rows(); v += 7) {
            const Eigen::Vector3d point = vertices.row(v).cast<double>().transpose();
            const Eigen::Vector2d expected = raster.project(point).head<2>();
            const auto pixel = overlay.widgetToDrawing(m_view->projectToWidget(point));
            QVERIFY2(pixel, "a model point fell outside the drawing");
            worst = std::max(worst, (*pixel - expected).norm());
            ++compared;
            // And back: the overlay's inverse puts the drawing pixel on the rendered point.
            const QPointF widget = overlay.drawingToWidget(expected);
            QVERIFY((Eigen::Vector2d(widget.x(), widget.y())
                        - Eigen::Vector2d(m_view->projectToWidget(point).x(), m_view->projectToWidget(point).y()))
                        .norm()
                < 0.05);
        }
        QVERIFY(compared > 20);
        QVERIFY2(worst < 0.05, qPrintable(QStringLiteral("off by %1 drawing pixels").arg(worst)));
    }

    void outlineModeShowsTheExtractedOutline()
    {
        views::DrawingOverlay& overlay = m_view->drawingOverlay();
        overlay.setDrawing(m_drawing);
        const int before = overlay.outlineCache()->extractions();
        overlay.setOutline(true);
        QVERIFY(overlay.outlineProblem().isEmpty());
        const QImage* shown = overlay.image();
        QVERIFY(shown && shown->size() == QSize(480, 640));
        // Magenta on the disc's edge (radius 96 about the centre), nothing far from it.
        const QRgb edge = shown->pixel(240 + 96, 320);
        QVERIFY2(qRed(edge) > 200 && qAlpha(edge) > 200 && qGreen(edge) < 60, qPrintable(QString::number(edge, 16)));
        QCOMPARE(qAlpha(shown->pixel(10, 10)), 0);
        // A filled silhouette (the disc) is outlined, not painted over: its inside stays see-through
        // (it was solid magenta over the model when the outline mode traced every ink edge).
        QVERIFY2(qAlpha(shown->pixel(240, 320)) < 100, qPrintable(QString::number(shown->pixel(240, 320), 16)));
        // Extracted once, not at every paint.
        for (int i = 0; i < 3; ++i) {
            m_view->update();
            QApplication::processEvents();
            QVERIFY(overlay.image() != nullptr); // asking for the picture must not extract again
        }
        QCOMPARE(overlay.outlineCache()->extractions(), before + 1);

        // New settings are a new outline; a figure cut by the frame says why in the banner.
        model::DrawingOutline settings;
        settings.closingRadius = 4.0;
        m_doc->drawings().setDrawingOutline(m_drawing, settings);
        QCOMPARE(overlay.outlineCache()->extractions(), before + 2);
        const model::ObjectId cut = m_doc->drawings().addDrawing(paperDrawing(200, 200, true));
        overlay.setDrawing(cut);
        QVERIFY(overlay.outlineProblem().contains(QStringLiteral("border")));
        auto* banner = m_view->findChild<QLabel*>(QStringLiteral("outlineProblemBanner"));
        QVERIFY(banner && banner->isVisible());
        QCOMPARE(banner->text(), overlay.outlineProblem());
        overlay.setOutline(false);
        QVERIFY(overlay.outlineProblem().isEmpty());
        QVERIFY(!banner->isVisible());
    }

private:
    std::unique_ptr<model::Document> m_doc;
    std::unique_ptr<views::Viewport> m_view;
    model::ObjectId m_drawing = 0;
};

int main(int argc, char** argv)
{
    QSurfaceFormat::setDefaultFormat(views::Viewport::defaultFormat());
    QApplication app(argc, argv);
    TestDrawingProjection test;
    return QTest::qExec(&test, argc, argv);
}
#include "test_drawing_projection.moc"
