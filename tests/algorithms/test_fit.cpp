// Fitting a model to a drawing on synthetic model sheets with a known answer: the figures (masks,
// chamfer, IoU), the camera fit back from 5-10 degrees off, and the shape fit meeting a pulled
// outline while what is far from the pull stays; the options (region, pins, mirror, strength),
// cancel and bad input.
#include "fit_model_sheet.h"
#include "test_support.h"
#include "test_meshes.h"

#include "celform/algorithms/fit_camera.h"
#include "celform/algorithms/fit_metrics.h"
#include "celform/algorithms/fit_shape.h"
#include "celform/algorithms/arap.h"
#include "celform/algorithms/brush.h"
#include "celform/model/io/mesh_io.h"

#include <QElapsedTimer>

#include <cmath>
#include <memory>

using namespace celform::algo;
using celform::test::ModelSheet;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kSize = 1024;
const Eigen::Vector3d kView(0.8, 0.15, 0.55);

double degreesBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
    return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) * 180.0 / kPi;
}

std::unique_ptr<TriMesh> loadElephant()
{
    const QString path = celform::test::sharedDataPath(QStringLiteral("meshes/cgal_elephant.off"));
    if (path.isEmpty())
        return nullptr;
    return std::make_unique<TriMesh>(celform::model::importMesh(path).mesh);
}

class CancelAtOnce : public Progress {
public:
    void progress(std::int64_t, std::int64_t, const std::string&) override { ++calls; }
    [[nodiscard]] bool isCancelRequested() const override { return true; }
    int calls = 0;
};

class Counting : public Progress {
public:
    void progress(std::int64_t d, std::int64_t t, const std::string&) override
    {
        ++calls;
        done = d;
        total = t;
    }
    [[nodiscard]] bool isCancelRequested() const override { return false; }
    int calls = 0;
    std::int64_t done = 0, total = 0;
};

/// Largest displacement of the vertices farther than distance from centre, and of all.
double largestFarMove(const FitShapeResult& r, const Positions& shape, const Eigen::Vector3d& centre, double distance)
{
    double worst = 0.0;
    for (std::size_t k = 0; k < r.indices.size(); ++k)
        if ((shape.row(r.indices[k]).transpose().cast<double>() - centre).norm() > distance)
            worst = std::max(worst, double(r.displacements.row(Eigen::Index(k)).norm()));
    return worst;
}

} // namespace

class TestFit : public QObject {
    Q_OBJECT

private slots:
    void robustKernels()
    {
        const RobustKernel huber{RobustLoss::Huber, 2.0};
        QCOMPARE(huber.weight(1.0), 1.0);
        QCOMPARE(huber.weight(-4.0), 0.5);
        QCOMPARE(huber.rho(1.0), 0.5);
        QCOMPARE(huber.rho(4.0), 2.0 * (4.0 - 1.0));
        const RobustKernel tukey{RobustLoss::Tukey, 2.0};
        QCOMPARE(tukey.weight(3.0), 0.0);
        QCOMPARE(tukey.rho(3.0), 4.0 / 6.0);
        QVERIFY(tukey.weight(1.0) > 0.0 && tukey.weight(1.0) < 1.0);
    }

    void coverageMatchesTheRasteriser()
    {
        const auto sphere = celform::test::icosphere(3);
        RasterCamera camera;
        camera.eye = {0.4, 0.3, 3.5};
        camera.width = 300;
        camera.height = 200;
        std::vector<std::uint8_t> mask;
        silhouetteMask(sphere->vertices, sphere->faces, camera, mask);
        GBuffer g;
        rasterise(sphere->vertices, sphere->faces, Positions(), camera, g);
        int differ = 0, covered = 0;
        for (std::size_t i = 0; i < mask.size(); ++i) {
            differ += (mask[i] != 0) != (g.faceId[i] >= 0);
            covered += mask[i];
        }
        QVERIFY(covered > 1000);
        QVERIFY2(differ <= 2, qPrintable(QString::number(differ)));
    }

