// Stylized highlights (Anjyo & Hiramitsu 2003) sampled on grids of surface points of a unit
// sphere seen from +Z with the light at +Z, and of the plane z = 0 under a point light: what each
// operation does to the area's position and shape, post operations, keyframes, tangent frames.
#include "test_support.h"

#include "celform/algorithms/highlights.h"
#include "celform/algorithms/render.h"

#include <array>
#include <cmath>
#include <vector>

using namespace celform::algo;
using Eigen::Vector3f;

Q_DECLARE_METATYPE(celform::algo::HighlightOperation)

namespace {

/// Two triangles per cell of a k by k vertex grid numbered row by row.
Faces gridFaces(int k)
{
    Faces faces(2 * (k - 1) * (k - 1), 3);
    int f = 0;
    for (int j = 0; j + 1 < k; ++j)
        for (int i = 0; i + 1 < k; ++i) {
            const int a = j * k + i;
            faces.row(f++) << a, a + 1, a + k + 1;
            faces.row(f++) << a, a + k + 1, a + k;
        }
    return faces;
}

enum class Scene { Sphere, Plane };

/// A 0/1 (or coverage) mask on an n x n grid over [-extent, extent]^2 of the scene's x, y.
struct Mask {
    int n = 0;
    float extent = 1.0f;
    std::vector<float> values;
    [[nodiscard]] float at(int i, int j) const { return values[size_t(j * n + i)]; }
    [[nodiscard]] bool in(int i, int j) const { return i >= 0 && j >= 0 && i < n && j < n && at(i, j) >= 0.5f; }
    [[nodiscard]] float x(int i) const { return extent * (2.0f * (float(i) + 0.5f) / float(n) - 1.0f); }
    [[nodiscard]] int area() const
    {
        int a = 0;
        for (float v : values)
            a += v >= 0.5f ? 1 : 0;
        return a;
    }
    [[nodiscard]] Eigen::Vector2d centroid() const
    {
        Eigen::Vector2d c = Eigen::Vector2d::Zero();
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                if (in(i, j))
                    c += Eigen::Vector2d(x(i), x(j));
        return c / std::max(area(), 1);
    }
    /// Second moments about the centroid: (xx, yy).
    [[nodiscard]] Eigen::Vector2d spread() const
    {
        const Eigen::Vector2d c = centroid();
        Eigen::Vector2d s = Eigen::Vector2d::Zero();
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                if (in(i, j))
                    s += (Eigen::Vector2d(x(i), x(j)) - c).cwiseAbs2();
        return s / std::max(area(), 1);
    }
    /// Area over the area of the axis-aligned bounding box (pi / 4 for a disc, 1 for a square).
    [[nodiscard]] double boxFill() const
    {
        int i0 = n, i1 = -1, j0 = n, j1 = -1;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                if (in(i, j)) {
                    i0 = std::min(i0, i);
                    i1 = std::max(i1, i);
                    j0 = std::min(j0, j);
                    j1 = std::max(j1, j);
                }
        return i1 < 0 ? 0.0 : double(area()) / (double(i1 - i0 + 1) * double(j1 - j0 + 1));
    }
    /// 4-connected components of the area.
    [[nodiscard]] int components() const
    {
        std::vector<int> label(values.size(), 0);
        int count = 0;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                if (!in(i, j) || label[size_t(j * n + i)] != 0)
                    continue;
                ++count;
                std::vector<std::array<int, 2>> stack{{i, j}};
                label[size_t(j * n + i)] = count;
                while (!stack.empty()) {
                    const auto [a, b] = stack.back();
                    stack.pop_back();
                    const std::array<std::array<int, 2>, 4> next{{{a + 1, b}, {a - 1, b}, {a, b + 1}, {a, b - 1}}};
                    for (const auto& [c, d] : next)
                        if (c >= 0 && d >= 0 && c < n && d < n && in(c, d) && label[size_t(d * n + c)] == 0) {
                            label[size_t(d * n + c)] = count;
                            stack.push_back({c, d});
                        }
                }
            }
        return count;
    }
    /// True iff every point of this area is in other's.
    [[nodiscard]] bool inside(const Mask& other) const
    {
        for (size_t k = 0; k < values.size(); ++k)
            if (values[k] >= 0.5f && other.values[k] < 0.5f)
                return false;
        return true;
    }
};

struct SceneSetup {
    HighlightLight light;
    Vector3f eye;
    float extent;
};

SceneSetup setup(Scene scene)
{
    if (scene == Scene::Sphere)
        return {HighlightLight{false, Vector3f::UnitZ()}, Vector3f(0.0f, 0.0f, 1000.0f), 1.0f}; // nearly orthographic
    // Point light next to the eye, both 2 above the plane's origin.
    return {HighlightLight{true, Vector3f(0.0f, 0.0f, 2.0f)}, Vector3f(0.0f, 0.0f, 2.0f), 2.0f};
}

