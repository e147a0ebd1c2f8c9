// Shape blending (paper 1, section 3.2.3): the dense and sparse paths against a naive loop, and
// exactness at weight 1.
#include "test_support.h"

#include "celform/algorithms/blend.h"

#include <random>

using namespace celform::algo;

namespace {

struct KeyData {
    std::vector<std::uint32_t> indices;
    std::vector<float> offsets;
    bool dense = false;
    OffsetsView view() const
    {
        OffsetsView v;
        v.indices = indices.empty() ? nullptr : indices.data();
        v.offsets = offsets.data();
        v.count = offsets.size() / 3;
        v.dense = dense;
        return v;
    }
};

Positions randomPositions(std::mt19937& rng, int n)
{
    std::uniform_real_distribution<float> u(-2.f, 2.f);
    Positions p(n, 3);
    for (int i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k)
            p(i, k) = u(rng);
    return p;
}

KeyData randomKey(std::mt19937& rng, int vertexCount, bool dense, double fraction = 0.1)
{
    std::uniform_real_distribution<float> u(-0.5f, 0.5f);
    std::uniform_real_distribution<double> pick(0.0, 1.0);
    KeyData k;
    k.dense = dense;
    for (int i = 0; i < vertexCount; ++i) {
        if (!dense && pick(rng) > fraction)
            continue;
        if (!dense)
            k.indices.push_back(static_cast<std::uint32_t>(i));
        for (int c = 0; c < 3; ++c)
            k.offsets.push_back(u(rng));
    }
    return k;
}

/// The definition, vertex by vertex, in double precision.
Positions naiveBlend(const Positions& base, const std::vector<KeyData>& keys, const std::vector<float>& weights)
{
    Eigen::MatrixXd acc = base.cast<double>();
    for (std::size_t k = 0; k < keys.size(); ++k) {
        const std::size_t count = keys[k].offsets.size() / 3;
        for (std::size_t j = 0; j < count; ++j) {
            const std::size_t v = keys[k].dense ? j : keys[k].indices[j];
            for (int c = 0; c < 3; ++c)
                acc(static_cast<Eigen::Index>(v), c) += double(weights[k]) * keys[k].offsets[3 * j + c];
        }
    }
    return acc.cast<float>();
}

std::vector<WeightedOffsets> weighted(const std::vector<KeyData>& keys, const std::vector<float>& weights)
{
    std::vector<WeightedOffsets> out;
    for (std::size_t k = 0; k < keys.size(); ++k)
        out.push_back({keys[k].view(), weights[k]});
    return out;
}

} // namespace

class TestBlend : public QObject {
    Q_OBJECT
private slots:
    void matchesNaiveLoop_data()
    {
        QTest::addColumn<int>("denseKeys");
        QTest::addColumn<int>("sparseKeys");
        QTest::addColumn<int>("vertices");
        QTest::newRow("no keys") << 0 << 0 << 101;
        QTest::newRow("one dense") << 1 << 0 << 101;
        QTest::newRow("two dense") << 2 << 0 << 1001;
        QTest::newRow("three dense") << 3 << 0 << 1003;
        QTest::newRow("four dense") << 4 << 0 << 999;
        QTest::newRow("seven dense") << 7 << 0 << 517;
        QTest::newRow("three sparse") << 0 << 3 << 1000;
        QTest::newRow("mixed") << 2 << 3 << 777;
        QTest::newRow("one vertex") << 3 << 1 << 1;
    }
    void matchesNaiveLoop()
    {
        QFETCH(int, denseKeys);
        QFETCH(int, sparseKeys);
        QFETCH(int, vertices);
        std::mt19937 rng(42);
        const Positions base = randomPositions(rng, vertices);
        std::vector<KeyData> keys;
        std::vector<float> weights;
        std::uniform_real_distribution<float> w(0.f, 1.f);
        for (int k = 0; k < denseKeys + sparseKeys; ++k) {
            keys.push_back(randomKey(rng, vertices, k < denseKeys, 0.3));
            weights.push_back(w(rng));
        }
        Positions out;
        blendShape(base, weighted(keys, weights), out);
        const Positions expected = naiveBlend(base, keys, weights);
        QCOMPARE(out.rows(), base.rows());
        QVERIFY((out - expected).cwiseAbs().maxCoeff() < 1e-5f || vertices == 0);
    }

