// Cartoon shading (toon ramp and 32-entry table, Gooch-like lighting, hatching) on hand-computed
// cases, and the GLSL mirror of it: present, defining the four functions, and compiling.
#include "test_support.h"

#include "celform/algorithms/shading.h"

#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <cmath>
#include <cstring>
#include <limits>

using namespace celform::algo;
using Eigen::Vector3f;

Q_DECLARE_METATYPE(celform::algo::ToonRamp)
Q_DECLARE_METATYPE(celform::algo::GoochParams)
Q_DECLARE_METATYPE(Eigen::Vector3f)

namespace {

ToonRamp threeToneRamp()
{
    ToonRamp r;
    r.thresholds = {-0.2f, 0.4f};
    r.intensities = {0.2f, 0.6f, 1.0f};
    return r;
}

bool colorNear(const Color& a, const Color& b, float tolerance = 1e-5f)
{
    return (a - b).cwiseAbs().maxCoeff() <= tolerance;
}

QByteArray describe(const Color& c)
{
    return QByteArray::number(c.x()) + ", " + QByteArray::number(c.y()) + ", " + QByteArray::number(c.z());
}

/// Mean coverage over an n x n grid of the square [0, side)^2 of the plane z = 0 (normal +Z),
/// offset so the samples do not line up with the strokes.
double meanCoverage(int tone, int toneCount, const HatchParams& p, float footprint, int n = 400, float side = 1.0f)
{
    double sum = 0.0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const Vector3f pos(side * (static_cast<float>(i) + 0.37f) / static_cast<float>(n),
                side * (static_cast<float>(j) + 0.61f) / static_cast<float>(n), 0.0f);
            sum += hatchCoverage(pos, Vector3f::UnitZ(), tone, toneCount, p, footprint);
        }
    return sum / (static_cast<double>(n) * n);
}

QString shaderPath()
{
    return QStringLiteral(CELFORM_SOURCE_DIR "/resources/shaders/celform_shading.glsl");
}

} // namespace

class TestShading : public QObject {
    Q_OBJECT

private slots:
    void rampValidity_data()
    {
        QTest::addColumn<ToonRamp>("ramp");
        QTest::addColumn<bool>("valid");
        const float nan = std::numeric_limits<float>::quiet_NaN();
        const float inf = std::numeric_limits<float>::infinity();
        QTest::newRow("default") << ToonRamp{} << true;
        QTest::newRow("three tones") << threeToneRamp() << true;
        QTest::newRow("one tone") << ToonRamp{{}, {1.0f}} << false;
        QTest::newRow("no tones") << ToonRamp{{}, {}} << false;
        QTest::newRow("too many thresholds") << ToonRamp{{0.0f, 0.5f}, {0.2f, 0.8f}} << false;
        QTest::newRow("too few thresholds") << ToonRamp{{0.0f}, {0.2f, 0.5f, 0.8f}} << false;
        QTest::newRow("descending") << ToonRamp{{0.5f, 0.0f}, {0.2f, 0.5f, 0.8f}} << false;
        QTest::newRow("equal thresholds") << ToonRamp{{0.5f, 0.5f}, {0.2f, 0.5f, 0.8f}} << false;
        QTest::newRow("NaN threshold") << ToonRamp{{nan}, {0.2f, 0.8f}} << false;
        QTest::newRow("infinite threshold") << ToonRamp{{inf}, {0.2f, 0.8f}} << false;
        QTest::newRow("infinite intensity") << ToonRamp{{0.5f}, {0.2f, inf}} << false;
        QTest::newRow("NaN intensity") << ToonRamp{{0.5f}, {nan, 0.8f}} << false;
    }

    void rampValidity()
    {
        QFETCH(ToonRamp, ramp);
        QFETCH(bool, valid);
        QCOMPARE(ramp.isValid(), valid);
    }

