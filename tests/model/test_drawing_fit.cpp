// Fit to Drawing on the document: a drawing's outline settings saved and refused, the fits run on
// a synthetic model sheet with a known camera and pull, and each fit applied as one undo step that
// undo takes back whole.
#include "fit_model_sheet.h"
#include "test_meshes.h"
#include "test_support.h"

#include "celform/algorithms/fit_camera.h"
#include "celform/model/analysis/drawing_fit.h"
#include "celform/model/data/io_error.h"
#include "celform/model/document/document.h"
#include "celform/model/io/mesh_io.h"
#include "celform/model/io/project_file.h"

#include <QBuffer>
#include <QTemporaryDir>
#include <QUndoStack>

#include <cmath>

using namespace celform;
using namespace celform::model;

namespace {

QImage greyImage(const algo::DrawingImage& drawing)
{
    QImage image(drawing.width, drawing.height, QImage::Format_Grayscale8);
    for (int y = 0; y < drawing.height; ++y)
        std::memcpy(image.scanLine(y), drawing.pixels.data() + std::size_t(y) * std::size_t(drawing.width),
            std::size_t(drawing.width));
    return image;
}

Drawing drawingOf(const QImage& image, const QString& name)
{
    Drawing d;
    d.name = name;
    QBuffer buffer(&d.imageData);
    buffer.open(QIODevice::WriteOnly);
    image.save(&buffer, "PNG");
    d.imageFormat = QStringLiteral("png");
    d.image = image;
    return d;
}

Camera documentCamera(const algo::RasterCamera& r)
{
    Camera c;
    c.eye = r.eye;
    c.target = r.target;
    c.up = r.up;
    c.fovYDegrees = r.fovYDegrees;
    return c;
}

double degreesBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
    return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) * 180.0 / 3.14159265358979323846;
}

} // namespace

class TestDrawingFit : public QObject {
    Q_OBJECT

private:
    std::shared_ptr<const algo::TriMesh> m_elephant;

    /// A document on the elephant with the drawing of sheet, its key seen from a camera orbited
    /// (yaw, pitch) degrees off the sheet's.
    void makeProject(
        Document& doc, const test::ModelSheet& sheet, double yaw, double pitch, ObjectId& drawing, ObjectId& key)
    {
        doc.reset(newProject(m_elephant, QStringLiteral("cgal_elephant.off")));
        drawing = doc.drawings().addDrawing(
            drawingOf(greyImage(test::silhouetteDrawing(sheet.pulled, m_elephant->faces, sheet.camera)),
                QStringLiteral("sheet")));
        const algo::RasterCamera start
            = algo::orbitCamera(sheet.camera, algo::centroid(m_elephant->vertices), yaw, pitch);
        key = doc.keys().createKey(QStringLiteral("side"), documentCamera(start), {drawing});
    }

private slots:
    void initTestCase()
    {
        const QString path = test::sharedDataPath(QStringLiteral("meshes/cgal_elephant.off"));
        if (!path.isEmpty())
            m_elephant = std::make_shared<const algo::TriMesh>(importMesh(path).mesh);
    }

