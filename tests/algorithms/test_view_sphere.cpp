// Viewing-sphere lookup and blend weights (paper 1, sections 3.2 and 3.3) on key sets whose
// answers are known by hand, plus continuity and brute-force agreement on random sets.
#include "test_support.h"

#include "celform/algorithms/view_sphere.h"

#include <Eigen/Dense>

#include <cmath>
#include <map>
#include <random>

using namespace celform::algo;
using Eigen::Vector3d;

Q_DECLARE_METATYPE(celform::algo::UnspecifiedRegions)

namespace {

/// Keys at +X, -X, +Y, -Y, +Z, -Z (indices 0..5).
std::vector<Vector3d> octahedron()
{
    return {Vector3d::UnitX(), -Vector3d::UnitX(), Vector3d::UnitY(), -Vector3d::UnitY(), Vector3d::UnitZ(),
        -Vector3d::UnitZ()};
}

std::map<int, double> weightMap(const ViewBlend& b)
{
    std::map<int, double> m;
    for (const KeyWeight& kw : b.weights)
        m[kw.key] += kw.weight;
    return m;
}

double weightOf(const ViewBlend& b, int key)
{
    for (const KeyWeight& kw : b.weights)
        if (kw.key == key)
            return kw.weight;
    return 0.0;
}

double weightSum(const ViewBlend& b)
{
    double s = 0.0;
    for (const KeyWeight& kw : b.weights)
        s += kw.weight;
    return s;
}

ViewSphere buildOrFail(const std::vector<Vector3d>& keys, UnspecifiedRegions mode)
{
    std::string error;
    auto s = ViewSphere::build(keys, mode, &error);
    if (!s)
        qFatal("ViewSphere::build failed: %s", error.c_str());
    return std::move(*s);
}

Vector3d randomUnit(std::mt19937& rng)
{
    std::normal_distribution<double> g;
    Vector3d v;
    do {
        v = Vector3d(g(rng), g(rng), g(rng));
    } while (v.norm() < 1e-6);
    return v.normalized();
}

/// count random unit keys at least minAngle apart, with z >= minZ.
std::vector<Vector3d> randomKeys(std::mt19937& rng, int count, double minAngleDegrees, double minZ = -1.0)
{
    const double minCos = std::cos(minAngleDegrees * M_PI / 180.0);
    std::vector<Vector3d> keys;
    while (static_cast<int>(keys.size()) < count) {
        const Vector3d v = randomUnit(rng);
        if (v.z() < minZ)
            continue;
        bool ok = true;
        for (const Vector3d& k : keys)
            ok = ok && k.dot(v) < minCos;
        if (ok)
            keys.push_back(v);
    }
    return keys;
}

/// Brute force: the facet whose cone contains d best (largest smallest normalised barycentric
/// numerator), over the inverses of every facet's [p0 p1 p2].
std::vector<Eigen::Matrix3d> facetInverses(const ViewSphere& s)
{
    std::vector<Eigen::Matrix3d> inverses;
    for (const auto& f : s.facets()) {
        Eigen::Matrix3d m;
        for (int k = 0; k < 3; ++k)
            m.col(k) = s.points()[f[k]];
        inverses.push_back(m.inverse());
    }
    return inverses;
}

double containment(const Eigen::Matrix3d& inverse, const Vector3d& d)
{
    const Vector3d l = inverse * d;
    return l.minCoeff() / l.cwiseAbs().sum();
}

int bruteForceFacet(const std::vector<Eigen::Matrix3d>& inverses, const Vector3d& d, double& score)
{
    int best = -1;
    score = -std::numeric_limits<double>::infinity();
    for (int f = 0; f < static_cast<int>(inverses.size()); ++f) {
        const double sc = containment(inverses[f], d);
        if (sc > score) {
            score = sc;
            best = f;
        }
    }
    return best;
}

/// Largest change of any key's weight between two blends.
double largestChange(const ViewBlend& a, const ViewBlend& b)
{
    const std::map<int, double> wa = weightMap(a);
    const std::map<int, double> wb = weightMap(b);
    double worst = 0.0;
    for (const auto& [key, w] : wa)
        worst = std::max(worst, std::abs(w - (wb.count(key) ? wb.at(key) : 0.0)));
    for (const auto& [key, w] : wb)
        worst = std::max(worst, std::abs(w - (wa.count(key) ? wa.at(key) : 0.0)));
    return worst;
}

} // namespace