    void maskFigures()
    {
        const int w = 200, h = 160;
        auto disc = [&](double cx, double cy, double r) {
            std::vector<std::uint8_t> m(std::size_t(w * h));
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x)
                    m[std::size_t(y * w + x)] = std::hypot(x + 0.5 - cx, y + 0.5 - cy) < r;
            return m;
        };
        const auto a = disc(100, 80, 50);
        const FitMetrics same = compareMasks(a.data(), a.data(), w, h);
        QVERIFY(same.valid);
        QCOMPARE(same.iou, 1.0);
        QCOMPARE(same.chamferPx, 0.0);
        const auto b = disc(104, 80, 50);
        const FitMetrics shifted = compareMasks(a.data(), b.data(), w, h);
        // A 4 px shift: boundary points move between 0 (top, bottom) and 4 px (left, right) away.
        QVERIFY2(shifted.chamferPx > 1.5 && shifted.chamferPx < 3.5, qPrintable(QString::number(shifted.chamferPx)));
        QVERIFY(shifted.iou > 0.9 && shifted.iou < 0.96);
        std::vector<std::uint8_t> empty(a.size(), 0);
        QVERIFY(!compareMasks(a.data(), empty.data(), w, h).valid);
        // The signed field crosses zero half way between the pixels either side of the boundary.
        std::vector<std::uint8_t> half(std::size_t(w * h));
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                half[std::size_t(y * w + x)] = x < 100;
        std::vector<float> field;
        signedDistanceField(half.data(), w, h, field);
        QVERIFY(std::abs(sampleBilinear(field, w, h, 100.0, 50.0)) < 1e-6);
        QVERIFY(std::abs(sampleBilinear(field, w, h, 103.0, 50.0) - 3.0) < 1e-6);
        QVERIFY(std::abs(sampleBilinear(field, w, h, 96.0, 50.0) + 4.0) < 1e-6);
    }

    void arapFollowsARigidMotion()
    {
        // Handles on one cap moved rigidly: the rigid motion has no energy, so the whole sphere
        // follows it (given the many iterations ARAP needs from rest for a 40 degree turn); a
        // pinned vertex stays at rest.
        const auto sphere = celform::test::icosphere(3);
        const Eigen::Matrix3d rotation
            = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
        const Eigen::Vector3d shift(0.3, -0.2, 0.1);
        std::vector<std::uint8_t> free(std::size_t(sphere->vertices.rows()), 1);
        ArapSolver solver(sphere->vertices, sphere->faces, free);
        std::vector<ArapHandle> handles;
        for (Eigen::Index v = 0; v < sphere->vertices.rows(); ++v)
            if (sphere->vertices(v, 0) > 0.6f)
                handles.push_back(
                    {std::int32_t(v), rotation * sphere->vertices.row(v).transpose().cast<double>() + shift, 1e4});
        QVERIFY(handles.size() > 20);
        QVERIFY(solver.setHandles(handles));
        Eigen::MatrixXd current = sphere->vertices.cast<double>();
        QVERIFY(solver.solve(current, 300));
        double worst = 0.0;
        for (Eigen::Index v = 0; v < current.rows(); ++v)
            worst = std::max(worst,
                (current.row(v).transpose() - (rotation * sphere->vertices.row(v).transpose().cast<double>() + shift))
                    .norm());
        QVERIFY2(worst < 5e-3, qPrintable(QString::number(worst)));
        free[0] = 0;
        ArapSolver pinned(sphere->vertices, sphere->faces, free);
        QCOMPARE(pinned.freeCount(), std::int64_t(sphere->vertices.rows() - 1));
        QVERIFY(pinned.setHandles(handles));
        current = sphere->vertices.cast<double>();
        pinned.solve(current, 5);
        QCOMPARE(current.row(0), sphere->vertices.row(0).cast<double>());
    }

    void cameraComesBackToTheDrawing_data()
    {
        QTest::addColumn<double>("amplitude");
        QTest::addColumn<bool>("orthographic");
        QTest::addColumn<double>("yaw");
        QTest::addColumn<double>("pitch");
        QTest::newRow("exact, perspective") << 0.0 << false << 6.0 << -4.0;
        QTest::newRow("pulled sheet, perspective") << 0.04 << false << -7.0 << 5.0;
        QTest::newRow("pulled sheet, orthographic") << 0.04 << true << 5.0 << 6.0;
    }

    void cameraComesBackToTheDrawing()
    {
        QFETCH(double, amplitude);
        QFETCH(bool, orthographic);
        QFETCH(double, yaw);
        QFETCH(double, pitch);
        const auto mesh = loadElephant();
        if (!mesh)
            QSKIP("shared test data not found: ../shared/data/meshes/cgal_elephant.off");
        const ModelSheet sheet = celform::test::makeModelSheet(*mesh, kView, kSize, amplitude, 0.12, orthographic);
        QVERIFY2(sheet.outline.ok(), outlineErrorMessage(sheet.outline.error).c_str());
        const Eigen::Vector3d centre = centroid(mesh->vertices);
        RasterCamera start = orbitCamera(sheet.camera, centre, yaw, pitch);
        if (orthographic)
            start.orthoHeight *= 1.08;
        else
            start.fovYDegrees = 33.0;
        const double startError = degreesBetween(viewDirection(start, centre), viewDirection(sheet.camera, centre));
        QVERIFY(startError > 5.0 && startError < 10.0);
        Counting progress;
        QElapsedTimer timer;
        timer.start();
        const FitCameraResult r
            = fitCamera(mesh->vertices, mesh->faces, mesh->edgeTopology(), start, sheet.outline, {}, &progress);
        const qint64 ms = timer.elapsed();
        QVERIFY2(r.ok, r.error.c_str());
        const double error = degreesBetween(viewDirection(r.camera, centre), viewDirection(sheet.camera, centre));
        qInfo("camera fit: %.2f deg off -> %.3f deg; IoU %.4f -> %.4f, chamfer %.2f -> %.2f px; %d iterations, %lld ms",
            startError, error, r.before.iou, r.after.iou, r.before.chamferPx, r.after.chamferPx, r.iterations, ms);
        QVERIFY2(error < 1.0, qPrintable(QString::number(error)));
        QVERIFY(r.after.iou > r.before.iou);
        if (amplitude == 0.0) {
            QVERIFY(r.after.iou > 0.99);
            QVERIFY(r.after.chamferPx < 0.6);
        }
        QVERIFY(progress.calls > 0);
        QCOMPARE(progress.done, progress.total);
    }

    void shapeMeetsThePulledOutline()
    {
        const auto mesh = loadElephant();
        if (!mesh)
            QSKIP("shared test data not found: ../shared/data/meshes/cgal_elephant.off");
        const ModelSheet sheet = celform::test::makeModelSheet(*mesh, kView, kSize, 0.04);
        QVERIFY(sheet.outline.ok());
        QElapsedTimer timer;
        timer.start();
        const FitShapeResult r
            = fitShape(mesh->vertices, mesh->faces, mesh->edgeTopology(), sheet.camera, sheet.outline);
        const qint64 ms = timer.elapsed();
        QVERIFY2(r.ok, r.error.c_str());
        const double far = largestFarMove(r, mesh->vertices, sheet.pullCentre, 3.0 * sheet.pullSigma);
        qInfo("shape fit: IoU %.4f -> %.4f, chamfer %.2f -> %.2f px, %d rounds, %lld matched, %zu moved, far move %.3f "
              "%% "
              "of the size, %lld ms",
            r.before.iou, r.after.iou, r.before.chamferPx, r.after.chamferPx, r.rounds, (long long)r.matchedVertices,
            r.indices.size(), 100.0 * far / sheet.modelSize, ms);
        QVERIFY2(r.after.iou >= 0.97, qPrintable(QString::number(r.after.iou)));
        QVERIFY2(r.after.chamferPx <= 1.5, qPrintable(QString::number(r.after.chamferPx)));
        QVERIFY2(far < 0.02 * sheet.modelSize, qPrintable(QString::number(far / sheet.modelSize)));
        QVERIFY(std::is_sorted(r.indices.begin(), r.indices.end()));
        QCOMPARE(Eigen::Index(r.indices.size()), r.displacements.rows());
        // Parallel to the image plane at the matched vertices: depth is kept where the fit pulls.
        // (Checked on the whole result: the mean depth change is small against the moves.)
        const Eigen::Vector3d forward = sheet.camera.forward();
        double along = 0.0, across = 0.0;
        for (Eigen::Index k = 0; k < r.displacements.rows(); ++k) {
            const Eigen::Vector3d d = r.displacements.row(k).transpose().cast<double>();
            along += std::abs(d.dot(forward));
            across += (d - d.dot(forward) * forward).norm();
        }
        QVERIFY2(along < 0.5 * across, qPrintable(QString("%1 %2").arg(along).arg(across)));
    }

    void shapeOptions()
    {
        const auto mesh = loadElephant();
        if (!mesh)
            QSKIP("shared test data not found: ../shared/data/meshes/cgal_elephant.off");
        const ModelSheet sheet = celform::test::makeModelSheet(*mesh, kView, 512, 0.04);
        QVERIFY(sheet.outline.ok());
        const Positions& shape = mesh->vertices;
        FitShapeOptions options;
        options.maxRounds = 3;
        const FitShapeResult full
            = fitShape(shape, mesh->faces, mesh->edgeTopology(), sheet.camera, sheet.outline, options);
        QVERIFY(full.ok && !full.indices.empty());

        // Strength scales the result.
        options.strength = 0.5;
        const FitShapeResult half
            = fitShape(shape, mesh->faces, mesh->edgeTopology(), sheet.camera, sheet.outline, options);
        QVERIFY(half.ok);
        QCOMPARE(half.indices.size(), full.indices.size());
        QVERIFY((half.displacements * 2.0f - full.displacements).cwiseAbs().maxCoeff() < 1e-5f);
        QVERIFY(half.after.iou < full.after.iou);
        options.strength = 1.0;

        // Pins stay, and so does everything outside the region.
        std::vector<std::int32_t> near, region;
        for (Eigen::Index v = 0; v < shape.rows(); ++v)
            if ((shape.row(v).transpose().cast<double>() - sheet.pullCentre).norm() < sheet.pullSigma)
                near.push_back(std::int32_t(v));
        options.pinnedVertices = near;
        const FitShapeResult pinned
            = fitShape(shape, mesh->faces, mesh->edgeTopology(), sheet.camera, sheet.outline, options);
        QVERIFY(pinned.ok);
        for (std::int32_t v : near)
            QVERIFY(!std::binary_search(pinned.indices.begin(), pinned.indices.end(), std::uint32_t(v)));
        options.pinnedVertices.clear();
        std::vector<std::uint8_t> inRegion(std::size_t(shape.rows()), 0);
        for (Eigen::Index f = 0; f < mesh->faces.rows(); ++f) {
            bool close = true;
            for (int k = 0; k < 3; ++k)
                close = close
                    && (shape.row(mesh->faces(f, k)).transpose().cast<double>() - sheet.pullCentre).norm()
                        < 2.5 * sheet.pullSigma;
            if (close) {
                region.push_back(std::int32_t(f));
                for (int k = 0; k < 3; ++k)
                    inRegion[std::size_t(mesh->faces(f, k))] = 1;
            }
        }
        options.regionFaces = region;
        const FitShapeResult regional
            = fitShape(shape, mesh->faces, mesh->edgeTopology(), sheet.camera, sheet.outline, options);
        QVERIFY(regional.ok && !regional.indices.empty());
        for (std::uint32_t v : regional.indices)
            QVERIFY(inRegion[v]);
        QVERIFY(regional.after.iou > regional.before.iou);
        options.regionFaces.clear();
    }

    void shapeMirror()
    {
        // A sphere, symmetric across x = 0, seen from the front, drawn pulled out on both sides:
        // with the mirror each moved vertex moves as its twin's reflection.
        const auto sphere = celform::test::icosphere(4);
        ModelSheet sheet = celform::test::makeModelSheet(*sphere, Eigen::Vector3d(0.0, 0.2, 1.0), 400, 0.05);
        // The drawing is symmetric too: the pull mirrored onto the left side.
        const std::vector<std::int32_t> twins = mirrorMap(sphere->vertices, 1e-4 * sheet.modelSize);
        for (Eigen::Index v = 0; v < sphere->vertices.rows(); ++v) {
            Eigen::Vector3f d = sheet.pulled.row(v) - sphere->vertices.row(v);
            if (sphere->vertices(v, 0) < 0.0f)
                continue;
            const std::int32_t twin = twins[std::size_t(v)];
            d.x() = -d.x();
            sheet.pulled.row(twin) = sphere->vertices.row(twin) + d.transpose();
        }
        sheet.outline = extractOutline(celform::test::silhouetteDrawing(sheet.pulled, sphere->faces, sheet.camera));
        QVERIFY(sheet.outline.ok());
        FitShapeOptions options;
        options.mirror = twins;
        QVERIFY(std::find(twins.begin(), twins.end(), -1) == twins.end());
        const FitShapeResult mirrored
            = fitShape(sphere->vertices, sphere->faces, sphere->edgeTopology(), sheet.camera, sheet.outline, options);
        qInfo("mirror: ok %d, %s, rounds %d, chamfer %.2f -> %.2f, moved %zu", mirrored.ok, mirrored.error.c_str(),
            mirrored.rounds, mirrored.before.chamferPx, mirrored.after.chamferPx, mirrored.indices.size());
        QVERIFY(mirrored.ok && !mirrored.indices.empty());
        auto offsetOf = [&](std::uint32_t v) -> Eigen::Vector3d {
            const auto it = std::lower_bound(mirrored.indices.begin(), mirrored.indices.end(), v);
            if (it == mirrored.indices.end() || *it != v)
                return Eigen::Vector3d::Zero();
            return mirrored.displacements.row(it - mirrored.indices.begin()).transpose().cast<double>();
        };
        double worst = 0.0, largest = 0.0;
        for (std::uint32_t v : mirrored.indices) {
            Eigen::Vector3d reflected = offsetOf(std::uint32_t(options.mirror[v]));
            reflected.x() = -reflected.x();
            worst = std::max(worst, (offsetOf(v) - reflected).norm());
            largest = std::max(largest, offsetOf(v).norm());
        }
        QVERIFY(largest > 0.01 * sheet.modelSize);
        QVERIFY2(worst < 1e-4 * largest, qPrintable(QString::number(worst / largest)));
        QVERIFY(mirrored.after.iou > 0.97);
        QVERIFY(mirrored.after.chamferPx < 0.5 * mirrored.before.chamferPx);
    }

    void cancelAndBadInput()
    {
        const auto sphere = celform::test::icosphere(2);
        RasterCamera camera;
        camera.eye = {0, 0, 4};
        camera.width = camera.height = 200;
        const auto outline = extractOutline(celform::test::silhouetteDrawing(sphere->vertices, sphere->faces, camera));
        QVERIFY(outline.ok());
        CancelAtOnce cancel;
        const FitCameraResult c
            = fitCamera(sphere->vertices, sphere->faces, sphere->edgeTopology(), camera, outline, {}, &cancel);
        QVERIFY(c.cancelled && !c.ok);
        QCOMPARE(c.camera.eye, camera.eye);
        const FitShapeResult s
            = fitShape(sphere->vertices, sphere->faces, sphere->edgeTopology(), camera, outline, {}, &cancel);
        QVERIFY(s.cancelled && !s.ok && s.indices.empty());

        Outline bad;
        bad.error = OutlineError::TouchesBorder;
        const FitCameraResult badCamera
            = fitCamera(sphere->vertices, sphere->faces, sphere->edgeTopology(), camera, bad);
        QVERIFY(!badCamera.ok && !badCamera.error.empty());
        const FitShapeResult badShape = fitShape(sphere->vertices, sphere->faces, sphere->edgeTopology(), camera, bad);
        QVERIFY(!badShape.ok && !badShape.error.empty());
        // The model behind the camera: nothing to fit.
        RasterCamera away = camera;
        away.target = {0, 0, 8};
        QVERIFY(!fitCamera(sphere->vertices, sphere->faces, sphere->edgeTopology(), away, outline).ok);
        QVERIFY(!fitShape(sphere->vertices, sphere->faces, sphere->edgeTopology(), away, outline).ok);
        // Everything pinned: nothing may move.
        FitShapeOptions pinned;
        for (int v = 0; v < sphere->vertices.rows(); ++v)
            pinned.pinnedVertices.push_back(v);
        QVERIFY(!fitShape(sphere->vertices, sphere->faces, sphere->edgeTopology(), camera, outline, pinned).ok);
    }
};

QTEST_GUILESS_MAIN(TestFit)
#include "test_fit.moc"