    void toonIntensity_data()
    {
        QTest::addColumn<ToonRamp>("ramp");
        QTest::addColumn<float>("lambert");
        QTest::addColumn<int>("tone");
        QTest::addColumn<float>("intensity");
        // Paper 3, section 3.3: t = 0.5, bright = 0.75, dark = 0.25.
        QTest::newRow("default 0.49") << ToonRamp{} << 0.49f << 0 << 0.25f;
        QTest::newRow("default at threshold") << ToonRamp{} << 0.5f << 1 << 0.75f;
        QTest::newRow("default 1") << ToonRamp{} << 1.0f << 1 << 0.75f;
        QTest::newRow("default -1") << ToonRamp{} << -1.0f << 0 << 0.25f;
        QTest::newRow("default offset past 1") << ToonRamp{} << 1.7f << 1 << 0.75f; // N.L + offset
        QTest::newRow("default NaN") << ToonRamp{} << std::numeric_limits<float>::quiet_NaN() << 0 << 0.25f;
        const ToonRamp r3 = threeToneRamp();
        QTest::newRow("3 tones -1") << r3 << -1.0f << 0 << 0.2f;
        QTest::newRow("3 tones -0.21") << r3 << -0.21f << 0 << 0.2f;
        QTest::newRow("3 tones at -0.2") << r3 << -0.2f << 1 << 0.6f;
        QTest::newRow("3 tones 0.39") << r3 << 0.39f << 1 << 0.6f;
        QTest::newRow("3 tones at 0.4") << r3 << 0.4f << 2 << 1.0f;
        QTest::newRow("3 tones 1") << r3 << 1.0f << 2 << 1.0f;
        QTest::newRow("3 tones -3") << r3 << -3.0f << 0 << 0.2f;
    }

    void toonIntensity()
    {
        QFETCH(ToonRamp, ramp);
        QFETCH(float, lambert);
        QFETCH(int, tone);
        QFETCH(float, intensity);
        QCOMPARE(toonTone(ramp, lambert), tone);
        QCOMPARE(celform::algo::toonIntensity(ramp, lambert), intensity);
    }

    void antialiasedToneBoundary()
    {
        // Issue 25: a one-pixel ramp centred on the threshold, the hard step without a width.
        ToonRamp ramp; // threshold 0.5, intensities 0.25 and 0.75
        QCOMPARE(toneCoverage(0.5f, 0.5f, 0.1f), 0.5f);
        QCOMPARE(toneCoverage(0.45f, 0.5f, 0.1f), 0.0f);
        QCOMPARE(toneCoverage(0.55f, 0.5f, 0.1f), 1.0f);
        QVERIFY(std::abs(toneCoverage(0.525f, 0.5f, 0.1f) - 0.75f) < 1e-6f);
        QCOMPARE(toneCoverage(0.5f, 0.5f, 0.0f), 1.0f);
        QCOMPARE(toneCoverage(0.49f, 0.5f, 0.0f), 0.0f);
        QCOMPARE(toneCoverage(std::nanf(""), 0.5f, 0.1f), 0.0f);
        QCOMPARE(toonIntensityAntialiased(ramp, 0.5f, 0.1f), 0.5f);
        // Away from the boundary, and with no width, exactly the hard tones.
        for (const float s : {-1.0f, 0.0f, 0.4f, 0.6f, 1.0f}) {
            QCOMPARE(toonIntensityAntialiased(ramp, s, 0.1f), celform::algo::toonIntensity(ramp, s));
            QCOMPARE(toonIntensityAntialiased(ramp, s, 0.0f), celform::algo::toonIntensity(ramp, s));
        }
        // Three tones: each boundary blends its own two neighbours.
        ToonRamp three;
        three.thresholds = {0.0f, 0.5f};
        three.intensities = {0.2f, 0.5f, 0.9f};
        QVERIFY(std::abs(toonIntensityAntialiased(three, 0.0f, 0.2f) - 0.35f) < 1e-6f);
        QVERIFY(std::abs(toonIntensityAntialiased(three, 0.5f, 0.2f) - 0.7f) < 1e-6f);
    }

    void lookupTable_data()
    {
        QTest::addColumn<ToonRamp>("ramp");
        QTest::addColumn<QVector<float>>("expected");
        // Entry i covers N.L in [-1 + i/16, -1 + (i+1)/16) and holds the ramp at its centre.
        // Default: centre >= 0.5 from i = 24 on.
        QVector<float> d(32, 0.25f);
        for (int i = 24; i < 32; ++i)
            d[i] = 0.75f;
        QTest::newRow("default") << ToonRamp{} << d;
        // Three tones: centre >= -0.2 from i = 13 (centre -0.15625), >= 0.4 from i = 22 (0.40625).
        QVector<float> t(32, 0.2f);
        for (int i = 13; i < 32; ++i)
            t[i] = i >= 22 ? 1.0f : 0.6f;
        QTest::newRow("three tones") << threeToneRamp() << t;
    }