class TestViewSphere : public QObject {
    Q_OBJECT
private slots:
    void keyDirectionGivesThatKeyExactly_data()
    {
        QTest::addColumn<UnspecifiedRegions>("mode");
        QTest::newRow("dummy") << UnspecifiedRegions::Dummy;
        QTest::newRow("cosine") << UnspecifiedRegions::Cosine;
        QTest::newRow("cosine2") << UnspecifiedRegions::Cosine2;
    }
    void keyDirectionGivesThatKeyExactly()
    {
        QFETCH(UnspecifiedRegions, mode);
        std::mt19937 rng(7);
        // The octahedron, a random full set, a one-sided set, and un-normalised keys.
        std::vector<std::vector<Vector3d>> sets{octahedron(), randomKeys(rng, 20, 10.0), randomKeys(rng, 12, 10.0, 0.4),
            {Vector3d(0, 0, 2), Vector3d(3, 0, 0.5), Vector3d(0, -1, 1)}};
        for (const auto& keys : sets) {
            const ViewSphere s = buildOrFail(keys, mode);
            for (int k = 0; k < static_cast<int>(keys.size()); ++k) {
                for (double sharpness : {1.0, 4.0, 0.5}) {
                    const ViewBlend b = s.blend(keys[k], sharpness);
                    QCOMPARE(b.weights.size(), std::size_t(1));
                    QCOMPARE(b.weights[0].key, k);
                    QVERIFY(b.weights[0].weight == 1.0); // bit-exact
                }
            }
        }
    }

    void octahedronCentreOfFacet()
    {
        const ViewSphere s = buildOrFail(octahedron(), UnspecifiedRegions::Dummy);
        QCOMPARE(s.points().size(), std::size_t(6)); // every axis is a key: no dummies
        QCOMPARE(s.facets().size(), std::size_t(8));
        const ViewBlend b = s.blend(Vector3d(1, 1, 1), 1.0);
        QVERIFY(b.facet >= 0);
        QCOMPARE(b.weights.size(), std::size_t(3));
        QVERIFY(std::abs(weightOf(b, 0) - 1.0 / 3.0) < 1e-12);
        QVERIFY(std::abs(weightOf(b, 2) - 1.0 / 3.0) < 1e-12);
        QVERIFY(std::abs(weightOf(b, 4) - 1.0 / 3.0) < 1e-12);
        QCOMPARE(b.falloff, 1.0);
    }

    void octahedronBarycentricByHand()
    {
        const ViewSphere s = buildOrFail(octahedron(), UnspecifiedRegions::Cosine);
        // (2,1,0): the ray meets the plane x + y + z = 1 at (2/3, 1/3, 0), on the +X/+Y edge.
        ViewBlend b = s.blend(Vector3d(2, 1, 0).normalized(), 1.0);
        QVERIFY(std::abs(weightOf(b, 0) - 2.0 / 3.0) < 1e-12);
        QVERIFY(std::abs(weightOf(b, 2) - 1.0 / 3.0) < 1e-12);
        QVERIFY(std::abs(weightSum(b) - 1.0) < 1e-12);
        // (2,1,1): hit at (1/2, 1/4, 1/4).
        b = s.blend(Vector3d(2, 1, 1), 1.0);
        QVERIFY(std::abs(weightOf(b, 0) - 0.5) < 1e-12);
        QVERIFY(std::abs(weightOf(b, 2) - 0.25) < 1e-12);
        QVERIFY(std::abs(weightOf(b, 4) - 0.25) < 1e-12);
        // (-1,2,-1): facet (-X, +Y, -Z), hit at (-1/4, 1/2, -1/4).
        b = s.blend(Vector3d(-1, 2, -1), 1.0);
        QVERIFY(std::abs(weightOf(b, 1) - 0.25) < 1e-12);
        QVERIFY(std::abs(weightOf(b, 2) - 0.5) < 1e-12);
        QVERIFY(std::abs(weightOf(b, 5) - 0.25) < 1e-12);
    }