    void outlineSettingsAreSavedAndRefused()
    {
        Document doc;
        ProjectData data;
        data.baseMesh = test::octahedron();
        QImage paper(64, 48, QImage::Format_RGB32);
        paper.fill(Qt::white);
        doc.reset(std::move(data));
        const ObjectId id = doc.drawings().addDrawing(drawingOf(paper, QStringLiteral("paper")));
        DrawingOutline outline;
        outline.threshold = 0.4;
        outline.closingRadius = 5.0;
        outline.innerLines = true;
        outline.minComponentPixels = 30;
        const int steps = doc.undoStack()->count();
        doc.drawings().setDrawingOutline(id, outline);
        QCOMPARE(doc.undoStack()->count(), steps + 1);
        QVERIFY(doc.data().drawing(id)->outline == outline);
        doc.undoStack()->undo();
        QVERIFY(doc.data().drawing(id)->outline == DrawingOutline{});
        doc.undoStack()->redo();

        // Out of range: refused, nothing changes.
        for (auto bad : {DrawingOutline{1.5, 2.0, false, 0}, DrawingOutline{-1.0, -1.0, false, 0},
                 DrawingOutline{-1.0, 65.0, false, 0}, DrawingOutline{-1.0, 2.0, false, -3},
                 DrawingOutline{std::nan(""), 2.0, false, 0}}) {
            QVERIFY_THROWS_EXCEPTION(EditRefused, doc.drawings().setDrawingOutline(id, bad));
            QVERIFY(doc.data().drawing(id)->outline == outline);
        }

        // Saved and read back; a file with a bad value is refused, naming the drawing.
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("outline.celform"));
        saveProject(doc.data(), path);
        const ProjectData back = loadProject(path);
        QVERIFY(back.drawings.at(0).outline == outline);
    }

    void badDrawingsSayWhy()
    {
        if (!m_elephant)
            QSKIP("shared test data not found: ../shared/data/meshes/cgal_elephant.off");
        Document doc;
        doc.reset(newProject(m_elephant, QStringLiteral("cgal_elephant.off")));
        QImage white(256, 256, QImage::Format_RGB32);
        white.fill(Qt::white);
        QImage black(256, 256, QImage::Format_RGB32);
        black.fill(Qt::black);
        QImage cut = white; // a figure running off the right edge
        for (int y = 60; y < 200; ++y)
            for (int x = 100; x < 256; ++x)
                cut.setPixel(x, y, qRgb(0, 0, 0));
        QImage lines = white; // two strokes that never enclose anything
        for (int i = 20; i < 230; ++i) {
            lines.setPixel(i, 128, qRgb(0, 0, 0));
            lines.setPixel(128, i, qRgb(0, 0, 0));
        }
        const struct {
            QImage image;
            const char* name;
            const char* says;
        } cases[]
            = {{QImage(), "empty", "no image"}, {white, "white", "all one tone"}, {black, "black", "all one tone"},
                {cut, "cut", "touches the image border"}, {lines, "lines", "no closed outline"}};
        for (const auto& c : cases) {
            Drawing d = drawingOf(c.image.isNull() ? white : c.image, QString::fromLatin1(c.name));
            if (c.image.isNull())
                d.image = QImage();
            const ObjectId drawing = doc.drawings().addDrawing(d);
            d.camera.eye = Eigen::Vector3d(0, 0, 3);
            const ObjectId key
                = doc.keys().createKey(QStringLiteral("k %1").arg(QLatin1String(c.name)), Camera{}, {drawing});
            const ProjectData before = doc.data();
            const CameraFit camera = fitCameraToDrawing(doc.data(), drawing, key);
            QVERIFY(!camera.ok);
            QVERIFY2(camera.error.contains(QLatin1String(c.says)) && camera.error.contains(QLatin1String(c.name)),
                qPrintable(camera.error));
            const ShapeFit shape = fitShapeToDrawing(doc.data(), key, drawing);
            QVERIFY(!shape.ok);
            QCOMPARE(shape.error, camera.error);
            QVERIFY(doc.data() == before);
            doc.keys().removeKey(key);
        }
    }

    // The figures through the document: camera within 1 degree, then the shape to IoU
    // >= 0.97 and chamfer <= 1.5 px; two undo steps, each undone whole.
    void fitsAreOneStepEach()
    {
        if (!m_elephant)
            QSKIP("shared test data not found: ../shared/data/meshes/cgal_elephant.off");
        const test::ModelSheet sheet = test::makeModelSheet(*m_elephant, Eigen::Vector3d(0.2, 0.1, 1.0), 768, 0.04);
        QVERIFY(sheet.outline.ok());
        Document doc;
        ObjectId drawing = 0, key = 0;
        makeProject(doc, sheet, 6.0, -4.0, drawing, key);
        const Eigen::Vector3d centre = algo::centroid(m_elephant->vertices);
        const ProjectData start = doc.data();
        const int steps = doc.undoStack()->count();

        const CameraFit camera = fitCameraToDrawing(doc.data(), drawing, key);
        QVERIFY2(camera.ok, qPrintable(camera.error));
        doc.keys().applyFittedCamera(drawing, key, camera.after);
        QCOMPARE(doc.undoStack()->count(), steps + 1);
        QCOMPARE(doc.undoStack()->text(steps), QStringLiteral("Fit Camera to Drawing"));
        const KeyViewpoint& k = *doc.data().key(key);
        QVERIFY(k.camera == camera.after);
        QVERIFY(doc.data().drawing(drawing)->camera == camera.after && doc.data().drawing(drawing)->aligned);
        const double off = degreesBetween(k.camera.eye - centre, sheet.camera.eye - centre);
        QVERIFY2(off < 1.0, qPrintable(QString::number(off)));
        QVERIFY(k.direction.isApprox((k.camera.eye - doc.data().baseCentre(0)).normalized(), 1e-9));

        const ShapeFit shape = fitShapeToDrawing(doc.data(), key, drawing);
        QVERIFY2(shape.ok, qPrintable(shape.error));
        doc.keys().applyFittedShape(key, shape.frame, shape.indices, shape.displacements);
        QCOMPARE(doc.undoStack()->count(), steps + 2);
        QCOMPARE(doc.undoStack()->text(steps + 1), QStringLiteral("Fit Shape to Drawing"));
        const algo::FitMetrics after
            = keyFitMetrics(doc.data(), *doc.data().key(key), *doc.data().drawing(drawing), sheet.outline);
        qInfo("through the document: camera %.2f deg off; IoU %.4f -> %.4f, chamfer %.2f -> %.2f px", off,
            camera.metricsBefore.iou, after.iou, camera.metricsBefore.chamferPx, after.chamferPx);
        QVERIFY2(after.iou >= 0.97, qPrintable(QString::number(after.iou)));
        QVERIFY2(after.chamferPx <= 1.5, qPrintable(QString::number(after.chamferPx)));

        doc.undoStack()->undo();
        doc.undoStack()->undo();
        QVERIFY(doc.data() == start);
    }

    void regionAndPinsAreHonoured()
    {
        if (!m_elephant)
            QSKIP("shared test data not found: ../shared/data/meshes/cgal_elephant.off");
        const test::ModelSheet sheet = test::makeModelSheet(*m_elephant, Eigen::Vector3d(0.0, 0.0, 1.0), 512, 0.05);
        Document doc;
        ObjectId drawing = 0, key = 0;
        makeProject(doc, sheet, 0.0, 0.0, drawing, key);
        // A region of nothing near the pull: no fit to make there, and a missing face set is named.
        ShapeFitRequest request;
        request.regionFaceSet = QStringLiteral("nowhere");
        ShapeFit fit = fitShapeToDrawing(doc.data(), key, drawing, request);
        QVERIFY(!fit.ok && fit.error.contains(QLatin1String("nowhere")));
        request = {};
        request.strength = 1.5;
        fit = fitShapeToDrawing(doc.data(), key, drawing, request);
        QVERIFY(!fit.ok);
        // Pinning every face: nothing may move.
        std::vector<std::int32_t> all(std::size_t(m_elephant->faceCount()));
        for (std::size_t f = 0; f < all.size(); ++f)
            all[f] = std::int32_t(f);
        doc.faceSets().setFaceSet(QStringLiteral("everything"), all, QStringLiteral("Paint"));
        request = {};
        request.pinFaceSet = QStringLiteral("everything");
        fit = fitShapeToDrawing(doc.data(), key, drawing, request);
        float largest = 0.0F;
        for (Eigen::Index r = 0; r < fit.displacements.rows(); ++r)
            largest = std::max(largest, fit.displacements.row(r).norm());
        QVERIFY2(largest < 1e-6F, qPrintable(QString::number(double(largest))));
    }
};

QTEST_GUILESS_MAIN(TestDrawingFit)
#include "test_drawing_fit.moc"
