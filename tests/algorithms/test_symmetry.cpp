// The mirror plane of a model (algorithms/…/symmetry.h): detected on a mesh symmetric across one
// plane only, exactly and with noise, and on the sample elephant (roughly symmetric across z); the
// twins of approximate symmetry.
#include "test_meshes.h"
#include "test_support.h"

#include "celform/algorithms/symmetry.h"
#include "celform/model/io/mesh_io.h"

#include <QtTest>

#include <random>

using namespace celform::algo;

namespace {

/// An icosphere stretched to (2, 1, 0.7), bent (y += 0.3 x^3, so only the z plane mirrors it) and
/// moved off the origin, so the plane through the bounding-box centre is not z = 0.
TriMesh bentEllipsoid()
{
    TriMesh mesh = *celform::test::icosphere(3);
    for (Eigen::Index i = 0; i < mesh.vertices.rows(); ++i) {
        Eigen::Vector3f p = mesh.vertices.row(i).transpose().cwiseProduct(Eigen::Vector3f(2.f, 1.f, 0.7f));
        p.y() += 0.3f * p.x() * p.x() * p.x();
        mesh.vertices.row(i) = (p + Eigen::Vector3f(5.f, -3.f, 1.5f)).transpose();
    }
    return mesh;
}

} // namespace

class TestSymmetry : public QObject {
    Q_OBJECT
private slots:
    void exactSymmetry()
    {
        const TriMesh mesh = bentEllipsoid();
        const SymmetryEstimate s = detectSymmetry(mesh.vertices);
        qInfo("exact: axis %d, errors x %.4f y %.4f z %.6f", s.axis, s.error[0], s.error[1], s.error[2]);
        QCOMPARE(s.axis, 2);
        QVERIFY(s.error[2] < 1e-5);
        QVERIFY(s.error[0] > 0.02 && s.error[1] > 0.02);
        // The plane goes through the bounding-box centre, and each vertex's twin is its reflection.
        const AxisPlane plane = centrePlane(mesh.vertices, 2);
        QVERIFY(std::abs(plane.offset - 1.5) < 1e-5);
        const double diagonal = boundingBox(mesh.vertices).diagonal().norm();
        const std::vector<std::int32_t> twins = mirrorMap(mesh.vertices, plane, 1e-4 * diagonal);
        for (Eigen::Index i = 0; i < mesh.vertices.rows(); ++i) {
            QVERIFY(twins[std::size_t(i)] >= 0);
            const Eigen::Vector3d p = reflect(plane, mesh.vertices.row(i).transpose().cast<double>());
            QVERIFY((mesh.vertices.row(twins[std::size_t(i)]).transpose().cast<double>() - p).norm() < 1e-4 * diagonal);
        }
    }

    void noisySymmetry()
    {
        TriMesh mesh = bentEllipsoid();
        std::mt19937 random(7);
        std::normal_distribution<float> noise(0.f, 0.01f); // 0.2% of the model's size
        for (Eigen::Index i = 0; i < mesh.vertices.rows(); ++i)
            mesh.vertices.row(i) += Eigen::RowVector3f(noise(random), noise(random), noise(random));
        const SymmetryEstimate s = detectSymmetry(mesh.vertices);
        qInfo("noisy: axis %d, errors x %.4f y %.4f z %.4f", s.axis, s.error[0], s.error[1], s.error[2]);
        QCOMPARE(s.axis, 2);
        // No vertex-exact twins at the old tolerance, but every vertex finds its approximate one.
        const AxisPlane plane = centrePlane(mesh.vertices, 2);
        const double diagonal = boundingBox(mesh.vertices).diagonal().norm();
        const std::vector<std::int32_t> exact = mirrorMap(mesh.vertices, plane, 1e-4 * diagonal);
        const auto exactCount = std::count_if(exact.begin(), exact.end(), [](std::int32_t t) { return t >= 0; });
        const std::vector<std::int32_t> twins = mirrorMap(mesh.vertices, plane, 0.05 * diagonal);
        QVERIFY(exactCount < mesh.vertices.rows() / 10);
        QVERIFY(std::all_of(twins.begin(), twins.end(), [](std::int32_t t) { return t >= 0; }));
        // The mesh caches the same.
        QCOMPARE(mesh.symmetry().axis, 2);
        QCOMPARE(mesh.mirrorTwins(2), twins);
    }

    void noPlane()
    {
        // A bent, twisted blob: no axis plane mirrors it within a strict tolerance.
        TriMesh mesh = bentEllipsoid();
        for (Eigen::Index i = 0; i < mesh.vertices.rows(); ++i)
            mesh.vertices(i, 2) += 0.4f * mesh.vertices(i, 0) * mesh.vertices(i, 0) * mesh.vertices(i, 1);
        const SymmetryEstimate s = detectSymmetry(mesh.vertices, 0.01);
        qInfo("none: axis %d, errors x %.4f y %.4f z %.4f", s.axis, s.error[0], s.error[1], s.error[2]);
        QCOMPARE(s.axis, -1); // none within 1% of the model's size
        QVERIFY(s.error[0] > 0.01 && s.error[1] > 0.01 && s.error[2] > 0.01);
        QCOMPARE(detectSymmetry(Positions(0, 3)).axis, -1);
    }

    void elephant()
    {
        CELFORM_REQUIRE_SHARED(path, QStringLiteral("meshes/cgal_elephant.off"));
        const TriMesh mesh = celform::model::importMesh(path).mesh;
        const SymmetryEstimate s = detectSymmetry(mesh.vertices, 0.05);
        qInfo("elephant: %lld vertices, axis %d, errors x %.4f y %.4f z %.4f", qint64(mesh.vertices.rows()), s.axis,
            s.error[0], s.error[1], s.error[2]);
        QCOMPARE(s.axis, 2);
        QVERIFY(s.error[2] < s.error[0] && s.error[2] < s.error[1]);
        // Not vertex-exact symmetric across any plane: the old tolerance pairs (almost) nothing.
        const double diagonal = boundingBox(mesh.vertices).diagonal().norm();
        const std::vector<std::int32_t> exact
            = mirrorMap(mesh.vertices, centrePlane(mesh.vertices, 2), 1e-4 * diagonal);
        const auto exactTwins = std::count_if(exact.begin(), exact.end(), [](std::int32_t t) { return t >= 0; });
        const auto& twins = mesh.mirrorTwins(2);
        const auto approximateTwins = std::count_if(twins.begin(), twins.end(), [](std::int32_t t) { return t >= 0; });
        qInfo("elephant twins: exact %lld, approximate %lld", qint64(exactTwins), qint64(approximateTwins));
        QVERIFY(approximateTwins > mesh.vertices.rows() / 2);
    }
};

QTEST_GUILESS_MAIN(TestSymmetry)
#include "test_symmetry.moc"