    void lookupTable()
    {
        QFETCH(ToonRamp, ramp);
        QFETCH(QVector<float>, expected);
        const std::array<float, 32> table = toonLookupTable(ramp);
        for (int i = 0; i < 32; ++i)
            QCOMPARE(table[static_cast<std::size_t>(i)], expected[i]);
        // Every step boundary -1 + k/16 (exact in float) reads the step it opens; a little below it
        // (1/4096: the float nearest below can round back up in s + 1) reads the step before; 1
        // reads the last entry.
        for (int k = 0; k <= 32; ++k) {
            const float boundary = -1.0f + static_cast<float>(k) / 16.0f;
            QCOMPARE(lookupIntensity(table, boundary), expected[std::min(k, 31)]);
            if (k > 0)
                QCOMPARE(lookupIntensity(table, boundary - 1.0f / 4096.0f), expected[k - 1]);
        }
        QCOMPARE(lookupIntensity(table, -5.0f), expected[0]);
        QCOMPARE(lookupIntensity(table, 5.0f), expected[31]);
        QCOMPARE(lookupIntensity(table, std::numeric_limits<float>::quiet_NaN()), expected[0]);
        QCOMPARE(lookupIntensity(table, std::numeric_limits<float>::infinity()), expected[31]);
    }

    void lookupAgreesAwayFromThresholds_data()
    {
        QTest::addColumn<ToonRamp>("ramp");
        QTest::newRow("default") << ToonRamp{};
        QTest::newRow("three tones") << threeToneRamp();
        QTest::newRow("four tones, odd thresholds") << ToonRamp{{-0.53f, 0.11f, 0.77f}, {0.1f, 0.3f, 0.6f, 0.9f}};
    }

    void lookupAgreesAwayFromThresholds()
    {
        QFETCH(ToonRamp, ramp);
        const std::array<float, 32> table = toonLookupTable(ramp);
        int compared = 0;
        for (int i = 0; i <= 2000; ++i) {
            const float lambert = -1.0f + 2.0f * static_cast<float>(i) / 2000.0f;
            bool nearThreshold = false;
            for (const float t : ramp.thresholds)
                nearThreshold = nearThreshold || std::abs(lambert - t) <= 1.0f / 16.0f; // one table step
            if (nearThreshold)
                continue;
            ++compared;
            QCOMPARE(lookupIntensity(table, lambert), celform::algo::toonIntensity(ramp, lambert));
        }
        QVERIFY(compared > 1500);
    }