/// The surface point over grid cell (i, j), false off the sphere's visible disc. Frames: du
/// along +x, dv along +y (on the sphere, +x and +y projected on the tangent plane).
bool surfacePoint(Scene scene, float x, float y, HighlightSurfacePoint& p)
{
    if (scene == Scene::Plane) {
        p.position = Vector3f(x, y, 0.0f);
        p.normal = Vector3f::UnitZ();
        p.frame = {Vector3f::UnitX(), Vector3f::UnitY()};
        return true;
    }
    const float r2 = x * x + y * y;
    if (r2 >= 0.98f)
        return false;
    p.position = Vector3f(x, y, std::sqrt(1.0f - r2));
    p.normal = p.position;
    p.frame = guideTangentFrame(p.normal, Vector3f::UnitX());
    return true;
}

Mask sampleLayers(Scene scene, const std::vector<HighlightLayer>& layers, int n = 201, bool filtered = false)
{
    const SceneSetup s = setup(scene);
    Mask m;
    m.n = n;
    m.extent = s.extent;
    m.values.assign(size_t(n * n), 0.0f);
    const float step = 2.0f * s.extent / float(n);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            HighlightSurfacePoint p;
            if (!surfacePoint(scene, m.x(i), m.x(j), p))
                continue;
            HighlightFootprint fp;
            if (filtered) {
                // Neighbouring grid points give the differentials.
                HighlightSurfacePoint px, py;
                if (!surfacePoint(scene, m.x(i) + step, m.x(j), px) || !surfacePoint(scene, m.x(i), m.x(j) + step, py))
                    continue;
                fp.dPdx = px.position - p.position;
                fp.dPdy = py.position - p.position;
                fp.dNdx = px.normal - p.normal;
                fp.dNdy = py.normal - p.normal;
            }
            m.values[size_t(j * n + i)]
                = evaluateHighlights(p, s.light, s.eye, layers, filtered ? &fp : nullptr).coverage;
        }
    return m;
}

HighlightLayer layerOf(std::vector<HighlightOperation> ops, float epsilon = 0.05f)
{
    HighlightLayer l;
    l.shape.epsilon = epsilon;
    l.shape.operations = std::move(ops);
    return l;
}

Mask sample(Scene scene, std::vector<HighlightOperation> ops, float epsilon = 0.05f)
{
    return sampleLayers(scene, {layerOf(std::move(ops), epsilon)});
}

/// The plane z = 0 over [-1, 1]^2 as a k x k grid of vertices, each lifted by a deterministic
/// pseudo-random height in [-amplitude, amplitude] (the noise of a scanned or sculpted model).
TriMesh bumpyPlane(int k, float amplitude)
{
    TriMesh mesh;
    mesh.vertices.resize(k * k, 3);
    for (int j = 0; j < k; ++j)
        for (int i = 0; i < k; ++i) {
            const double hash = std::sin(double(i) * 12.9898 + double(j) * 78.233) * 43758.5453;
            const float noise = float(2.0 * (hash - std::floor(hash)) - 1.0);
            mesh.vertices.row(j * k + i) << -1.0f + 2.0f * float(i) / float(k - 1),
                -1.0f + 2.0f * float(j) / float(k - 1), amplitude * noise;
        }
    mesh.faces = gridFaces(k);
    return mesh;
}

/// The highlights pass of renderFrame as a mask (n x n pixels).
Mask highlightsPassMask(const RenderPasses& passes, int n)
{
    Mask m;
    m.n = n;
    m.values = passes.highlights;
    return m;
}

/// Edges between pixels in and out of the area (4-neighbourhood; the image border counts as out).
int perimeter(const Mask& m)
{
    int edges = 0;
    for (int j = 0; j < m.n; ++j)
        for (int i = 0; i < m.n; ++i)
            if (m.in(i, j))
                edges += int(!m.in(i + 1, j)) + int(!m.in(i - 1, j)) + int(!m.in(i, j + 1)) + int(!m.in(i, j - 1));
    return edges;
}

QByteArray describe(const Eigen::Vector2d& v)
{
    return QByteArray::number(v.x()) + ", " + QByteArray::number(v.y());
}

} // namespace

class TestHighlights : public QObject {
    Q_OBJECT