    void sharpnessFour()
    {
        // Paper 1, section 3.2.2: w' = w^4 / sum w^4 with w = (1/2, 1/4, 1/4):
        // (1/16, 1/256, 1/256) / (18/256) = (8/9, 1/18, 1/18).
        const ViewSphere s = buildOrFail(octahedron(), UnspecifiedRegions::Dummy);
        const ViewBlend b = s.blend(Vector3d(2, 1, 1), 4.0);
        QVERIFY(std::abs(weightOf(b, 0) - 8.0 / 9.0) < 1e-12);
        QVERIFY(std::abs(weightOf(b, 2) - 1.0 / 18.0) < 1e-12);
        QVERIFY(std::abs(weightOf(b, 4) - 1.0 / 18.0) < 1e-12);
        QVERIFY(std::abs(b.barycentric.sum() - 1.0) < 1e-12); // unsharpened
        // Sharpness 1 leaves the barycentric weights.
        const ViewBlend b1 = s.blend(Vector3d(2, 1, 1), 1.0);
        QVERIFY(std::abs(weightOf(b1, 0) - 0.5) < 1e-12);
    }

    void singleKeyCosine_data()
    {
        QTest::addColumn<double>("x");
        QTest::addColumn<double>("y");
        QTest::addColumn<double>("z");
        QTest::newRow("front") << 0.0 << 0.0 << 1.0;
        QTest::newRow("45 degrees") << 1.0 << 0.0 << 1.0;
        QTest::newRow("oblique") << 0.0 << 1.0 << 2.0;
        QTest::newRow("mixed") << 0.3 << -0.7 << 0.5;
        QTest::newRow("side +X") << 1.0 << 0.0 << 0.0;
        QTest::newRow("side -Y") << 0.0 << -1.0 << 0.0;
        QTest::newRow("behind") << 0.0 << 0.0 << -1.0;
        QTest::newRow("behind oblique") << 1.0 << 1.0 << -1.0;
    }
    void singleKeyCosine()
    {
        QFETCH(double, x);
        QFETCH(double, y);
        QFETCH(double, z);
        const Vector3d d = Vector3d(x, y, z).normalized();
        const double c = std::max(0.0, d.z()); // paper 1, section 3.3: max(0, V_key . V_eye)
        const ViewSphere cosine = buildOrFail({Vector3d::UnitZ()}, UnspecifiedRegions::Cosine);
        const ViewSphere cosine2 = buildOrFail({Vector3d::UnitZ()}, UnspecifiedRegions::Cosine2);
        QCOMPARE(cosine.points().size(), std::size_t(1));
        const ViewBlend b = cosine.blend(d, 1.0);
        const ViewBlend b2 = cosine2.blend(d, 3.0);
        QVERIFY(std::abs(weightOf(b, 0) - c) < 1e-12);
        QVERIFY(std::abs(weightOf(b2, 0) - c * c) < 1e-12);
        QCOMPARE(b.facet, -1);
        QVERIFY(std::abs(b.falloff - c) < 1e-12);
        if (c == 0.0) {
            QVERIFY(b.weights.empty());
            QVERIFY(b2.weights.empty());
        }
    }