    void goochShade_data()
    {
        QTest::addColumn<GoochParams>("params");
        QTest::addColumn<Color>("base");
        QTest::addColumn<Vector3f>("n");
        QTest::addColumn<Color>("expected");
        const Vector3f l1 = Vector3f(1.0f, 2.0f, 2.0f) / 3.0f; // unit, not axis-aligned
        const Vector3f perp = Vector3f(2.0f, -2.0f, 1.0f) / 3.0f; // unit, perpendicular to l1
        const GoochParams def;
        const Color c(0.5f, 0.4f, 0.3f);
        // warm (1, .55, .1), cool (.1, .25, 1), ka .9, k1..k4 1.
        // n = l1: .9C + (warm - C) = warm - .1C.
        QTest::newRow("default, n = l1") << def << c << l1 << Color(0.95f, 0.51f, 0.07f);
        // n = -l1: .9C + (cool - C) = cool - .1C.
        QTest::newRow("default, n = -l1") << def << c << Vector3f(-l1) << Color(0.05f, 0.21f, 0.97f);
        // n perpendicular to l1: ambient only.
        QTest::newRow("default, n perp l1") << def << c << perp << Color(0.45f, 0.36f, 0.27f);
        // 60 degrees from l1 (l1.n = 0.5): .9C + .5 (warm - C).
        const Vector3f at60 = (0.5f * l1 + std::sqrt(0.75f) * perp).normalized();
        QTest::newRow("default, 60 degrees") << def << c << at60 << Color(0.45f + 0.25f, 0.36f + 0.075f, 0.27f - 0.1f);
        // k1 = .5, k2 = .8, n = l1, C = (.2, .4, .6): .9C + (warm - .5C) * .8 = (.9, .64, .38).
        GoochParams custom;
        custom.k1 = 0.5f;
        custom.k2 = 0.8f;
        QTest::newRow("k1 .5 k2 .8, n = l1") << custom << Color(0.2f, 0.4f, 0.6f) << l1 << Color(0.9f, 0.64f, 0.38f);
        // Purple preset (k4 = 2), n = -l1, C = (.5, .1, .7): .9C + (cool - C) * 2 = (-.35, .39, 1.23),
        // clamped to (0, .39, 1).
        QTest::newRow("purple, n = -l1, clamped")
            << goochPreset("purple") << Color(0.5f, 0.1f, 0.7f) << Vector3f(-l1) << Color(0.0f, 0.39f, 1.0f);
        // White preset (k2 = 0): the warm light is off, n = l1 gives ambient only.
        QTest::newRow("white, n = l1") << goochPreset("white") << Color(0.95f, 0.95f, 0.95f) << l1
                                       << Color(0.855f, 0.855f, 0.855f);
        // Red preset (k2 = .5, k4 = 1.5), C = (.85, .1, .1):
        // n = l1: .9C + (warm - C) * .5 = (.765 + .075, .09 + .225, .09 + 0) = (.84, .315, .09);
        QTest::newRow("red, n = l1") << goochPreset("red") << Color(0.85f, 0.1f, 0.1f) << l1
                                     << Color(0.84f, 0.315f, 0.09f);
        // n = -l1: .9C + (cool - C) * 1.5 = (.765 - 1.125, .09 + .225, .09 + 1.35) -> (0, .315, 1).
        QTest::newRow("red, n = -l1") << goochPreset("red") << Color(0.85f, 0.1f, 0.1f) << Vector3f(-l1)
                                      << Color(0.0f, 0.315f, 1.0f);
    }

    void goochShade()
    {
        QFETCH(GoochParams, params);
        QFETCH(Color, base);
        QFETCH(Vector3f, n);
        QFETCH(Color, expected);
        const Vector3f l1 = Vector3f(1.0f, 2.0f, 2.0f) / 3.0f;
        const Color got = celform::algo::goochShade(base, n, l1, params);
        QVERIFY2(colorNear(got, expected), describe(got) + " expected " + describe(expected));
    }

    void goochPresets()
    {
        const GoochParams def = goochPreset("default");
        QCOMPARE(def, GoochParams{});
        QCOMPARE(def.ka, 0.9f);
        QCOMPARE(def.k1, 1.0f);
        QCOMPARE(def.k2, 1.0f);
        QCOMPARE(def.k3, 1.0f);
        QCOMPARE(def.k4, 1.0f);
        QCOMPARE(goochPreset("no such preset"), def);

        const GoochParams white = goochPreset("white");
        QCOMPARE(white.preset, std::string("white"));
        QCOMPARE(white.k2, 0.0f);
        QCOMPARE(white.k4, 1.0f);

        const GoochParams purple = goochPreset("purple");
        QCOMPARE(purple.preset, std::string("purple"));
        QCOMPARE(purple.k4, 2.0f);
        QCOMPARE(purple.k2, 1.0f);

        const GoochParams red = goochPreset("red");
        QCOMPARE(red.preset, std::string("red"));
        QVERIFY(red.k2 < def.k2); // less warm light
        QVERIFY(red.k4 > def.k4); // more cool light
        QCOMPARE(red.k2, 0.5f);
        QCOMPARE(red.k4, 1.5f);
    }

    void goochPresetForColor_data()
    {
        QTest::addColumn<Color>("base");
        QTest::addColumn<QString>("preset");
        QTest::newRow("white") << Color(0.95f, 0.95f, 0.95f) << "white";
        QTest::newRow("cool white") << Color(0.85f, 0.9f, 0.95f) << "white";
        QTest::newRow("purple") << Color(0.5f, 0.1f, 0.7f) << "purple"; // hue 280
        QTest::newRow("red") << Color(0.85f, 0.1f, 0.1f) << "red";
        QTest::newRow("dark red") << Color(0.3f, 0.05f, 0.05f) << "red";
        QTest::newRow("crimson") << Color(0.9f, 0.1f, 0.3f) << "red"; // hue 345
        QTest::newRow("green") << Color(0.1f, 0.7f, 0.2f) << "default";
        QTest::newRow("mid grey") << Color(0.5f, 0.5f, 0.5f) << "default";
        QTest::newRow("black") << Color(0.0f, 0.0f, 0.0f) << "default";
        QTest::newRow("orange") << Color(0.9f, 0.5f, 0.1f) << "default"; // hue 30
        QTest::newRow("pale pink") << Color(0.9f, 0.7f, 0.7f) << "default"; // red hue, saturation .22
        QTest::newRow("blue") << Color(0.1f, 0.2f, 0.9f) << "default"; // hue 232.5
        QTest::newRow("NaN") << Color(std::numeric_limits<float>::quiet_NaN(), 0.5f, 0.5f) << "default";
    }

