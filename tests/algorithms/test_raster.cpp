// The CPU G-buffer rasteriser (DESIGN.md, "Rendering"): camera round trips, exact pixel-centre
// coverage with the top-left rule, depth order, perspective-correct interpolation against
// analytic ray casts, near-plane clipping, determinism, and anti-aliased hidden-line strokes.
#include "test_support.h"

#include "celform/algorithms/raster.h"

#include <cmath>
#include <cstring>
#include <random>

using namespace celform::algo;

namespace {

/// Orthographic camera looking down -z at an image of w x h pixels, one pixel per model unit:
/// model (x, y) lands on pixel (w / 2 + x, h / 2 - y).
/// n triangles of separate corners drawn uniformly in [-3, 3]^3, each with its face normal.
struct Soup {
    Positions v;
    Faces f;
    Positions normals;
    Soup(int n, unsigned seed)
        : v(3 * n, 3)
        , f(n, 3)
    {
        std::mt19937 rng(seed);
        std::uniform_real_distribution<float> u(-3.f, 3.f);
        for (Eigen::Index i = 0; i < v.rows(); ++i)
            v.row(i) = Eigen::RowVector3f(u(rng), u(rng), u(rng));
        for (int t = 0; t < n; ++t)
            f.row(t) << 3 * t, 3 * t + 1, 3 * t + 2;
        normals = vertexNormals(v, f);
    }
};

/// A perspective camera of w x h pixels at eye looking at target.
RasterCamera lookingAt(const Eigen::Vector3d& eye, const Eigen::Vector3d& target, int w, int h)
{
    RasterCamera c;
    c.eye = eye;
    c.target = target;
    c.width = w;
    c.height = h;
    return c;
}

/// The same elements, bit for bit.
template <typename V> bool sameBytes(const V& x, const V& y)
{
    return x.size() == y.size() && std::memcmp(x.data(), y.data(), x.size() * sizeof(x[0])) == 0;
}

RasterCamera pixelCamera(int w, int h)
{
    RasterCamera c;
    c.eye = Eigen::Vector3d(0, 0, 10);
    c.target = Eigen::Vector3d::Zero();
    c.up = Eigen::Vector3d::UnitY();
    c.orthographic = true;
    c.orthoHeight = h;
    c.width = w;
    c.height = h;
    return c;
}

/// Model point of pixel position (px, py) for pixelCamera(w, h), at height z.
Eigen::RowVector3f atPixel(int w, int h, double px, double py, double z = 0.0)
{
    return Eigen::RowVector3f(float(px - 0.5 * w), float(0.5 * h - py), float(z));
}

struct Mesh {
    Positions v;
    Faces f;
};

/// Axis-aligned square in pixel coordinates as two triangles (diagonal (x0, y0)-(x1, y1)).
Mesh pixelSquare(int w, int h, double x0, double y0, double x1, double y1, double z = 0.0, bool flip = false)
{
    Mesh m;
    m.v.resize(4, 3);
    m.v.row(0) = atPixel(w, h, x0, y0, z);
    m.v.row(1) = atPixel(w, h, x1, y0, z);
    m.v.row(2) = atPixel(w, h, x1, y1, z);
    m.v.row(3) = atPixel(w, h, x0, y1, z);
    m.f.resize(2, 3);
    m.f << 0, 1, 2, 0, 2, 3;
    if (flip)
        m.f << 0, 2, 1, 0, 3, 2;
    return m;
}

Positions noNormals()
{
    return Positions(0, 3);
}

int coveredCount(const GBuffer& g)
{
    int n = 0;
    for (std::int32_t id : g.faceId)
        n += id >= 0 ? 1 : 0;
    return n;
}

/// Ray / triangle plane intersection: parameter along the ray and barycentrics of the hit.
bool intersect(const Eigen::Vector3d& o, const Eigen::Vector3d& d, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
    const Eigen::Vector3d& c, double& t, Eigen::Vector3d& bary)
{
    const Eigen::Vector3d n = (b - a).cross(c - a);
    const double denom = n.dot(d);
    if (std::abs(denom) < 1e-12)
        return false;
    t = n.dot(a - o) / denom;
    const Eigen::Vector3d p = o + t * d;
    const double area = n.squaredNorm();
    bary
        = Eigen::Vector3d((c - b).cross(p - b).dot(n), (a - c).cross(p - c).dot(n), (b - a).cross(p - a).dot(n)) / area;
    return true;
}

/// UV sphere of radius 1 at the origin, outward counter-clockwise faces.
Mesh uvSphere(int slices, int stacks)
{
    Mesh m;
    m.v.resize((stacks + 1) * slices, 3);
    for (int i = 0; i <= stacks; ++i) {
        const double theta = M_PI * i / stacks;
        for (int j = 0; j < slices; ++j) {
            const double phi = 2 * M_PI * j / slices;
            m.v.row(i * slices + j) = Eigen::RowVector3f(float(std::sin(theta) * std::cos(phi)), float(std::cos(theta)),
                float(-std::sin(theta) * std::sin(phi)));
        }
    }
    std::vector<Eigen::Vector3i> tris;
    for (int i = 0; i < stacks; ++i)
        for (int j = 0; j < slices; ++j) {
            const int a = i * slices + j, b = i * slices + (j + 1) % slices;
            const int c = (i + 1) * slices + j, d = (i + 1) * slices + (j + 1) % slices;
            tris.emplace_back(a, c, d);
            tris.emplace_back(a, d, b);
        }
    m.f.resize(Eigen::Index(tris.size()), 3);
    for (std::size_t k = 0; k < tris.size(); ++k)
        m.f.row(Eigen::Index(k)) = tris[k].transpose();
    return m;
}

StyledStroke stroke(std::initializer_list<Eigen::Vector2f> points, float width, float depth)
{
    StyledStroke s;
    s.points = points;
    s.widths.assign(s.points.size(), width);
    s.depths.assign(s.points.size(), depth);
    return s;
}

GBuffer emptyGBuffer(int w, int h)
{
    GBuffer g;
    rasterise(Positions(0, 3), Faces(0, 3), noNormals(), pixelCamera(w, h), g);
    return g;
}

} // namespace