    void weightOneIsExact()
    {
        std::mt19937 rng(3);
        const int n = 1000;
        const Positions base = randomPositions(rng, n);
        for (bool dense : {true, false}) {
            const KeyData key = randomKey(rng, n, dense, 0.2);
            Positions out;
            // Other keys at weight zero take no part.
            const KeyData other = randomKey(rng, n, true);
            blendShape(base, {{key.view(), 1.f}, {other.view(), 0.f}}, out);
            Positions expected = base;
            for (std::size_t j = 0; j < key.offsets.size() / 3; ++j) {
                const Eigen::Index v = dense ? Eigen::Index(j) : Eigen::Index(key.indices[j]);
                for (int c = 0; c < 3; ++c)
                    expected(v, c) = base(v, c) + key.offsets[3 * j + c];
            }
            QVERIFY(out == expected); // bit-exact: base + 1 * offset
        }
    }

    // Paper 1, section 4.2: offsets over time by cubic splines, as weights of the keyed frames.
    void splineWeightsByHand()
    {
        auto near = [](const std::vector<double>& got, const std::vector<double>& want) {
            if (got.size() != want.size())
                return false;
            for (std::size_t i = 0; i < got.size(); ++i)
                if (std::abs(got[i] - want[i]) > 1e-12)
                    return false;
            return true;
        };
        // Two knots: the natural spline is the straight line.
        QVERIFY(near(splineWeights({0, 10}, 2.5, false), {0.75, 0.25}));
        // Three knots one apart: M1 = 1.5 (y0 - 2 y1 + y2), M0 = M2 = 0, so at t = 0.5
        // S = 0.5 y0 + 0.5 y1 + (0.5^3 - 0.5) / 6 * M1 = 0.40625 y0 + 0.6875 y1 - 0.09375 y2.
        QVERIFY(near(splineWeights({0, 1, 2}, 0.5, false), {0.40625, 0.6875, -0.09375}));
        // Exactly at a knot: that knot alone; outside the range: the end held.
        QVERIFY(near(splineWeights({0, 4, 7, 12}, 7, false), {0, 0, 1, 0}));
        QVERIFY(near(splineWeights({0, 4, 7, 12}, -3, false), {1, 0, 0, 0}));
        QVERIFY(near(splineWeights({0, 4, 7, 12}, 40, false), {0, 0, 0, 1}));
        QVERIFY(near(splineWeights({5}, 1, false), {1}));
        QVERIFY(splineWeights({}, 1, false).empty());
        // Constants and straight lines come out unchanged (natural splines reproduce them).
        const std::vector<double> knots{0, 3, 4, 9, 10};
        for (double t : {0.5, 3.3, 6.0, 9.9}) {
            const auto w = splineWeights(knots, t, false);
            double sum = 0, line = 0;
            for (std::size_t i = 0; i < w.size(); ++i) {
                sum += w[i];
                line += w[i] * (2.0 * knots[i] - 1.0);
            }
            QVERIFY(std::abs(sum - 1.0) < 1e-12);
            QVERIFY(std::abs(line - (2.0 * t - 1.0)) < 1e-12);
        }
    }

    void periodicSplineWeights()
    {
        // A cycle of three keys at 0, 1, 2, closed by the key at 3 (the first again).
        const std::vector<double> knots{0, 1, 2, 3};
        const auto w = splineWeights(knots, 0.5, true);
        QCOMPARE(w.size(), std::size_t(4));
        QCOMPARE(w[3], 0.0);
        QVERIFY(std::abs(w[0] + w[1] + w[2] - 1.0) < 1e-12);
        QVERIFY(std::abs(w[0] - w[1]) < 1e-12); // halfway between 0 and 1, by symmetry
        // Wrapping: a frame and the same frame one cycle later or earlier agree.
        for (double t : {3.5, -2.5, 6.5}) {
            const auto wt = splineWeights(knots, t, true);
            for (std::size_t i = 0; i < 4; ++i)
                QVERIFY(std::abs(wt[i] - w[i]) < 1e-12);
        }
        // The closing key stands for the first.
        QCOMPARE(splineWeights(knots, 3, true), (std::vector<double>{1, 0, 0, 0}));
        // Too few keys for a cycle: the first holds.
        QCOMPARE(splineWeights({0, 8}, 3, true), (std::vector<double>{1, 0}));
    }

    void emptyBase()
    {
        Positions base(0, 3);
        Positions out = Positions::Ones(4, 3);
        blendShape(base, {}, out);
        QCOMPARE(out.rows(), Eigen::Index(0));
    }
};

QTEST_APPLESS_MAIN(TestBlend)
#include "test_blend.moc"