    static void addScenes()
    {
        QTest::addColumn<int>("scene");
        QTest::newRow("sphere, light at +Z") << int(Scene::Sphere);
        QTest::newRow("plane, point light") << int(Scene::Plane);
    }

private slots:
    void originalHighlightIsBlinn_data() { addScenes(); }
    void originalHighlightIsBlinn()
    {
        // Eq. 1: (N, H) > 1 - epsilon with H the halfway vector; centred under light and eye.
        QFETCH(int, scene);
        const Mask m = sample(Scene(scene), {});
        QVERIFY(m.area() > 100);
        QVERIFY(m.centroid().norm() < 0.01);
        QCOMPARE(m.components(), 1);
        // A disc: the expected radius from (N, H) = 1 - epsilon.
        const double r = scene == int(Scene::Sphere) ? std::sin(std::acos(0.95) / 1.0) // H ~ +Z
                                                     : 2.0 * std::sqrt(1.0 / (0.95 * 0.95) - 1.0);
        const double cell = 2.0 * m.extent / m.n;
        const double expected = M_PI * r * r / (cell * cell);
        QVERIFY2(std::abs(m.area() - expected) < 0.05 * expected,
            QByteArray::number(m.area()) + " vs " + QByteArray::number(expected));
        // The same by the lower-level functions.
        const SceneSetup s = setup(Scene(scene));
        HighlightSurfacePoint p;
        QVERIFY(surfacePoint(Scene(scene), 0.05f, -0.02f, p));
        const Vector3f h = halfwayVector(p.position, s.light, s.eye);
        QCOMPARE(highlightFunction(h, p.normal, p.frame, HighlightShape{}), p.normal.dot(h));
    }

    void translationMovesAlongFrame_data()
    {
        QTest::addColumn<int>("scene");
        QTest::addColumn<float>("alpha");
        QTest::addColumn<float>("beta");
        for (const int scene : {int(Scene::Sphere), int(Scene::Plane)}) {
            const char* name = scene == int(Scene::Sphere) ? "sphere" : "plane";
            QTest::addRow("%s, alpha", name) << scene << 0.2f << 0.0f;
            QTest::addRow("%s, beta", name) << scene << 0.0f << 0.2f;
            QTest::addRow("%s, -alpha", name) << scene << -0.2f << 0.0f;
            QTest::addRow("%s, alpha and beta", name) << scene << 0.15f << 0.15f;
        }
    }
    void translationMovesAlongFrame()
    {
        QFETCH(int, scene);
        QFETCH(float, alpha);
        QFETCH(float, beta);
        const Eigen::Vector2d c0 = sample(Scene(scene), {}).centroid();
        const Mask moved = sample(Scene(scene), {HighlightOperation::translation(alpha, beta)});
        QVERIFY(moved.area() > 50);
        const Eigen::Vector2d d = moved.centroid() - c0;
        // du is +x, dv is +y at the centre of either scene.
        const Eigen::Vector2d dir = Eigen::Vector2d(alpha, beta).normalized();
        QVERIFY2(d.dot(dir) > 0.1, describe(d));
        QVERIFY2(std::abs(d.x() * dir.y() - d.y() * dir.x()) < 0.02, describe(d));
    }

    void rotationTurnsLaterOperations_data() { addScenes(); }
    void rotationTurnsLaterOperations()
    {
        QFETCH(int, scene);
        // Rotation alone: (N, H) unchanged, so the same area.
        const Mask base = sample(Scene(scene), {});
        const Mask rotated = sample(Scene(scene), {HighlightOperation::rotation(37.0f)});
        QCOMPARE(rotated.values, base.values);
        // Scaling along du stretches along x; rotating by 90 degrees first stretches along y.
        const Eigen::Vector2d alongU = sample(Scene(scene), {HighlightOperation::directionalScaling(0.8f)}).spread();
        const Eigen::Vector2d alongV
            = sample(Scene(scene), {HighlightOperation::rotation(90.0f), HighlightOperation::directionalScaling(0.8f)})
                  .spread();
        QVERIFY2(alongU.x() > 2.0 * alongU.y(), describe(alongU));
        QVERIFY2(alongV.y() > 2.0 * alongV.x(), describe(alongV));
        // Rotation turns the translation direction too: +du after 90 degrees is +y.
        const Eigen::Vector2d c
            = sample(Scene(scene), {HighlightOperation::rotation(90.0f), HighlightOperation::translation(0.2f, 0.0f)})
                  .centroid();
        QVERIFY2(c.y() > 0.1 && std::abs(c.x()) < 0.02, describe(c));
    }

    void directionalScalingGrowsAndContains_data()
    {
        QTest::addColumn<int>("scene");
        QTest::addColumn<float>("delta");
        for (const int scene : {int(Scene::Sphere), int(Scene::Plane)})
            for (const float delta : {0.3f, 0.6f, 0.9f})
                QTest::addRow("%s, delta %.1f", scene == int(Scene::Sphere) ? "sphere" : "plane", double(delta))
                    << scene << delta;
    }
    void directionalScalingGrowsAndContains()
    {
        QFETCH(int, scene);
        QFETCH(float, delta);
        const Mask base = sample(Scene(scene), {});
        const Mask scaled = sample(Scene(scene), {HighlightOperation::directionalScaling(delta)});
        QVERIFY(scaled.area() > base.area());
        // Paper, after eq. 4: H*[epsilon] includes H_epsilon.
        QVERIFY(base.inside(scaled));
        const Eigen::Vector2d s = scaled.spread();
        QVERIFY2(s.x() > s.y(), describe(s));
    }