    void dummyModeOneFrontKey()
    {
        const ViewSphere s = buildOrFail({Vector3d::UnitZ()}, UnspecifiedRegions::Dummy);
        QCOMPARE(s.keyCount(), 1);
        QCOMPARE(s.points().size(), std::size_t(6)); // +Z is the key, five dummies
        QCOMPARE(s.facets().size(), std::size_t(8));
        for (const Vector3d& d : {Vector3d(1, 0, 0), Vector3d(-1, 0, 0), Vector3d(0, 1, 0), Vector3d(0, -1, 0),
                 Vector3d(0, 0, -1), Vector3d(1, 1, -1)}) {
            const ViewBlend b = s.blend(d, 1.0);
            QVERIFY(b.facet >= 0);
            QVERIFY2(b.weights.empty(), "the base model alone");
        }
        const ViewBlend front = s.blend(Vector3d(0, 0, 1), 1.0);
        QCOMPARE(front.weights.size(), std::size_t(1));
        QVERIFY(front.weights[0].weight == 1.0);
        // (1,0,1): hit (1/2, 0, 1/2) on the +X/+Z edge; (1,1,1): a third each.
        QVERIFY(std::abs(weightOf(s.blend(Vector3d(1, 0, 1), 1.0), 0) - 0.5) < 1e-12);
        QVERIFY(std::abs(weightOf(s.blend(Vector3d(1, 1, 1), 1.0), 0) - 1.0 / 3.0) < 1e-12);
        // (1,1,2): plane x + y + z = 1 at (1/4, 1/4, 1/2).
        QVERIFY(std::abs(weightOf(s.blend(Vector3d(1, 1, 2), 1.0), 0) - 0.5) < 1e-12);
    }

    void dummiesLeftOutNearKeys()
    {
        // A key at 30 degrees from +Z in the XZ plane: +Z is within 45 degrees, +X is 60 away.
        const Vector3d key(std::sin(M_PI / 6), 0, std::cos(M_PI / 6));
        const ViewSphere s = buildOrFail({key}, UnspecifiedRegions::Dummy);
        QCOMPARE(s.points().size(), std::size_t(6));
        for (std::size_t i = 1; i < s.points().size(); ++i)
            QVERIFY(s.points()[i].dot(Vector3d::UnitZ()) < 0.99);
        // Exactly 45 degrees counts as "within": key (1,1,0)/sqrt2 removes +X and +Y.
        const ViewSphere s45 = buildOrFail({Vector3d(1, 1, 0)}, UnspecifiedRegions::Dummy);
        QCOMPARE(s45.points().size(), std::size_t(5));
    }

    void twoKeys()
    {
        const ViewSphere s = buildOrFail({Vector3d::UnitZ(), Vector3d::UnitX()}, UnspecifiedRegions::Cosine);
        QVERIFY(s.facets().empty());
        // On the arc: chord-linear weights, no falloff.
        ViewBlend b = s.blend(Vector3d(1, 0, 1), 1.0);
        QVERIFY(std::abs(weightOf(b, 0) - 0.5) < 1e-12);
        QVERIFY(std::abs(weightOf(b, 1) - 0.5) < 1e-12);
        QVERIFY(std::abs(b.falloff - 1.0) < 1e-12);
        // (1,1,1): nearest arc point (1,0,1)/sqrt2, c = sqrt(2/3).
        b = s.blend(Vector3d(1, 1, 1), 1.0);
        const double c = std::sqrt(2.0 / 3.0);
        QVERIFY(std::abs(weightOf(b, 0) - 0.5 * c) < 1e-12);
        QVERIFY(std::abs(weightOf(b, 1) - 0.5 * c) < 1e-12);
        // Beyond the +Z end: nearest point +Z, c = cos 45.
        b = s.blend(Vector3d(-1, 0, 1), 1.0);
        QVERIFY(std::abs(weightOf(b, 0) - std::sqrt(0.5)) < 1e-12);
        QCOMPARE(weightOf(b, 1), 0.0);
        // Perpendicular to the arc's plane and opposite: the base.
        QVERIFY(s.blend(Vector3d(0, 1, 0), 1.0).weights.empty());
        QVERIFY(s.blend(Vector3d(-1, 0, -1), 1.0).weights.empty());
        // Cosine2 squares the falloff.
        const ViewSphere s2 = buildOrFail({Vector3d::UnitZ(), Vector3d::UnitX()}, UnspecifiedRegions::Cosine2);
        b = s2.blend(Vector3d(1, 1, 1), 1.0);
        QVERIFY(std::abs(weightOf(b, 0) - 0.5 * c * c) < 1e-12);
        // Antipodal keys: two isolated points, each with its own cosine.
        const ViewSphere anti = buildOrFail({Vector3d::UnitZ(), -Vector3d::UnitZ()}, UnspecifiedRegions::Cosine);
        b = anti.blend(Vector3d(1, 0, 1), 1.0);
        QVERIFY(std::abs(weightOf(b, 0) - std::sqrt(0.5)) < 1e-12);
        QVERIFY(anti.blend(Vector3d(1, 0, 0), 1.0).weights.empty());
    }