class TestRaster : public QObject {
    Q_OBJECT

private slots:
    void projectRayRoundTrip_data()
    {
        QTest::addColumn<bool>("ortho");
        QTest::addColumn<double>("shift");
        QTest::newRow("perspective") << false << 0.0;
        QTest::newRow("perspective shifted") << false << 0.037;
        QTest::newRow("orthographic") << true << 0.0;
        QTest::newRow("orthographic shifted") << true << -0.05;
    }
    void projectRayRoundTrip()
    {
        QFETCH(bool, ortho);
        QFETCH(double, shift);
        RasterCamera c;
        c.eye = Eigen::Vector3d(1.5, -0.7, 4.2);
        c.target = Eigen::Vector3d(0.1, 0.2, -0.3);
        c.up = Eigen::Vector3d(0.1, 1.0, 0.2);
        c.orthographic = ortho;
        c.fovYDegrees = 40;
        c.orthoHeight = 3;
        c.width = 320;
        c.height = 200;
        c.horizontalShift = shift;
        // Right-handed orthonormal frame.
        QVERIFY(std::abs(c.forward().norm() - 1) < 1e-12 && std::abs(c.right().norm() - 1) < 1e-12);
        QVERIFY((c.forward().cross(c.trueUp()) - c.right()).norm() < 1e-12); // right-handed
        QVERIFY((c.right().cross(c.forward()) - c.trueUp()).norm() < 1e-12);
        QVERIFY(std::abs(c.trueUp().dot(c.forward())) < 1e-12);
        // The view axis projects to the (shifted) image centre.
        const Eigen::Vector3d axis = c.project(c.target);
        QVERIFY(std::abs(axis.x() - (160 + shift * 320)) < 1e-9 && std::abs(axis.y() - 100) < 1e-9);
        QVERIFY(std::abs(axis.z() - (c.target - c.eye).norm()) < 1e-9);
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        for (int k = 0; k < 200; ++k) {
            const Eigen::Vector3d p = c.target + Eigen::Vector3d(u(rng), u(rng), u(rng));
            const Eigen::Vector3d s = c.project(p);
            Eigen::Vector3d o, d;
            c.ray(s.x(), s.y(), o, d);
            QVERIFY(std::abs(d.norm() - 1) < 1e-12);
            const double t = (p - o).dot(d);
            QVERIFY2((o + t * d - p).norm() < 1e-9, "ray misses the projected point");
            QVERIFY(std::abs(s.z() - (p - c.eye).dot(c.forward())) < 1e-9);
            // y is down: a point above the target projects to a smaller row.
            QVERIFY(c.project(p + 0.1 * c.trueUp()).y() < s.y());
            QVERIFY(c.project(p + 0.1 * c.right()).x() > s.x());
        }
    }