    void splitMakesPieces_data()
    {
        QTest::addColumn<int>("scene");
        QTest::addColumn<float>("gamma1");
        QTest::addColumn<float>("gamma2");
        QTest::addColumn<int>("pieces");
        for (const int scene : {int(Scene::Sphere), int(Scene::Plane)}) {
            const char* name = scene == int(Scene::Sphere) ? "sphere" : "plane";
            QTest::addRow("%s, gamma1", name) << scene << 0.4f << 0.0f << 2;
            QTest::addRow("%s, gamma2", name) << scene << 0.0f << 0.4f << 2;
            QTest::addRow("%s, both", name) << scene << 0.4f << 0.4f << 4;
            // Below sqrt(1 / (1 - epsilon)^2 - 1) = 0.246 the halves still touch.
            QTest::addRow("%s, small gamma1", name) << scene << 0.15f << 0.0f << 1;
        }
    }
    void splitMakesPieces()
    {
        QFETCH(int, scene);
        QFETCH(float, gamma1);
        QFETCH(float, gamma2);
        QFETCH(int, pieces);
        const Mask m = sample(Scene(scene), {HighlightOperation::split(gamma1, gamma2)}, 0.03f);
        QCOMPARE(m.components(), pieces);
        // The centre of the original highlight leaves the area once the pieces separate (paper,
        // "Split": spl(H) moves away from N where H ~ N).
        QCOMPARE(m.in(m.n / 2, m.n / 2), pieces == 1);
        // Pieces split across du lie on both sides of x = 0, symmetrically.
        if (gamma1 > 0.3f) {
            int left = 0, right = 0;
            for (int j = 0; j < m.n; ++j)
                for (int i = 0; i < m.n; ++i)
                    if (m.in(i, j))
                        (m.x(i) < 0 ? left : right) += 1;
            QVERIFY(left > 20 && right > 20);
            QVERIFY2(std::abs(left - right) < 0.05 * (left + right),
                QByteArray::number(left) + " / " + QByteArray::number(right));
        }
    }

    void squaringMakesSquare_data() { addScenes(); }
    void squaringMakesSquare()
    {
        QFETCH(int, scene);
        const double disc = sample(Scene(scene), {}).boxFill();
        QVERIFY2(std::abs(disc - M_PI / 4) < 0.03, QByteArray::number(disc));
        double previous = disc;
        // Up to sigma ~ 0.2 (n = 2) the sides straighten; beyond, the corners overshoot along the
        // diagonals towards a four-pointed star.
        for (const float sigma : {0.05f, 0.1f, 0.15f, 0.2f}) {
            const double fill = sample(Scene(scene), {HighlightOperation::squaring(sigma, 2.0f)}).boxFill();
            qInfo("sigma %.2f, n 2: area / box %.3f", double(sigma), fill);
            QVERIFY2(fill > previous, QByteArray::number(fill));
            previous = fill;
        }
        QVERIFY2(previous > 0.9, QByteArray::number(previous));
        // Squared along du and dv: turned by 45 degrees it is a diamond in the x, y box.
        const double diamond
            = sample(Scene(scene), {HighlightOperation::rotation(45.0f), HighlightOperation::squaring(0.2f, 2.0f)})
                  .boxFill();
        qInfo("turned by 45 degrees: %.3f", diamond);
        QVERIFY2(diamond < disc, QByteArray::number(diamond));
        // The square contains the original disc (tangential parts only shrink).
        QVERIFY(sample(Scene(scene), {}).inside(sample(Scene(scene), {HighlightOperation::squaring(0.2f, 2.0f)})));
        // Larger n: corners pushed out along the diagonals only, sides stay: smaller fill.
        const double sharp = sample(Scene(scene), {HighlightOperation::squaring(0.2f, 8.0f)}).boxFill();
        qInfo("sigma 0.2, n 8: %.3f", sharp);
        QVERIFY(sharp < previous);
    }

