// Camera from correspondences: synthetic cameras are recovered from their own projections, noise
// gives the expected residual, and degenerate input is refused with a message.
#include "test_support.h"

#include "celform/algorithms/camera_solve.h"

#include <Eigen/Geometry>

#include <cmath>
#include <random>

using namespace celform::algo;

Q_DECLARE_METATYPE(Eigen::Vector3d)

namespace {

constexpr int kWidth = 1600;
constexpr int kHeight = 1000;

SolvedCamera makeCamera(
    const Eigen::Vector3d& eye, const Eigen::Vector3d& target, const Eigen::Vector3d& up, double fov)
{
    SolvedCamera c;
    c.eye = eye;
    c.target = target;
    c.up = up;
    c.fovYDegrees = fov;
    return c;
}

Eigen::Vector3d forwardOf(const SolvedCamera& c)
{
    return (c.target - c.eye).normalized();
}

/// The camera's true up: up made orthogonal to the view axis.
Eigen::Vector3d upOf(const SolvedCamera& c)
{
    const Eigen::Vector3d f = forwardOf(c);
    return f.cross(c.up).normalized().cross(f);
}

/// count points spread over a box of half-size `spread` around centre (not coplanar).
std::vector<Eigen::Vector3d> randomPoints(int count, const Eigen::Vector3d& centre, double spread, unsigned seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-spread, spread);
    std::vector<Eigen::Vector3d> points;
    for (int i = 0; i < count; ++i)
        points.push_back(centre + Eigen::Vector3d(u(rng), u(rng), u(rng)));
    return points;
}

std::vector<Eigen::Vector2d> project(const SolvedCamera& c, const std::vector<Eigen::Vector3d>& points)
{
    std::vector<Eigen::Vector2d> pixels;
    for (const auto& p : points)
        pixels.push_back(projectToImage(c, p, kWidth, kHeight));
    return pixels;
}

} // namespace