    void squareCoverage_data()
    {
        QTest::addColumn<double>("x0");
        QTest::addColumn<double>("y0");
        QTest::addColumn<double>("x1");
        QTest::addColumn<double>("y1");
        QTest::addColumn<bool>("flip");
        QTest::addColumn<QString>("mask"); // rows of the 4 x 4 image, '#' covered
        QTest::newRow("1..3") << 1.0 << 1.0 << 3.0 << 3.0 << false << "....|.##.|.##.|....";
        QTest::newRow("1..3 flipped winding") << 1.0 << 1.0 << 3.0 << 3.0 << true << "....|.##.|.##.|....";
        // Centres exactly on the edges: left and top edges are in, right and bottom are out.
        QTest::newRow("0.5..2.5 top-left") << 0.5 << 0.5 << 2.5 << 2.5 << false << "##..|##..|....|....";
        QTest::newRow("0.5..2.5 flipped") << 0.5 << 0.5 << 2.5 << 2.5 << true << "##..|##..|....|....";
        QTest::newRow("0.5..3.5") << 0.5 << 0.5 << 3.5 << 3.5 << false << "###.|###.|###.|....";
        QTest::newRow("past the image") << -5.0 << 1.2 << 9.0 << 2.7 << false << "....|####|####|....";
        QTest::newRow("between centres") << 1.6 << 1.6 << 2.4 << 2.4 << false << "....|....|....|....";
    }
    void squareCoverage()
    {
        QFETCH(double, x0);
        QFETCH(double, y0);
        QFETCH(double, x1);
        QFETCH(double, y1);
        QFETCH(bool, flip);
        QFETCH(QString, mask);
        const Mesh m = pixelSquare(4, 4, x0, y0, x1, y1, 0.0, flip);
        GBuffer g;
        rasterise(m.v, m.f, noNormals(), pixelCamera(4, 4), g);
        QCOMPARE(g.width, 4);
        QCOMPARE(g.height, 4);
        QString got;
        for (int y = 0; y < 4; ++y) {
            if (y)
                got += '|';
            for (int x = 0; x < 4; ++x)
                got += g.faceId[std::size_t(y * 4 + x)] >= 0 ? '#' : '.';
        }
        QCOMPARE(got, mask);
        for (std::size_t p = 0; p < g.faceId.size(); ++p) {
            if (g.faceId[p] < 0) {
                QVERIFY(std::isinf(g.depth[p]));
            } else {
                QVERIFY(std::abs(g.depth[p] - 10.f) < 1e-5f);
                QVERIFY(std::abs(g.barycentric[p].sum() - 1.f) < 1e-5f);
            }
        }
    }