    void booleanPostOperations_data() { addScenes(); }
    void booleanPostOperations()
    {
        QFETCH(int, scene);
        const HighlightLayer a = layerOf({}, 0.05f);
        const HighlightShape b{0.03f, {HighlightOperation::translation(0.15f, 0.05f)}};
        HighlightLayer bLayer;
        bLayer.shape = b;
        const Mask ma = sample(Scene(scene), {}, 0.05f);
        const Mask mb = sampleLayers(Scene(scene), {bLayer});

        HighlightLayer u = a;
        u.combinations.push_back({HighlightBoolean::Union, b});
        const Mask mu = sampleLayers(Scene(scene), {u});
        QVERIFY(mu.area() >= ma.area() && mu.area() >= mb.area());
        QVERIFY(ma.inside(mu) && mb.inside(mu));

        HighlightLayer d = a;
        d.combinations.push_back({HighlightBoolean::Subtraction, b});
        const Mask md = sampleLayers(Scene(scene), {d});
        QVERIFY(md.area() <= ma.area());
        QVERIFY(md.area() > 0 && md.area() < ma.area()); // a crescent
        QVERIFY(md.inside(ma));
        // |A \ B| = |A| - |A n B| and |A u B| = |A| + |B| - |A n B|.
        int both = 0;
        for (size_t k = 0; k < ma.values.size(); ++k)
            both += ma.values[k] >= 0.5f && mb.values[k] >= 0.5f ? 1 : 0;
        QVERIFY(both > 0);
        QCOMPARE(md.area(), ma.area() - both);
        QCOMPARE(mu.area(), ma.area() + mb.area() - both);
    }

    void offSpecularCut()
    {
        // A translated highlight reaches where the light does not; the cut removes that part.
        HighlightLayer l = layerOf({HighlightOperation::translation(0.8f, 0.0f)}, 0.05f);
        const Mask full = sampleLayers(Scene::Sphere, {l});
        l.offSpecularCut = 0.8f;
        const Mask cut = sampleLayers(Scene::Sphere, {l});
        QVERIFY(cut.area() > 0 && cut.area() < full.area());
        QVERIFY(cut.inside(full));
        for (int j = 0; j < cut.n; ++j)
            for (int i = 0; i < cut.n; ++i)
                if (cut.in(i, j)) {
                    HighlightSurfacePoint p;
                    QVERIFY(surfacePoint(Scene::Sphere, cut.x(i), cut.x(j), p));
                    QVERIFY(p.normal.z() > 0.8f);
                }
    }

    void antiAliasedCoverage_data() { addScenes(); }
    void antiAliasedCoverage()
    {
        QFETCH(int, scene);
        const std::vector<HighlightLayer> layers{layerOf({HighlightOperation::directionalScaling(0.5f)})};
        const Mask hard = sampleLayers(Scene(scene), layers, 101, false);
        const Mask soft = sampleLayers(Scene(scene), layers, 101, true);
        double sum = 0.0;
        int partial = 0;
        for (size_t k = 0; k < soft.values.size(); ++k) {
            const float v = soft.values[k];
            QVERIFY(v >= 0.0f && v <= 1.0f);
            sum += v;
            if (v > 0.0f && v < 1.0f) {
                ++partial;
                // Fractional only on the edge: the hard mask changes within one cell.
                const int i = int(k) % soft.n, j = int(k) / soft.n;
                bool edge = false;
                for (int dj = -1; dj <= 1; ++dj)
                    for (int di = -1; di <= 1; ++di)
                        edge = edge || hard.in(i + di, j + dj) != hard.in(i, j);
                QVERIFY(edge);
            }
        }
        QVERIFY(partial > 10);
        QVERIFY2(std::abs(sum - hard.area()) < 0.03 * hard.area(), QByteArray::number(sum));
    }

    void layersPaintInOrder()
    {
        HighlightLayer red = layerOf({HighlightOperation::translation(-0.1f, 0.0f)});
        red.color = Color(1.0f, 0.0f, 0.0f);
        HighlightLayer blue = layerOf({HighlightOperation::translation(0.1f, 0.0f)});
        blue.color = Color(0.0f, 0.0f, 1.0f);
        const SceneSetup s = setup(Scene::Plane);
        HighlightSurfacePoint p;
        QVERIFY(surfacePoint(Scene::Plane, 0.0f, 0.0f, p)); // in both
        const HighlightSample both = evaluateHighlights(p, s.light, s.eye, {red, blue});
        QCOMPARE(both.coverage, 1.0f);
        QVERIFY((both.color - blue.color).norm() < 1e-6f);
        QVERIFY(surfacePoint(Scene::Plane, -0.7f, 0.0f, p)); // red only
        const HighlightSample left = evaluateHighlights(p, s.light, s.eye, {red, blue});
        QCOMPARE(left.coverage, 1.0f);
        QVERIFY((left.color - red.color).norm() < 1e-6f);
        QVERIFY(surfacePoint(Scene::Plane, 1.9f, 1.9f, p)); // neither
        QCOMPARE(evaluateHighlights(p, s.light, s.eye, {red, blue}).coverage, 0.0f);
        QCOMPARE(evaluateHighlights(p, s.light, s.eye, {}).coverage, 0.0f);
    }