    void goochPresetForColor()
    {
        QFETCH(Color, base);
        QFETCH(QString, preset);
        const GoochParams p = celform::algo::goochPresetForColor(base);
        QCOMPARE(QString::fromStdString(p.preset), preset);
        QCOMPARE(p, goochPreset(preset.toStdString()));
    }

    void hatchBrightestToneHasNoInk()
    {
        const HatchParams p;
        const Vector3f normals[]
            = {Vector3f::UnitX(), Vector3f::UnitY(), Vector3f::UnitZ(), Vector3f(0.3f, -0.5f, 0.8f).normalized()};
        for (int toneCount = 2; toneCount <= 4; ++toneCount)
            for (const Vector3f& n : normals)
                for (int i = 0; i < 2000; ++i) {
                    const Vector3f pos(0.0013f * static_cast<float>(i), 0.0007f * static_cast<float>(i), 0.011f);
                    QCOMPARE(hatchCoverage(pos, n, toneCount - 1, toneCount, p, 0.0f), 0.0f);
                    QCOMPARE(hatchCoverage(pos, n, toneCount - 1, toneCount, p, 0.005f), 0.0f);
                }
        // A single tone has no shadow to hatch.
        QCOMPARE(hatchCoverage(Vector3f::Zero(), Vector3f::UnitZ(), 0, 1, p, 0.0f), 0.0f);
    }

    void hatchSingleStrokes()
    {
        const HatchParams p; // spacing .02, 45 degrees, width .35
        // Hard edges (no footprint): only ink or paper, covering the width on average.
        int ink = 0;
        int paper = 0;
        for (int i = 0; i < 1000; ++i) {
            const Vector3f pos(0.00173f * static_cast<float>(i), 0.00091f * static_cast<float>(i), 0.0f);
            const float c = hatchCoverage(pos, Vector3f::UnitZ(), 0, 2, p, 0.0f);
            QVERIFY(c == 0.0f || c == 1.0f);
            (c == 1.0f ? ink : paper) += 1;
        }
        QVERIFY(ink > 100 && paper > 100);
        QVERIFY(std::abs(meanCoverage(0, 2, p, 0.0f) - p.width) < 0.01);
        // Anti-aliased edges (a quarter of the spacing per pixel): partial values, same mean.
        QVERIFY(std::abs(meanCoverage(0, 2, p, 0.005f) - p.width) < 0.01);
        bool partial = false;
        for (int i = 0; i < 200 && !partial; ++i) {
            const float c = hatchCoverage(
                Vector3f(0.0011f * static_cast<float>(i), 0.0f, 0.0f), Vector3f::UnitZ(), 0, 2, p, 0.005f);
            partial = c > 0.01f && c < 0.99f;
        }
        QVERIFY(partial);
        // Strokes run along the angle (45 degrees in the (x, y) plane of a +Z normal): constant
        // coverage along (1, 1), and a stroke period of spacing * sqrt(2) along x.
        const Vector3f start(0.0123f, 0.0049f, 0.0f);
        const float c0 = hatchCoverage(start, Vector3f::UnitZ(), 0, 2, p, 0.003f);
        for (int i = 1; i < 50; ++i) {
            const Vector3f along = start + Vector3f(1.0f, 1.0f, 0.0f) * (0.0037f * static_cast<float>(i));
            QVERIFY(std::abs(hatchCoverage(along, Vector3f::UnitZ(), 0, 2, p, 0.003f) - c0) < 1e-3f);
        }
        const Vector3f period = start + Vector3f(p.spacing * std::sqrt(2.0f), 0.0f, 0.0f);
        QVERIFY(std::abs(hatchCoverage(period, Vector3f::UnitZ(), 0, 2, p, 0.003f) - c0) < 1e-3f);
        // The tone above the darkest of three is hatched with single strokes too.
        QVERIFY(std::abs(meanCoverage(1, 3, p, 0.0f) - p.width) < 0.01);
    }