    /// Triangles rasterised one at a time: every pixel centre of the square is covered by exactly
    /// one of them, also where the shared edges run through pixel centres.
    void sharedEdgesNoGapsNoOverlap_data()
    {
        QTest::addColumn<int>("variant");
        QTest::newRow("diagonal through centres") << 0;
        QTest::newRow("anti-diagonal through centres") << 1;
        QTest::newRow("fan with edges through centres") << 2;
        QTest::newRow("random fan, perspective-free") << 3;
    }
    void sharedEdgesNoGapsNoOverlap()
    {
        QFETCH(int, variant);
        const int w = 16, h = 16;
        Positions v;
        Faces f;
        if (variant <= 1) {
            const Mesh m = pixelSquare(w, h, 0, 0, 16, 16);
            v = m.v;
            f.resize(2, 3);
            if (variant == 0)
                f << 0, 1, 2, 0, 2, 3;
            else
                f << 0, 1, 3, 1, 2, 3;
        } else {
            // A fan around the centre of the square with rim points on the border.
            std::vector<Eigen::Vector2d> rim;
            if (variant == 2) {
                for (double x : {0.0, 4.5, 8.0, 12.5})
                    rim.emplace_back(x, 0.0);
                for (double y : {0.0, 5.5, 8.5, 12.0})
                    rim.emplace_back(16.0, y);
                for (double x : {16.0, 11.5, 8.5, 3.0})
                    rim.emplace_back(x, 16.0);
                for (double y : {16.0, 10.5, 7.5, 1.5})
                    rim.emplace_back(0.0, y);
            } else {
                std::mt19937 rng(3);
                std::uniform_real_distribution<double> u(0.0, 16.0);
                for (int side = 0; side < 4; ++side) {
                    std::vector<double> t = {u(rng), u(rng), u(rng)};
                    std::sort(t.begin(), t.end());
                    const double corner[4][2] = {{0, 0}, {16, 0}, {16, 16}, {0, 16}};
                    rim.emplace_back(corner[side][0], corner[side][1]);
                    for (double s : t) {
                        const double x = side == 0 ? s : side == 1 ? 16 : side == 2 ? 16 - s : 0;
                        const double y = side == 0 ? 0 : side == 1 ? s : side == 2 ? 16 : 16 - s;
                        rim.emplace_back(x, y);
                    }
                }
            }
            const Eigen::Vector2d centre = variant == 2 ? Eigen::Vector2d(8.5, 7.5) : Eigen::Vector2d(7.3, 8.9);
            v.resize(Eigen::Index(rim.size() + 1), 3);
            v.row(0) = atPixel(w, h, centre.x(), centre.y());
            for (std::size_t k = 0; k < rim.size(); ++k)
                v.row(Eigen::Index(k + 1)) = atPixel(w, h, rim[k].x(), rim[k].y());
            f.resize(Eigen::Index(rim.size()), 3);
            for (std::size_t k = 0; k < rim.size(); ++k)
                f.row(Eigen::Index(k)) << 0, std::int32_t(k + 1), std::int32_t((k + 1) % rim.size() + 1);
        }
        std::vector<int> count(std::size_t(w * h), 0);
        for (Eigen::Index t = 0; t < f.rows(); ++t) {
            Faces one = f.row(t);
            GBuffer g;
            rasterise(v, one, noNormals(), pixelCamera(w, h), g);
            for (std::size_t p = 0; p < count.size(); ++p)
                count[p] += g.faceId[p] >= 0 ? 1 : 0;
        }
        int total = 0;
        for (std::size_t p = 0; p < count.size(); ++p) {
            QVERIFY2(count[p] == 1, qPrintable(QStringLiteral("pixel %1 covered %2 times").arg(p).arg(count[p])));
            total += count[p];
        }
        QCOMPARE(total, w * h); // = the square's area in pixels
        GBuffer all;
        rasterise(v, f, noNormals(), pixelCamera(w, h), all);
        QCOMPARE(coveredCount(all), w * h);
    }