    void keyframes()
    {
        HighlightLayer k0 = layerOf({HighlightOperation::translation(0.0f, 0.1f), HighlightOperation::rotation(0.0f),
                                        HighlightOperation::directionalScaling(0.2f)},
            0.02f);
        k0.color = Color(1.0f, 1.0f, 1.0f);
        k0.combinations.push_back({HighlightBoolean::Subtraction, {0.01f, {HighlightOperation::split(0.1f, 0.0f)}}});
        HighlightLayer k1 = layerOf({HighlightOperation::translation(0.4f, -0.1f), HighlightOperation::rotation(90.0f),
                                        HighlightOperation::directionalScaling(0.6f)},
            0.08f);
        k1.color = Color(1.0f, 0.5f, 0.0f);
        k1.combinations.push_back({HighlightBoolean::Subtraction, {0.03f, {HighlightOperation::split(0.3f, 0.2f)}}});
        k1.offSpecularCut = 0.0f;
        const std::vector<HighlightKey> keys{{10.0, k0}, {20.0, k1}};
        QVERIFY(sameHighlightStructure(k0, k1));

        const std::optional<HighlightLayer> mid = interpolateHighlightKeys(keys, 15.0);
        QVERIFY(mid);
        QCOMPARE(mid->shape.epsilon, 0.05f);
        QVERIFY((mid->color - Color(1.0f, 0.75f, 0.5f)).norm() < 1e-6f);
        for (size_t i = 0; i < 3; ++i) {
            QCOMPARE(mid->shape.operations[i].type, k0.shape.operations[i].type);
            QCOMPARE(mid->shape.operations[i].a, 0.5f * (k0.shape.operations[i].a + k1.shape.operations[i].a));
            QCOMPARE(mid->shape.operations[i].b, 0.5f * (k0.shape.operations[i].b + k1.shape.operations[i].b));
        }
        QCOMPARE(mid->combinations[0].shape.epsilon, 0.02f);
        QCOMPARE(mid->combinations[0].shape.operations[0].a, 0.2f);
        QCOMPARE(mid->combinations[0].shape.operations[0].b, 0.1f);
        QCOMPARE(mid->offSpecularCut, -0.5f);
        // A quarter of the way.
        QCOMPARE(interpolateHighlightKeys(keys, 12.5)->shape.operations[0].a, 0.1f);
        // Held outside, exact at the keys.
        QCOMPARE(*interpolateHighlightKeys(keys, -3.0), k0);
        QCOMPARE(*interpolateHighlightKeys(keys, 10.0), k0);
        QCOMPARE(*interpolateHighlightKeys(keys, 20.0), k1);
        QCOMPARE(*interpolateHighlightKeys(keys, 99.0), k1);
        QVERIFY(!interpolateHighlightKeys({}, 0.0));
        // Keys of different structure cannot be blended: the earlier one holds until the next.
        HighlightLayer other = k1;
        other.shape.operations.pop_back();
        QVERIFY(!sameHighlightStructure(k0, other));
        QCOMPARE(*interpolateHighlightKeys({{10.0, k0}, {20.0, other}}, 15.0), k0);
        QCOMPARE(*interpolateHighlightKeys({{10.0, k0}, {20.0, other}}, 20.0), other);
    }

    void tangentFrames()
    {
        // Orthonormal, handedness of dv kept.
        const Vector3f n = Vector3f(0.2f, -0.3f, 1.0f).normalized();
        for (const float side : {1.0f, -1.0f}) {
            const HighlightFrame f = makeTangentFrame(n, Vector3f(1.0f, 0.1f, 0.3f), side * Vector3f(0.2f, 1.0f, 0.0f));
            QVERIFY(std::abs(f.du.norm() - 1.0f) < 1e-6f && std::abs(f.dv.norm() - 1.0f) < 1e-6f);
            QVERIFY(std::abs(f.du.dot(f.dv)) < 1e-6f && std::abs(f.du.dot(n)) < 1e-6f && std::abs(f.dv.dot(n)) < 1e-6f);
            QVERIFY(n.cross(f.du).dot(f.dv) * side > 0.99f);
        }
        // Degenerate guide: still a frame.
        const HighlightFrame g = guideTangentFrame(Vector3f::UnitZ(), Vector3f::UnitZ());
        QVERIFY(std::abs(g.du.dot(Vector3f::UnitZ())) < 1e-6f && std::abs(g.du.norm() - 1.0f) < 1e-6f);

        // A grid in the plane z = 0 with u = -x (mirrored), v = y, and UVs per corner.
        TriMesh mesh;
        const int k = 5;
        mesh.vertices.resize(k * k, 3);
        mesh.uvs.resize(k * k, 2);
        for (int j = 0; j < k; ++j)
            for (int i = 0; i < k; ++i) {
                mesh.vertices.row(j * k + i) << float(i), float(j), 0.0f;
                mesh.uvs.row(j * k + i) << -0.1f * float(i), 0.1f * float(j);
            }
        mesh.faces = gridFaces(k);
        mesh.uvFaces = mesh.faces;
        Positions du, dv;
        QVERIFY(faceTangentFrames(mesh, du, dv));
        QCOMPARE(du.rows(), mesh.faces.rows());
        for (Eigen::Index r = 0; r < du.rows(); ++r) {
            QVERIFY((du.row(r) - Eigen::RowVector3f(-1.0f, 0.0f, 0.0f)).norm() < 1e-5f);
            QVERIFY((dv.row(r) - Eigen::RowVector3f(0.0f, 1.0f, 0.0f)).norm() < 1e-5f);
        }
        const Positions normals = vertexNormals(mesh.vertices, mesh.faces);
        QVERIFY(vertexTangentFramesFromUvs(mesh, normals, du, dv));
        QCOMPARE(du.rows(), mesh.vertices.rows());
        for (Eigen::Index r = 0; r < du.rows(); ++r)
            QVERIFY((du.row(r) - Eigen::RowVector3f(-1.0f, 0.0f, 0.0f)).norm() < 1e-5f);
        TriMesh noUv = mesh;
        noUv.uvs.resize(0, 2);
        QVERIFY(!faceTangentFrames(noUv, du, dv));

        // Guide frames over a patch (the first row of quads): the guide projected, zero elsewhere.
        const std::vector<std::int32_t> patch{0, 1, 2, 3, 4, 5, 6, 7};
        const Vector3f guide(1.0f, 1.0f, 0.5f);
        QVERIFY(guideVertexFrames(mesh.vertices, mesh.faces, normals, patch, guide, 3, du, dv));
        const Eigen::RowVector3f expected = Eigen::RowVector3f(1.0f, 1.0f, 0.0f).normalized();
        for (int r = 0; r < k * k; ++r) {
            if (r < 2 * k) {
                QVERIFY((du.row(r) - expected).norm() < 1e-5f);
                QVERIFY((dv.row(r) - Eigen::RowVector3f(-1.0f, 1.0f, 0.0f).normalized()).norm() < 1e-5f);
            } else {
                QCOMPARE(du.row(r).norm(), 0.0f);
            }
        }
        QVERIFY(!guideVertexFrames(mesh.vertices, mesh.faces, normals, patch, Vector3f::Zero(), 3, du, dv));
    }