    void keysOnOneGreatCircle()
    {
        const std::vector<Vector3d> keys{Vector3d::UnitX(), Vector3d::UnitY(), -Vector3d::UnitX(), -Vector3d::UnitY()};
        const ViewSphere s = buildOrFail(keys, UnspecifiedRegions::Cosine);
        QVERIFY(s.facets().empty());
        QVERIFY(s.blend(Vector3d::UnitZ(), 1.0).weights.empty()); // the pole is 90 degrees away
        ViewBlend b = s.blend(Vector3d(1, 1, 0), 1.0);
        QVERIFY(std::abs(weightOf(b, 0) - 0.5) < 1e-12);
        QVERIFY(std::abs(weightOf(b, 1) - 0.5) < 1e-12);
        b = s.blend(Vector3d(1, 0, 1), 1.0);
        QVERIFY(std::abs(weightOf(b, 0) - std::sqrt(0.5)) < 1e-12);
        // Keys on half the circle: no arc across the 180-degree gap from -X back to +X.
        const ViewSphere half
            = buildOrFail({Vector3d::UnitX(), Vector3d::UnitY(), -Vector3d::UnitX()}, UnspecifiedRegions::Cosine);
        QVERIFY(half.facets().empty());
        QVERIFY(half.blend(-Vector3d::UnitY(), 1.0).weights.empty());
        b = half.blend(Vector3d(1, -1, 0), 1.0); // nearest covered point +X, 45 degrees away
        QVERIFY(std::abs(weightOf(b, 0) - std::sqrt(0.5)) < 1e-12);
        QCOMPARE(weightOf(b, 2), 0.0);
        // Dummy mode on the same keys adds the poles and covers everything.
        const ViewSphere dummy = buildOrFail(keys, UnspecifiedRegions::Dummy);
        QCOMPARE(dummy.points().size(), std::size_t(6));
        QVERIFY(dummy.blend(Vector3d::UnitZ(), 1.0).facet >= 0);
    }