    void depthOrdering_data()
    {
        QTest::addColumn<bool>("nearFirst");
        QTest::newRow("near quad first") << true;
        QTest::newRow("far quad first") << false;
    }
    void depthOrdering()
    {
        QFETCH(bool, nearFirst);
        const int w = 12, h = 10;
        const Mesh nearQuad = pixelSquare(w, h, 1, 1, 8, 8, 1.0); // depth 9
        const Mesh farQuad = pixelSquare(w, h, 4, 3, 11, 9, -2.0); // depth 12
        const Mesh& a = nearFirst ? nearQuad : farQuad;
        const Mesh& b = nearFirst ? farQuad : nearQuad;
        Positions v(8, 3);
        v << a.v, b.v;
        Faces f(4, 3);
        f << a.f, (b.f.array() + 4).matrix();
        GBuffer g;
        rasterise(v, f, noNormals(), pixelCamera(w, h), g);
        const std::int32_t nearIds = nearFirst ? 0 : 2;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const double cx = x + 0.5, cy = y + 0.5;
                const bool inNear = cx > 1 && cx < 8 && cy > 1 && cy < 8;
                const bool inFar = cx > 4 && cx < 11 && cy > 3 && cy < 9;
                const std::size_t p = std::size_t(y * w + x);
                if (inNear) {
                    QVERIFY(g.faceId[p] == nearIds || g.faceId[p] == nearIds + 1);
                    QCOMPARE(g.depth[p], 9.f);
                } else if (inFar) {
                    QVERIFY(g.faceId[p] == 2 - nearIds || g.faceId[p] == 3 - nearIds);
                    QCOMPARE(g.depth[p], 12.f);
                } else {
                    QCOMPARE(g.faceId[p], -1);
                }
            }
    }

    void depthTieLowerFaceWins()
    {
        const int w = 8, h = 8;
        const Mesh m = pixelSquare(w, h, 0, 0, 8, 8);
        Positions v(8, 3);
        v << m.v, m.v;
        Faces f(4, 3);
        f << m.f, (m.f.array() + 4).matrix();
        GBuffer g;
        rasterise(v, f, noNormals(), pixelCamera(w, h), g);
        for (std::int32_t id : g.faceId)
            QVERIFY(id == 0 || id == 1);
    }

    void perspectiveCorrectBarycentrics_data()
    {
        QTest::addColumn<double>("shift");
        QTest::newRow("centred") << 0.0;
        QTest::newRow("shifted") << 0.08;
    }
    void perspectiveCorrectBarycentrics()
    {
        QFETCH(double, shift);
        RasterCamera c;
        c.eye = Eigen::Vector3d(0.3, 0.5, 4);
        c.target = Eigen::Vector3d::Zero();
        c.fovYDegrees = 50;
        c.width = 64;
        c.height = 48;
        c.horizontalShift = shift;
        Positions v(3, 3);
        v << -2, -1.5, -1, 2, -1, -3, 0, 2, 0.5;
        Faces f(1, 3);
        f << 0, 1, 2;
        Positions n(3, 3);
        n << 1, 0, 0, 0, 1, 0, 0, 0.6f, 0.8f;
        GBuffer g;
        rasterise(v, f, n, c, g);
        const Eigen::Vector3d a = v.row(0).cast<double>().transpose();
        const Eigen::Vector3d b = v.row(1).cast<double>().transpose();
        const Eigen::Vector3d d = v.row(2).cast<double>().transpose();
        int checked = 0;
        for (int y = 0; y < c.height; ++y)
            for (int x = 0; x < c.width; ++x) {
                Eigen::Vector3d o, dir, bary;
                double t = 0;
                c.ray(x + 0.5, y + 0.5, o, dir);
                QVERIFY(intersect(o, dir, a, b, d, t, bary));
                const std::size_t p = std::size_t(y * c.width + x);
                if (bary.minCoeff() < -1e-3 || t <= 0) {
                    QCOMPARE(g.faceId[p], -1);
                    continue;
                }
                if (bary.minCoeff() < 1e-3) // on an edge (within the 1/256 pixel snapping): either answer
                    continue;
                QCOMPARE(g.faceId[p], 0);
                const Eigen::Vector3d hit = o + t * dir;
                QVERIFY((g.barycentric[p].cast<double>() - bary).cwiseAbs().maxCoeff() < 1e-5);
                QVERIFY((g.position[p].cast<double>() - hit).norm() < 1e-5);
                QVERIFY(std::abs(double(g.depth[p]) - (hit - c.eye).dot(c.forward())) < 1e-5);
                const Eigen::Vector3d expected
                    = (bary[0] * n.row(0) + bary[1] * n.row(1) + bary[2] * n.row(2)).cast<double>().normalized();
                QVERIFY((g.normal[p].cast<double>() - expected).norm() < 1e-5);
                ++checked;
            }
        QVERIFY(checked > 300);
    }

    /// Ground triangles with corners behind the eye: clipped at the near plane, the visible part
    /// is still drawn, matching an analytic ray cast.
    void nearPlaneClipping_data()
    {
        QTest::addColumn<bool>("ortho");
        QTest::addColumn<int>("behind");
        QTest::newRow("perspective, one corner behind") << false << 1;
        QTest::newRow("perspective, two corners behind") << false << 2;
        QTest::newRow("orthographic, two corners behind") << true << 2;
    }
    void nearPlaneClipping()
    {
        QFETCH(bool, ortho);
        QFETCH(int, behind);
        RasterCamera c;
        c.eye = Eigen::Vector3d(0, 1, 0);
        c.target = Eigen::Vector3d(0, 0.5, -3);
        c.fovYDegrees = 70;
        c.orthographic = ortho;
        c.orthoHeight = 4;
        c.width = 80;
        c.height = 60;
        Positions v(3, 3);
        if (behind == 1)
            v << 0, 0, 6, -30, 0, -40, 30, 0, -40;
        else
            v << -8, 0, 5, 8, 0, 5, 0, 0, -60;
        Faces f(1, 3);
        f << 0, 1, 2;
        GBuffer g;
        rasterise(v, f, noNormals(), c, g);
        const Eigen::Vector3d a = v.row(0).cast<double>().transpose();
        const Eigen::Vector3d b = v.row(1).cast<double>().transpose();
        const Eigen::Vector3d d = v.row(2).cast<double>().transpose();
        int drawn = 0;
        for (int y = 0; y < c.height; ++y)
            for (int x = 0; x < c.width; ++x) {
                Eigen::Vector3d o, dir, bary;
                double t = 0;
                c.ray(x + 0.5, y + 0.5, o, dir);
                const std::size_t p = std::size_t(y * c.width + x);
                const bool hits = intersect(o, dir, a, b, d, t, bary);
                if (hits && (std::abs(bary.minCoeff()) < 1e-3 || std::abs(t) < 1e-2))
                    continue; // on an edge or at the near plane: either answer is right
                const bool inside = hits && t > 0 && bary.minCoeff() > 0;
                QVERIFY2(inside == (g.faceId[p] == 0), qPrintable(QStringLiteral("pixel %1, %2").arg(x).arg(y)));
                if (inside) {
                    ++drawn;
                    const Eigen::Vector3d hit = o + t * dir;
                    QVERIFY(std::abs(double(g.depth[p]) - (hit - c.eye).dot(c.forward())) < 1e-4 * (1 + t));
                    QVERIFY((g.position[p].cast<double>() - hit).norm() < 1e-4 * (1 + t));
                }
            }
        QVERIFY(drawn > c.width * c.height / 4);
    }

    void deterministic()
    {
        const Soup soup(3000, 11);
        // Inside the soup: many triangles cross the near plane.
        const RasterCamera c = lookingAt({0.5, 0.2, 2.0}, {0, 0, -1}, 160, 120);
        GBuffer g1, g2;
        rasterise(soup.v, soup.f, soup.normals, c, g1);
        rasterise(soup.v, soup.f, soup.normals, c, g2);
        QVERIFY(coveredCount(g1) > 1000);
        QVERIFY(sameBytes(g1.depth, g2.depth));
        QVERIFY(sameBytes(g1.faceId, g2.faceId));
        QVERIFY(sameBytes(g1.position, g2.position));
        QVERIFY(sameBytes(g1.normal, g2.normal));
        QVERIFY(sameBytes(g1.barycentric, g2.barycentric));
    }

    /// Without positions (issue 29), the G-buffer says which normals face away from the eye, as the
    /// renderer's test on the positions would (normal . (eye - point) < 0, in float), and holds the
    /// same depth, ids, normals and barycentrics. The soup's faces are seen from both sides, so
    /// both answers occur.
    void facesAwayWithoutPositions()
    {
        const Soup soup(2000, 5);
        const RasterCamera c = lookingAt({0.3, -0.2, 9.0}, {0, 0, 0}, 150, 110);
        GBuffer with, without;
        rasterise(soup.v, soup.f, soup.normals, c, with);
        rasterise(soup.v, soup.f, soup.normals, c, without, false);
        QVERIFY(without.position.empty());
        QVERIFY(with.facesAway.empty());
        QCOMPARE(without.facesAway.size(), with.faceId.size());
        QVERIFY(sameBytes(with.depth, without.depth));
        QVERIFY(sameBytes(with.faceId, without.faceId));
        QVERIFY(sameBytes(with.normal, without.normal));
        QVERIFY(sameBytes(with.barycentric, without.barycentric));
        const Eigen::Vector3f eye = c.eye.cast<float>();
        int away = 0, towards = 0;
        for (std::size_t i = 0; i < with.faceId.size(); ++i) {
            if (with.faceId[i] < 0) {
                QCOMPARE(int(without.facesAway[i]), 0);
                continue;
            }
            const bool expected = with.normal[i].dot(eye - with.position[i]) < 0.f;
            QCOMPARE(without.facesAway[i] != 0, expected);
            (expected ? away : towards) += 1;
        }
        QVERIFY2(
            away > 1000 && towards > 1000, qPrintable(QStringLiteral("%1 away, %2 towards").arg(away).arg(towards)));
        // The storage is reused: a second G-buffer made with positions drops facesAway again.
        rasterise(soup.v, soup.f, soup.normals, c, without);
        QVERIFY(without.facesAway.empty());
        QVERIFY(sameBytes(with.position, without.position));
    }

    void sphereSilhouetteNormals()
    {
        const Mesh m = uvSphere(96, 48);
        const Positions normals = vertexNormals(m.v, m.f);
        RasterCamera c = pixelCamera(120, 120);
        c.orthoHeight = 2.4; // radius 50 pixels
        GBuffer g;
        rasterise(m.v, m.f, normals, c, g);
        const int row = 60;
        int leftmost = -1, rightmost = -1;
        for (int x = 0; x < c.width; ++x)
            if (g.faceId[std::size_t(row * c.width + x)] >= 0) {
                if (leftmost < 0)
                    leftmost = x;
                rightmost = x;
            }
        QVERIFY(leftmost >= 9 && leftmost <= 11);
        QVERIFY(rightmost >= 108 && rightmost <= 110);
        const Eigen::Vector3f nl = g.normal[std::size_t(row * c.width + leftmost)];
        const Eigen::Vector3f nr = g.normal[std::size_t(row * c.width + rightmost)];
        QVERIFY(std::abs(nl.norm() - 1.f) < 1e-5f);
        QVERIFY2(nl.x() < -0.97f && std::abs(nl.z()) < 0.25f, "left silhouette normal points left");
        QVERIFY2(nr.x() > 0.97f && std::abs(nr.z()) < 0.25f, "right silhouette normal points right");
        const Eigen::Vector3f centre = g.normal[std::size_t(row * c.width + 60)];
        QVERIFY(centre.z() > 0.99f); // the near hemisphere faces the eye at +z
        QVERIFY(std::abs(g.depth[std::size_t(row * c.width + 60)] - 9.f) < 0.01f);
    }

    void strokeWidthAndAntialiasing_data()
    {
        QTest::addColumn<float>("y");
        QTest::addColumn<float>("width");
        QTest::addColumn<QVector<float>>("rows"); // coverage of rows 7..13 mid-line
        QTest::newRow("width 3 on a row centre") << 10.5f << 3.f << QVector<float>{0, 0, 1, 1, 1, 0, 0};
        QTest::newRow("width 3.5 on a row centre") << 10.5f << 3.5f << QVector<float>{0, 0.25f, 1, 1, 1, 0.25f, 0};
        QTest::newRow("width 3 off centre") << 10.25f << 3.f << QVector<float>{0, 0.25f, 1, 1, 0.75f, 0, 0};
    }
    void strokeWidthAndAntialiasing()
    {
        QFETCH(float, y);
        QFETCH(float, width);
        QFETCH(QVector<float>, rows);
        const GBuffer g = emptyGBuffer(50, 20);
        std::vector<float> coverage;
        drawStrokes({stroke({{5.f, y}, {45.f, y}}, width, 5.f)}, g, coverage);
        QCOMPARE(coverage.size(), std::size_t(50 * 20));
        for (int x = 8; x < 42; ++x)
            for (int r = 0; r < rows.size(); ++r)
                QVERIFY2(std::abs(coverage[std::size_t((7 + r) * 50 + x)] - rows[r]) < 1e-6f,
                    qPrintable(QStringLiteral("x %1 row %2: %3")
                                   .arg(x)
                                   .arg(7 + r)
                                   .arg(coverage[std::size_t((7 + r) * 50 + x)])));
        // Round caps: nothing beyond the end plus the half width and the ramp.
        QCOMPARE(coverage[std::size_t(10 * 50 + 1)], 0.f);
        QVERIFY(coverage[std::size_t(10 * 50 + 5)] > 0.99f);
    }

    void strokeRoundJoin()
    {
        const GBuffer g = emptyGBuffer(40, 40);
        std::vector<float> coverage;
        drawStrokes({stroke({{5.5f, 20.5f}, {20.5f, 20.5f}, {20.5f, 35.5f}}, 3.f, 5.f)}, g, coverage);
        // Every pixel centre within 1 pixel of the polyline is fully covered, the outer corner too.
        for (int y = 0; y < 40; ++y)
            for (int x = 0; x < 40; ++x) {
                const float cx = x + 0.5f, cy = y + 0.5f;
                const float d1 = (cx >= 5.5f && cx <= 20.5f) ? std::abs(cy - 20.5f) : 1e9f;
                const float d2 = (cy >= 20.5f && cy <= 35.5f) ? std::abs(cx - 20.5f) : 1e9f;
                const float corner = Eigen::Vector2f(cx - 20.5f, cy - 20.5f).norm();
                if (std::min({d1, d2, corner}) <= 1.f)
                    QCOMPARE(coverage[std::size_t(y * 40 + x)], 1.f);
            }
        QVERIFY(std::abs(coverage[std::size_t(19 * 40 + 21)] - (2.f - std::sqrt(2.f))) < 1e-5f);
    }

    void strokeHiddenBehindSurface_data()
    {
        QTest::addColumn<float>("depth");
        QTest::addColumn<bool>("visibleOverQuad");
        QTest::newRow("behind the quad") << 11.f << false;
        QTest::newRow("on the quad, within the bias") << 10.05f << true;
        QTest::newRow("in front of the quad") << 9.f << true;
    }
    void strokeHiddenBehindSurface()
    {
        QFETCH(float, depth);
        QFETCH(bool, visibleOverQuad);
        const int w = 40, h = 20;
        const Mesh quad = pixelSquare(w, h, 0, 0, 20, 20); // left half, depth 10
        GBuffer g;
        rasterise(quad.v, quad.f, noNormals(), pixelCamera(w, h), g);
        std::vector<float> coverage(std::size_t(w * h), 0.f);
        drawStrokes({stroke({{2.f, 10.5f}, {38.f, 10.5f}}, 1.f, depth)}, g, coverage);
        for (int x = 3; x < 37; ++x) {
            const float value = coverage[std::size_t(10 * w + x)];
            if (x >= 20)
                QCOMPARE(value, 1.f); // off the mesh: always drawn
            else
                QCOMPARE(value, visibleOverQuad ? 1.f : 0.f);
        }
    }

    void strokesCombineWithMax()
    {
        const GBuffer g = emptyGBuffer(20, 20);
        std::vector<float> coverage(20 * 20, 0.5f);
        drawStrokes({stroke({{2.f, 10.25f}, {18.f, 10.25f}}, 3.f, 5.f)}, g, coverage);
        QCOMPARE(coverage[std::size_t(8 * 20 + 10)], 0.5f); // 0.25 < 0.5 stays
        QCOMPARE(coverage[std::size_t(11 * 20 + 10)], 0.75f); // raised to 0.75
        QCOMPARE(coverage[std::size_t(10 * 20 + 10)], 1.f);
        QCOMPARE(coverage[std::size_t(2 * 20 + 10)], 0.5f);
    }
};

QTEST_GUILESS_MAIN(TestRaster)
#include "test_raster.moc"