    void smoothPatchNormalsByHand()
    {
        // A tent of two faces on the ridge 0-1 (the patch) and a third face outside it; positions
        // only give the vertex count, the normals are chosen (n2 not unit on purpose).
        Positions vertices = Positions::Zero(5, 3);
        Faces faces(3, 3);
        faces << 0, 1, 2, 1, 0, 3, 1, 3, 4;
        const Vector3f n0(0.6f, 0.0f, 0.8f), n1 = Vector3f::UnitZ(), n3 = Vector3f(1.0f, 0.0f, 1.0f).normalized();
        const Vector3f n2 = Vector3f(-1.0f, 0.0f, 1.0f).normalized(), n4 = Vector3f::UnitY();
        Positions normals(5, 3);
        normals << n0.transpose(), n1.transpose(), 2.0f * n2.transpose(), n3.transpose(), n4.transpose();
        const std::vector<std::int32_t> patch{0, 1};
        auto near = [](const Positions& p, int row, const Vector3f& expected) {
            return (p.row(row).transpose() - expected).norm() < 1e-6f;
        };

        // No rounds: the unit normals in the patch, zero outside.
        Positions smoothed;
        QVERIFY(smoothPatchNormals(vertices, faces, normals, patch, 0, smoothed));
        QCOMPARE(smoothed.rows(), Eigen::Index(5));
        QVERIFY(near(smoothed, 0, n0) && near(smoothed, 1, n1) && near(smoothed, 2, n2) && near(smoothed, 3, n3));
        QCOMPARE(smoothed.row(4).norm(), 0.0f);

        // One round: each vertex with its ring along the patch's edges, uniform weights, made
        // unit. The ridge 0-1 lies in both faces, so 0 and 1 see each other twice; 2 and 3 see
        // the ridge's ends once; the edge 1-3 of the outside face brings nothing from vertex 4.
        //   0: n0 + n1 + n2 + n1 + n3 = (0.6, 0, 2.8 + sqrt 2)
        //   1: n1 + n0 + n2 + n0 + n3 = (1.2, 0, 2.6 + sqrt 2)
        //   2: n2 + n1 + n0 = (0.6 - 1 / sqrt 2, 0, 1.8 + 1 / sqrt 2)
        //   3: n3 + n0 + n1 = (0.6 + 1 / sqrt 2, 0, 1.8 + 1 / sqrt 2)
        const float r = std::sqrt(0.5f);
        QVERIFY(smoothPatchNormals(vertices, faces, normals, patch, 1, smoothed));
        QVERIFY(near(smoothed, 0, Vector3f(0.6f, 0.0f, 2.8f + 2.0f * r).normalized()));
        QVERIFY(near(smoothed, 1, Vector3f(1.2f, 0.0f, 2.6f + 2.0f * r).normalized()));
        QVERIFY(near(smoothed, 2, Vector3f(0.6f - r, 0.0f, 1.8f + r).normalized()));
        QVERIFY(near(smoothed, 3, Vector3f(0.6f + r, 0.0f, 1.8f + r).normalized()));
        QCOMPARE(smoothed.row(4).norm(), 0.0f);
        // Unit rows, and more rounds pull the patch's normals together.
        for (int row = 0; row < 4; ++row)
            QVERIFY(std::abs(smoothed.row(row).norm() - 1.0f) < 1e-6f);
        Positions more;
        QVERIFY(smoothPatchNormals(vertices, faces, normals, patch, 20, more));
        QVERIFY(more.row(2).dot(more.row(3)) > smoothed.row(2).dot(smoothed.row(3)));
        QVERIFY(more.row(2).dot(more.row(3)) > 0.999f);

        // An empty patch is every face: vertex 4 takes part and joins vertex 1's ring.
        QVERIFY(smoothPatchNormals(vertices, faces, normals, {}, 1, smoothed));
        QVERIFY(smoothed.row(4).norm() > 0.99f);
        QVERIFY(smoothed.row(1).y() > 0.0f);

        // Sizes that do not match, faces or vertices out of range.
        QVERIFY(!smoothPatchNormals(vertices, faces, normals.topRows(4), patch, 1, smoothed));
        QVERIFY(!smoothPatchNormals(vertices, faces, normals, {0, 3}, 1, smoothed));
        QVERIFY(!smoothPatchNormals(vertices, faces, normals, {-1}, 1, smoothed));
        Faces outOfRange = faces;
        outOfRange(1, 2) = 5;
        QVERIFY(!smoothPatchNormals(vertices, outOfRange, normals, {}, 1, smoothed));
    }