    void hatchTriPlanar()
    {
        const HatchParams p;
        // An x-dominant normal projects on (y, z): moving along x changes nothing; the same for
        // y (z, x) and z (x, y).
        const Vector3f base(0.0311f, 0.0172f, 0.0093f);
        const Vector3f normals[]
            = {Vector3f(0.9f, 0.3f, 0.3f), Vector3f(0.2f, -0.9f, 0.3f), Vector3f(0.1f, 0.2f, 0.95f)};
        for (int axis = 0; axis < 3; ++axis) {
            const float c0 = hatchCoverage(base, normals[axis], 0, 3, p, 0.004f);
            for (int i = 1; i < 20; ++i) {
                Vector3f pos = base;
                pos[axis] += 0.0071f * static_cast<float>(i);
                QCOMPARE(hatchCoverage(pos, normals[axis], 0, 3, p, 0.004f), c0);
            }
        }
    }

    void hatchCrossIsDarker()
    {
        const HatchParams p;
        const double single = meanCoverage(1, 3, p, 0.0f);
        const double cross = meanCoverage(0, 3, p, 0.0f);
        QVERIFY(cross > single + 0.1);
        // Two orthogonal stripe sets cover 1 - (1 - width)^2 of the plane.
        const double w = p.width;
        QVERIFY(std::abs(cross - (1.0 - (1.0 - w) * (1.0 - w))) < 0.015);
        // Every darker tone of a four-tone ramp is cross-hatched.
        QVERIFY(std::abs(meanCoverage(0, 4, p, 0.0f) - cross) < 0.015);
        QVERIFY(std::abs(meanCoverage(1, 4, p, 0.0f) - cross) < 0.015);
        QVERIFY(std::abs(meanCoverage(2, 4, p, 0.0f) - single) < 1e-9);
        // Cross-hatching is never lighter than single strokes, point by point.
        for (int i = 0; i < 2000; ++i) {
            const Vector3f pos(0.00113f * static_cast<float>(i), 0.00071f * static_cast<float>(i), 0.0f);
            QVERIFY(hatchCoverage(pos, Vector3f::UnitZ(), 0, 3, p, 0.004f)
                >= hatchCoverage(pos, Vector3f::UnitZ(), 1, 3, p, 0.004f));
        }
    }

    void hatchDeterministic()
    {
        HatchParams p;
        p.angleDegrees = 30.0f;
        for (int i = 0; i < 500; ++i) {
            const Vector3f pos(0.0131f * static_cast<float>(i), -0.0077f * static_cast<float>(i), 0.5f);
            const Vector3f n = Vector3f(0.2f, 0.5f, 0.7f).normalized();
            for (int tone = 0; tone < 3; ++tone) {
                const float a = hatchCoverage(pos, n, tone, 3, p, 0.003f);
                const float b = hatchCoverage(pos, n, tone, 3, p, 0.003f);
                QVERIFY(std::memcmp(&a, &b, sizeof a) == 0);
                QVERIFY(a >= 0.0f && a <= 1.0f);
            }
        }
    }

    void hatchLargeFootprintIsGrey()
    {
        const HatchParams p;
        const double crossMean = 1.0 - (1.0 - p.width) * (1.0 - p.width);
        // Footprint at or past the spacing: flat grey, the mean coverage, at every point.
        for (const float footprint : {p.spacing, 2.0f * p.spacing, 10.0f * p.spacing}) {
            for (int i = 0; i < 500; ++i) {
                const Vector3f pos(0.00137f * static_cast<float>(i), 0.00291f * static_cast<float>(i), 0.0f);
                QVERIFY(std::abs(hatchCoverage(pos, Vector3f::UnitZ(), 0, 2, p, footprint) - p.width) < 1e-6f);
                QVERIFY(std::abs(hatchCoverage(pos, Vector3f::UnitZ(), 0, 3, p, footprint) - crossMean) < 1e-6);
            }
        }
        // Between half the spacing and the spacing: fading, little contrast left, mean kept.
        const float footprint = 0.75f * p.spacing;
        float lo = 1.0f;
        float hi = 0.0f;
        for (int i = 0; i < 500; ++i) {
            const float c = hatchCoverage(
                Vector3f(0.00137f * static_cast<float>(i), 0.0f, 0.0f), Vector3f::UnitZ(), 0, 2, p, footprint);
            lo = std::min(lo, c);
            hi = std::max(hi, c);
        }
        QVERIFY(hi - lo < 0.5f);
        QVERIFY(std::abs(meanCoverage(0, 2, p, footprint) - p.width) < 0.01);
    }