    void fewerThanFourKeys()
    {
        for (UnspecifiedRegions mode :
            {UnspecifiedRegions::Dummy, UnspecifiedRegions::Cosine, UnspecifiedRegions::Cosine2}) {
            const ViewSphere none = buildOrFail({}, mode);
            QCOMPARE(none.keyCount(), 0);
            QVERIFY(none.blend(Vector3d(0.2, 0.3, 0.9), 1.0).weights.empty());
            const ViewSphere three = buildOrFail({Vector3d::UnitX(), Vector3d::UnitY(), Vector3d::UnitZ()}, mode);
            const ViewBlend b = three.blend(Vector3d(1, 1, 1), 1.0);
            QVERIFY(b.facet >= 0);
            QVERIFY(std::abs(weightOf(b, 0) - 1.0 / 3.0) < 1e-12);
            QVERIFY(three.blend(Vector3d(-1, -1, -1), 1.0).weights.empty());
        }
        // Three keys in Cosine mode: one facet; below its X/Y edge the nearest point is (1,1,0)/sqrt2.
        const ViewSphere three
            = buildOrFail({Vector3d::UnitX(), Vector3d::UnitY(), Vector3d::UnitZ()}, UnspecifiedRegions::Cosine);
        QCOMPARE(three.facets().size(), std::size_t(1));
        const ViewBlend b = three.blend(Vector3d(1, 1, -1), 1.0);
        QCOMPARE(b.facet, -1);
        const double c = std::sqrt(2.0 / 3.0);
        QVERIFY(std::abs(b.falloff - c) < 1e-12);
        QVERIFY(std::abs(weightOf(b, 0) - 0.5 * c) < 1e-12);
        QVERIFY(std::abs(weightOf(b, 1) - 0.5 * c) < 1e-12);
        QCOMPARE(weightOf(b, 2), 0.0);
        // Four keys on a small circle (coplanar, off the origin): a fan of two facets.
        const double z = 0.5;
        const double r = std::sqrt(1 - z * z);
        const ViewSphere ring = buildOrFail(
            {Vector3d(r, 0, z), Vector3d(0, r, z), Vector3d(-r, 0, z), Vector3d(0, -r, z)}, UnspecifiedRegions::Cosine);
        QCOMPARE(ring.facets().size(), std::size_t(2));
        const ViewBlend top = ring.blend(Vector3d::UnitZ(), 1.0);
        QVERIFY(top.facet >= 0);
        QVERIFY(std::abs(weightSum(top) - 1.0) < 1e-12);
    }

    void refusesDuplicatesAndNonFinite()
    {
        std::string error;
        const double a = 0.2 * M_PI / 180.0;
        auto s = ViewSphere::build({Vector3d::UnitX(), Vector3d::UnitZ(), Vector3d(std::sin(a), 0, std::cos(a))},
            UnspecifiedRegions::Dummy, &error);
        QVERIFY(!s);
        QVERIFY2(error.find("1 and 2") != std::string::npos, error.c_str());
        error.clear();
        s = ViewSphere::build({Vector3d::UnitX(), Vector3d(0, std::nan(""), 1)}, UnspecifiedRegions::Cosine, &error);
        QVERIFY(!s);
        QVERIFY2(error.find('1') != std::string::npos, error.c_str());
        s = ViewSphere::build({Vector3d::Zero()}, UnspecifiedRegions::Cosine, &error);
        QVERIFY(!s);
        // 1 degree apart is allowed.
        const double b = 1.0 * M_PI / 180.0;
        QVERIFY(
            ViewSphere::build({Vector3d::UnitZ(), Vector3d(std::sin(b), 0, std::cos(b))}, UnspecifiedRegions::Dummy));
    }

    void degenerateViewGivesBase()
    {
        const ViewSphere s = buildOrFail(octahedron(), UnspecifiedRegions::Dummy);
        QVERIFY(s.blend(Vector3d::Zero(), 1.0).weights.empty());
        QVERIFY(s.blend(Vector3d(std::nan(""), 0, 1), 1.0).weights.empty());
    }

    void copyAndMove()
    {
        ViewSphere a = buildOrFail(octahedron(), UnspecifiedRegions::Cosine);
        ViewSphere b = a;
        ViewSphere c = std::move(a);
        a = b;
        for (const ViewSphere* s : {&a, &b, &c})
            QVERIFY(std::abs(weightOf(s->blend(Vector3d(2, 1, 1), 1.0), 0) - 0.5) < 1e-12);
    }