    void smoothedNormalsGiveOneCleanArea()
    {
        // A nearly flat, noisy surface (the elephant's ear in small) under a point light beside
        // the eye: with the surface's vertex normals (N, H) > 1 - epsilon breaks into blotches;
        // the smoothed normals stand in for the paper's smooth patch and give one round area.
        const TriMesh mesh = bumpyPlane(41, 0.006f);
        const Positions normals = vertexNormals(mesh.vertices, mesh.faces);
        RasterCamera camera;
        camera.eye = Eigen::Vector3d(0, 0, 3);
        camera.fovYDegrees = 40.0;
        const int size = 200;
        camera.width = camera.height = size;
        RenderLook look;
        look.lines = false;
        look.pointLight = true;
        look.light = Eigen::Vector3f(0.0f, 0.0f, 3.0f);
        RenderHighlight h;
        h.layer.shape.epsilon = 0.02f;
        QVERIFY(guideVertexFrames(mesh.vertices, mesh.faces, normals, {}, Vector3f::UnitX(), 4, h.du, h.dv));
        RenderCache cache;
        look.highlights = {h};
        RenderPasses rough;
        renderFrame(mesh.vertices, mesh, camera, look, cache, rough);

        QVERIFY(smoothPatchNormals(mesh.vertices, mesh.faces, normals, {}, 30, h.normals));
        QVERIFY(guideVertexFrames(mesh.vertices, mesh.faces, h.normals, {}, Vector3f::UnitX(), 4, h.du, h.dv));
        look.highlights = {h};
        RenderPasses smooth;
        renderFrame(mesh.vertices, mesh, camera, look, cache, smooth);
        QVERIFY(rough.tone == smooth.tone); // the shading keeps the surface's normals

        const Mask a = highlightsPassMask(rough, size);
        const Mask b = highlightsPassMask(smooth, size);
        // Compactness 4 pi area / perimeter^2 (pi^2 / 16 for a digital disc measured this way).
        auto compactness = [](const Mask& m) {
            const double p = double(perimeter(m));
            return p > 0.0 ? 4.0 * M_PI * double(m.area()) / (p * p) : 0.0;
        };
        const QByteArray summary = "rough: " + QByteArray::number(a.components()) + " pieces, area "
            + QByteArray::number(a.area()) + ", compactness " + QByteArray::number(compactness(a))
            + "; smoothed: " + QByteArray::number(b.components()) + " pieces, area " + QByteArray::number(b.area())
            + ", compactness " + QByteArray::number(compactness(b));
        qInfo("%s", summary.constData());
        QVERIFY2(a.components() > 1, summary.constData());
        QVERIFY2(b.components() == 1, summary.constData());
        QVERIFY2(compactness(b) > 2.0 * compactness(a), summary.constData());
        QVERIFY2(compactness(b) > 0.5, summary.constData());
        // Round about the point under the light and eye (the image centre; mask units of half
        // the image).
        QVERIFY2(b.centroid().norm() < 0.05, describe(b.centroid()).constData());
        QVERIFY2(b.area() > 200, summary.constData());
    }
};

QTEST_APPLESS_MAIN(TestHighlights)
#include "test_highlights.moc"