    void hatchDegenerateParams()
    {
        HatchParams p;
        const Vector3f pos(0.01f, 0.02f, 0.0f);
        const float nan = std::numeric_limits<float>::quiet_NaN();
        // Negative or NaN footprints are hard edges, not NaN.
        const float c = hatchCoverage(pos, Vector3f::UnitZ(), 0, 2, p, nan);
        QVERIFY(c == 0.0f || c == 1.0f);
        QCOMPARE(hatchCoverage(pos, Vector3f::UnitZ(), 0, 2, p, -1.0f), c);
        // No spacing: nothing can be drawn.
        p.spacing = 0.0f;
        QCOMPARE(hatchCoverage(pos, Vector3f::UnitZ(), 0, 2, p, 0.0f), 0.0f);
        p.spacing = nan;
        QCOMPARE(hatchCoverage(pos, Vector3f::UnitZ(), 0, 2, p, 0.0f), 0.0f);
    }

    void glslMirror()
    {
        QFile file(shaderPath());
        QVERIFY2(file.open(QIODevice::ReadOnly | QIODevice::Text), qPrintable(shaderPath()));
        const QString source = QString::fromUtf8(file.readAll());
        // A snippet: VTK's shader supplies the version directive.
        QVERIFY(!source.contains(
            QRegularExpression(QStringLiteral("^\\s*#\\s*version"), QRegularExpression::MultilineOption)));
        for (const char* signature : {"float cfToonIntensity(float lambert)", "float cfLookupIntensity(float lambert)",
                 "float cfToonIntensityAntialiased(float lambert, float width)",
                 "vec3 cfGoochShade(vec3 base, vec3 n, vec3 l1)",
                 "float cfHatchCoverage(vec3 position, vec3 normal, int tone, int toneCount, float footprint)"})
            QVERIFY2(source.contains(QLatin1String(signature)), signature);
        for (const char* uniform : {"uniform int cfToneCount;", "uniform float cfThresholds[7];",
                 "uniform float cfIntensities[8];", "uniform float cfLut[32];"})
            QVERIFY2(source.contains(QLatin1String(uniform)), uniform);

        const QString validator = QStandardPaths::findExecutable(QStringLiteral("glslangValidator"));
        if (validator.isEmpty())
            QSKIP("glslangValidator not installed (Debian package glslang-tools): GLSL not compiled");
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("celform_shading_check.frag"));
        QFile out(path);
        QVERIFY(out.open(QIODevice::WriteOnly | QIODevice::Text));
        // As VTK would: a GLSL 1.50 fragment shader around the snippet, calling every function.
        out.write("#version 150\n");
        out.write(source.toUtf8());
        out.write(
            "\nout vec4 fragColor;\n"
            "void main()\n"
            "{\n"
            "    float t = cfToonIntensity(0.3) + cfLookupIntensity(-0.2) + cfToonIntensityAntialiased(0.5, 0.01);\n"
            "    vec3 g = cfGoochShade(vec3(0.5), vec3(0.0, 0.0, 1.0), vec3(0.0, 0.6, 0.8));\n"
            "    float h = cfHatchCoverage(vec3(0.1, 0.2, 0.3), vec3(0.0, 0.0, 1.0), 0, 3, 0.001);\n"
            "    fragColor = vec4(g * t, h);\n"
            "}\n");
        out.close();
        QProcess process;
        process.start(validator, {path});
        QVERIFY(process.waitForFinished(60000));
        QVERIFY2(process.exitStatus() == QProcess::NormalExit && process.exitCode() == 0,
            process.readAllStandardOutput().constData());
    }
};

QTEST_APPLESS_MAIN(TestShading)
#include "test_shading.moc"