    void continuityAlongGreatCircles_data()
    {
        QTest::addColumn<UnspecifiedRegions>("mode");
        QTest::addColumn<double>("minZ");
        QTest::addColumn<double>("sharpness");
        QTest::newRow("dummy, all around") << UnspecifiedRegions::Dummy << -1.0 << 1.0;
        QTest::newRow("cosine, all around") << UnspecifiedRegions::Cosine << -1.0 << 1.0;
        QTest::newRow("cosine2, all around") << UnspecifiedRegions::Cosine2 << -1.0 << 1.0;
        QTest::newRow("dummy, one side") << UnspecifiedRegions::Dummy << 0.3 << 1.0;
        QTest::newRow("cosine, one side") << UnspecifiedRegions::Cosine << 0.3 << 1.0;
        QTest::newRow("cosine2, one side") << UnspecifiedRegions::Cosine2 << 0.3 << 1.0;
        QTest::newRow("cosine, one side, sharp") << UnspecifiedRegions::Cosine << 0.3 << 2.0;
    }
    void continuityAlongGreatCircles()
    {
        QFETCH(UnspecifiedRegions, mode);
        QFETCH(double, minZ);
        QFETCH(double, sharpness);
        std::mt19937 rng(20240611);
        const std::vector<Vector3d> keys = randomKeys(rng, 20, 15.0, minZ);
        const ViewSphere s = buildOrFail(keys, mode);
        double worst = 0.0;
        double worstRefined = 0.0;
        for (int circle = 0; circle < 5; ++circle) {
            // A great circle through a random key, so that the path crosses facets and edges.
            const Vector3d a = keys[rng() % keys.size()];
            const Vector3d b = a.cross(randomUnit(rng)).normalized();
            auto at = [&](double t) { return s.blend(std::cos(t) * a + std::sin(t) * b, sharpness); };
            const int samples = 2000;
            const double step = 2.0 * M_PI / samples;
            ViewBlend previous = at(0.0);
            for (int i = 1; i <= samples; ++i) {
                const ViewBlend current = at(step * i);
                double sum = 0.0;
                for (const KeyWeight& kw : current.weights) {
                    QVERIFY(kw.weight >= 0.0);
                    sum += kw.weight;
                }
                QVERIFY(sum <= 1.0 + 1e-9);
                const double change = largestChange(previous, current);
                worst = std::max(worst, change);
                if (change >= 0.02) {
                    // Sliver facets (on the rim of a one-sided set) have steep but finite
                    // gradients: refined 100 times, a continuous blend changes 100 times less,
                    // a jump would not.
                    ViewBlend sub = previous;
                    for (int k = 1; k <= 100; ++k) {
                        const ViewBlend next = at(step * (i - 1) + step * k / 100.0);
                        worstRefined = std::max(worstRefined, largestChange(sub, next));
                        sub = next;
                    }
                }
                previous = current;
            }
        }
        qInfo("largest weight change between neighbouring samples: %.5f (refined where >= 0.02: %.5f)", worst,
            worstRefined);
        QVERIFY(worst < 0.2);
        QVERIFY(worstRefined < 0.002);
    }

    void lookupAgreesWithBruteForce_data()
    {
        QTest::addColumn<double>("minZ");
        QTest::newRow("all around") << -1.0;
        QTest::newRow("one side") << 0.0;
    }
    void lookupAgreesWithBruteForce()
    {
        QFETCH(double, minZ);
        std::mt19937 rng(12345);
        const std::vector<Vector3d> keys = randomKeys(rng, 1000, 1.0, minZ);
        const ViewSphere s = buildOrFail(keys, UnspecifiedRegions::Cosine);
        QVERIFY(s.facets().size() > 1000);
        const std::vector<Eigen::Matrix3d> inverses = facetInverses(s);
        int hits = 0;
        for (int i = 0; i < 10000; ++i) {
            const Vector3d d = randomUnit(rng);
            const ViewBlend b = s.blend(d, 1.0);
            double bruteScore = 0.0;
            const int brute = bruteForceFacet(inverses, d, bruteScore);
            if (bruteScore > 1e-9) {
                QCOMPARE(b.facet, brute); // strictly inside one facet: the same one
            } else if (bruteScore < -1e-9) {
                QCOMPARE(b.facet, -1); // clearly outside the covered region
            }
            if (b.facet >= 0) {
                ++hits;
                QVERIFY(containment(inverses[b.facet], d) > -1e-9);
            }
        }
        if (minZ < -0.5)
            QCOMPARE(hits, 10000);
        else
            QVERIFY(hits > 3000 && hits < 7000);
    }
};

QTEST_APPLESS_MAIN(TestViewSphere)
#include "test_view_sphere.moc"