class TestCameraSolve : public QObject {
    Q_OBJECT
private slots:
    void projectionConventions()
    {
        // Looking down -z with y up: right of the axis is +x pixels, above it is smaller y.
        const SolvedCamera c = makeCamera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 60.0);
        const Eigen::Vector2d centre = projectToImage(c, {0, 0, 0}, kWidth, kHeight);
        QVERIFY((centre - Eigen::Vector2d(800, 500)).norm() < 1e-9);
        const Eigen::Vector2d upperRight = projectToImage(c, {1, 1, 0}, kWidth, kHeight);
        QVERIFY(upperRight.x() > 800 && upperRight.y() < 500);
        // The top edge of the image is at half the vertical field of view.
        const Eigen::Vector2d top = projectToImage(c, {0, 5 * std::tan(30.0 * M_PI / 180.0), 0}, kWidth, kHeight);
        QVERIFY((top - Eigen::Vector2d(800, 0)).norm() < 1e-9);
        // Behind the eye: not a pixel.
        QVERIFY(!projectToImage(c, {0, 0, 6}, kWidth, kHeight).allFinite());
    }

    void recoversSyntheticCamera_data()
    {
        QTest::addColumn<Eigen::Vector3d>("eye");
        QTest::addColumn<Eigen::Vector3d>("target");
        QTest::addColumn<Eigen::Vector3d>("up");
        QTest::addColumn<double>("fov");
        QTest::addColumn<int>("count");
        QTest::newRow("front, 30 deg, 8 points")
            << Eigen::Vector3d(0, 0, 6) << Eigen::Vector3d(0, 0, 0) << Eigen::Vector3d(0, 1, 0) << 30.0 << 8;
        QTest::newRow("oblique, tilted up, 12 points")
            << Eigen::Vector3d(3.5, 2.0, 4.0) << Eigen::Vector3d(0.2, -0.1, 0.3) << Eigen::Vector3d(0.3, 1.0, -0.2)
            << 45.0 << 12;
        QTest::newRow("from below, wide, 20 points")
            << Eigen::Vector3d(-1.0, -3.0, 0.5) << Eigen::Vector3d(0, 0, 0) << Eigen::Vector3d(0, 0, 1) << 70.0 << 20;
        QTest::newRow("telephoto, 10 points") << Eigen::Vector3d(10.0, 4.0, -12.0) << Eigen::Vector3d(0.5, 0.5, 0.0)
                                              << Eigen::Vector3d(0, 1, 0) << 12.0 << 10;
        QTest::newRow("minimum, 6 points")
            << Eigen::Vector3d(2.0, 1.0, 5.0) << Eigen::Vector3d(0, 0, 0) << Eigen::Vector3d(0, 1, 0) << 40.0 << 6;
    }
    void recoversSyntheticCamera()
    {
        QFETCH(Eigen::Vector3d, eye);
        QFETCH(Eigen::Vector3d, target);
        QFETCH(Eigen::Vector3d, up);
        QFETCH(double, fov);
        QFETCH(int, count);
        const SolvedCamera truth = makeCamera(eye, target, up, fov);
        const std::vector<Eigen::Vector3d> points = randomPoints(count, target, 1.0, unsigned(count));
        const std::vector<Eigen::Vector2d> pixels = project(truth, points);
        std::string error;
        const std::optional<SolvedCamera> solved = solveCamera(points, pixels, kWidth, kHeight, &error);
        QVERIFY2(solved, error.c_str());
        const double scale = (eye - target).norm();
        QVERIFY((solved->eye - eye).norm() < 1e-6 * scale);
        QVERIFY(forwardOf(*solved).dot(forwardOf(truth)) > 1.0 - 1e-12);
        QVERIFY(solved->up.normalized().dot(upOf(truth)) > 1.0 - 1e-12);
        QVERIFY(std::abs(solved->up.normalized().dot(forwardOf(*solved))) < 1e-9);
        QVERIFY(std::abs(solved->fovYDegrees - fov) < 1e-6);
        QVERIFY(solved->rmsPixelError < 1e-6);
        // target: on the axis at the distance of the points' centroid.
        Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
        for (const auto& p : points)
            centroid += p / double(points.size());
        QVERIFY(std::abs((solved->target - solved->eye).norm() - (centroid - solved->eye).norm()) < 1e-9 * scale);
        // The solved camera reproduces the pixels.
        for (std::size_t i = 0; i < points.size(); ++i)
            QVERIFY((projectToImage(*solved, points[i], kWidth, kHeight) - pixels[i]).norm() < 1e-5);
    }

    void noiseGivesMatchingResidual()
    {
        const SolvedCamera truth = makeCamera({2.5, 1.5, 5.0}, {0, 0, 0}, {0, 1, 0}, 35.0);
        const std::vector<Eigen::Vector3d> points = randomPoints(20, {0, 0, 0}, 1.0, 77);
        std::vector<Eigen::Vector2d> pixels = project(truth, points);
        // 0.5 px in a random direction: an rms distance of 0.5 px before fitting.
        std::mt19937 rng(5);
        std::uniform_real_distribution<double> angle(0.0, 2.0 * M_PI);
        for (auto& px : pixels) {
            const double a = angle(rng);
            px += 0.5 * Eigen::Vector2d(std::cos(a), std::sin(a));
        }
        std::string error;
        const std::optional<SolvedCamera> solved = solveCamera(points, pixels, kWidth, kHeight, &error);
        QVERIFY2(solved, error.c_str());
        // 7 parameters absorb a little of the 40 coordinates' noise: about 0.5 * sqrt(33/40).
        QVERIFY2(solved->rmsPixelError > 0.3 && solved->rmsPixelError < 0.55,
            qPrintable(QString::number(solved->rmsPixelError)));
        const double eyeError = (solved->eye - truth.eye).norm() / (truth.eye - truth.target).norm();
        qInfo("0.5 px noise: rms %.3f px, eye off by %.4f of the distance, fov %.3f deg (true %.1f)",
            solved->rmsPixelError, eyeError, solved->fovYDegrees, truth.fovYDegrees);
        QVERIFY2(eyeError < 0.01, qPrintable(QString::number(eyeError)));
        QVERIFY(forwardOf(*solved).dot(forwardOf(truth)) > std::cos(0.2 * M_PI / 180.0));
        QVERIFY(std::abs(solved->fovYDegrees - truth.fovYDegrees) < 0.3);
    }

    void refusesBadInput()
    {
        const SolvedCamera truth = makeCamera({0, 0, 6}, {0, 0, 0}, {0, 1, 0}, 30.0);
        std::vector<Eigen::Vector3d> points = randomPoints(8, {0, 0, 0}, 1.0, 3);
        std::vector<Eigen::Vector2d> pixels = project(truth, points);
        std::string error;

        const std::vector<Eigen::Vector3d> five(points.begin(), points.begin() + 5);
        const std::vector<Eigen::Vector2d> fivePx(pixels.begin(), pixels.begin() + 5);
        QVERIFY(!solveCamera(five, fivePx, kWidth, kHeight, &error));
        QVERIFY2(error.find("At least 6") != std::string::npos, error.c_str());

        error.clear();
        QVERIFY(!solveCamera(points, fivePx, kWidth, kHeight, &error));
        QVERIFY2(error.find("differ") != std::string::npos, error.c_str());

        error.clear();
        std::vector<Eigen::Vector2d> withNan = pixels;
        withNan[3].x() = std::numeric_limits<double>::quiet_NaN();
        QVERIFY(!solveCamera(points, withNan, kWidth, kHeight, &error));
        QVERIFY2(error.find("non-finite") != std::string::npos, error.c_str());

        // All on the plane z = 0.3 (tilted view so the image is not degenerate).
        error.clear();
        const SolvedCamera oblique = makeCamera({2, 3, 6}, {0, 0, 0}, {0, 1, 0}, 30.0);
        std::vector<Eigen::Vector3d> planar = randomPoints(10, {0, 0, 0}, 1.0, 4);
        for (auto& p : planar)
            p.z() = 0.3;
        QVERIFY(!solveCamera(planar, project(oblique, planar), kWidth, kHeight, &error));
        QVERIFY2(error.find("coplanar") != std::string::npos, error.c_str());

        // Nearly coplanar (1e-6 of the spread) counts as coplanar.
        error.clear();
        std::mt19937 rng(1);
        std::uniform_real_distribution<double> tiny(-1e-6, 1e-6);
        for (auto& p : planar)
            p.z() += tiny(rng);
        QVERIFY(!solveCamera(planar, project(oblique, planar), kWidth, kHeight, &error));
        QVERIFY2(error.find("coplanar") != std::string::npos, error.c_str());

        // Half the points behind the eye, "projected" through it by the pinhole formula: the
        // linear fit is exact but no real camera sees them.
        error.clear();
        std::vector<Eigen::Vector3d> around = randomPoints(12, {0, 0, 0}, 1.0, 6);
        std::vector<Eigen::Vector2d> through;
        const double focal = 0.5 * kHeight / std::tan(15.0 * M_PI / 180.0);
        for (std::size_t i = 0; i < around.size(); ++i) {
            around[i].z() += i % 2 ? 3.0 : -3.0; // eye at the origin looking down -z
            const Eigen::Vector3d q = around[i];
            through.emplace_back(0.5 * kWidth + focal * q.x() / -q.z(), 0.5 * kHeight - focal * q.y() / -q.z());
        }
        QVERIFY(!solveCamera(around, through, kWidth, kHeight, &error));
        QVERIFY2(error.find("behind") != std::string::npos, error.c_str());

        error.clear();
        QVERIFY(!solveCamera(points, pixels, 0, kHeight, &error));
        QVERIFY(!error.empty());
    }
};

QTEST_GUILESS_MAIN(TestCameraSolve)
#include "test_camera_solve.moc"
