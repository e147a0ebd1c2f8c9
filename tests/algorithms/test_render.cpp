// The offline renderer on scenes computed by hand: tone counts and boundaries on a sphere (paper 3,
// section 3.3), the Gooch formula per pixel (paper 1, section 3.2.4), the shading offset
// (paper 3, equation 4.3), passes and determinism.
#include "test_support.h"

#include "celform/algorithms/render.h"
#include "celform/algorithms/srgb_encode.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <set>

using namespace celform::algo;

namespace {

/// A UV sphere of radius 1 at the origin with outward counter-clockwise faces.
TriMesh sphere(int stacks = 48, int slices = 96)
{
    TriMesh m;
    m.vertices.resize((stacks + 1) * slices, 3);
    for (int i = 0; i <= stacks; ++i)
        for (int j = 0; j < slices; ++j) {
            const double t = M_PI * i / stacks, p = 2 * M_PI * j / slices;
            m.vertices.row(i * slices + j) << float(std::sin(t) * std::cos(p)), float(std::cos(t)),
                float(std::sin(t) * std::sin(p));
        }
    std::vector<std::array<int, 3>> f;
    for (int i = 0; i < stacks; ++i)
        for (int j = 0; j < slices; ++j) {
            const int a = i * slices + j, b = i * slices + (j + 1) % slices, c = a + slices, d = b + slices;
            if (i > 0)
                f.push_back({a, b, c});
            if (i < stacks - 1)
                f.push_back({b, d, c});
        }
    m.faces.resize(Eigen::Index(f.size()), 3);
    for (size_t k = 0; k < f.size(); ++k)
        m.faces.row(Eigen::Index(k)) << f[k][0], f[k][1], f[k][2];
    return m;
}

RasterCamera frontCamera(int size = 200)
{
    RasterCamera c;
    c.eye = Eigen::Vector3d(0, 0, 6);
    c.target = Eigen::Vector3d::Zero();
    c.orthographic = true;
    c.orthoHeight = 2.4;
    c.width = c.height = size;
    return c;
}

RenderLook plainLook(Style style)
{
    RenderLook look;
    look.style = style;
    look.lines = false;
    look.light = Eigen::Vector3f(0, 0, 1); // from the camera's side: N.L = n.z on the sphere
    look.defaultColor = Color(0.8f, 0.6f, 0.4f);
    return look;
}

} // namespace

class TestRender : public QObject {
    Q_OBJECT
private slots:
    // Issue 29: the table quantiser gives the power function's bytes exactly: at every step of
    // the code (a value and its neighbours one float apart), on two million random values, and
    // on the edges (NaN, infinities, negatives, above one).
    void srgbQuantiserMatchesThePowerFunction()
    {
        int mismatches = 0;
        auto check = [&](float v) {
            if (celform::algo::srgbEncode8(v) != celform::algo::srgbEncode8Reference(v) && ++mismatches <= 5)
                qWarning("%.9g: table %d, reference %d", double(v), celform::algo::srgbEncode8(v),
                    celform::algo::srgbEncode8Reference(v));
        };
        // Each code's first value: bisect the reference's step from k - 1 to k.
        for (int k = 1; k <= 255; ++k) {
            float lo = 0.f, hi = 1.f;
            for (int i = 0; i < 60; ++i) {
                const float mid = 0.5f * (lo + hi);
                (celform::algo::srgbEncode8Reference(mid) >= k ? hi : lo) = mid;
            }
            float v = std::nextafter(lo, 0.f);
            for (int i = 0; i < 4; ++i, v = std::nextafter(v, 2.f))
                check(v);
        }
        std::mt19937 random(29);
        std::uniform_real_distribution<float> unit(-0.1f, 1.1f);
        for (int i = 0; i < 2000000; ++i)
            check(unit(random));
        for (float v : {0.f, -0.f, 1.f, -1.f, 2.f, 1e-30f, std::numeric_limits<float>::denorm_min(),
                 std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
                 std::numeric_limits<float>::quiet_NaN(), std::nextafter(1.f, 0.f)})
            check(v);
        QCOMPARE(mismatches, 0);
        QCOMPARE(int(celform::algo::srgbEncode8(std::numeric_limits<float>::quiet_NaN())), 0);
        QCOMPARE(int(celform::algo::srgbEncode8(0.5f)), 188); // 1.055 * 0.5^(1/2.4) - 0.055 = 0.7354

        // RGBA: colour encoded, alpha scaled linearly.
        const float in[8] = {0.5f, 0.f, 1.f, 0.5f, 0.2140f, 0.0031308f, 2.f, 0.25f};
        std::uint8_t out[8] = {};
        celform::algo::quantise8(in, out, 8, 4, 3, true);
        const std::uint8_t expected[8] = {188, 0, 255, 128, 127, 10, 255, 64};
        QCOMPARE(std::memcmp(out, expected, 8), 0);
        celform::algo::quantise8(in, out, 8, 4, 3, false); // data: every channel linear
        QCOMPARE(int(out[0]), 128);

        // Runs of equal RGBA pixels (a toon frame's flat tones) take their first pixel's codes,
        // pixel by pixel the same as each quantised alone; NaN pixels in a run too.
        std::vector<float> runs;
        for (int k = 0; k < 3000; ++k) {
            const float v = k % 7 < 4 ? float(k / 7) / 430.f : unit(random);
            const float a = k % 11 == 0 ? std::numeric_limits<float>::quiet_NaN() : 0.5f;
            for (int r = 0; r < 1 + k % 5; ++r)
                runs.insert(runs.end(), {v, 1.f - v, 0.5f * v, a});
        }
        std::vector<std::uint8_t> quantised(runs.size());
        celform::algo::quantise8(runs.data(), quantised.data(), runs.size(), 4, 3, true);
        int runMismatches = 0;
        for (std::size_t i = 0; i < runs.size(); i += 4) {
            std::uint8_t alone[4] = {};
            celform::algo::quantise8(runs.data() + i, alone, 4, 4, 3, true);
            runMismatches += std::memcmp(alone, quantised.data() + i, 4) != 0 ? 1 : 0;
        }
        QCOMPARE(runMismatches, 0);

        // Linear channels (alpha, data) round as std::lround(255 * clamp(v, 0, 1)) did: around
        // every half-way point, on random values, on the edges.
        std::vector<float> values;
        for (int k = 0; k < 255; ++k) {
            float v = std::nextafter((float(k) + 0.5f) / 255.f, 0.f);
            for (int i = 0; i < 5; ++i, v = std::nextafter(v, 2.f))
                values.push_back(std::nextafter(v, 0.f));
        }
        for (int i = 0; i < 200000; ++i)
            values.push_back(unit(random));
        for (float v : {0.f, -0.f, 1.f, 2.f, -1.f, std::numeric_limits<float>::infinity(),
                 -std::numeric_limits<float>::infinity(), std::numeric_limits<float>::quiet_NaN()})
            values.push_back(v);
        std::vector<std::uint8_t> linear(values.size());
        celform::algo::quantise8(values.data(), linear.data(), values.size(), 1, 0, false);
        int linearMismatches = 0;
        for (std::size_t i = 0; i < values.size(); ++i) {
            const float c = std::clamp(values[i], 0.f, 1.f);
            const int rounded = c == c ? int(std::lround(c * 255.f)) : 0;
            linearMismatches += int(linear[i]) != rounded ? 1 : 0;
        }
        QCOMPARE(linearMismatches, 0);
    }

    // Issue 29: a file of the beauty alone asks for no data passes; the beauty and the lines are
    // the same to the bit, the data passes stay empty, and the next frame with them fills them
    // again from the same buffers.
    void beautyAloneSkipsTheDataPasses()
    {
        const TriMesh mesh = sphere();
        RenderLook look = plainLook(Style::Toon);
        look.lines = true;
        RenderCache cache;
        RenderPasses full, alone;
        renderFrame(mesh.vertices, mesh, frontCamera(), look, cache, full);
        look.dataPasses = false;
        renderFrame(mesh.vertices, mesh, frontCamera(), look, cache, alone);
        QCOMPARE(alone.beauty.pixels, full.beauty.pixels);
        QCOMPARE(alone.lines, full.lines);
        QVERIFY(std::any_of(full.lines.begin(), full.lines.end(), [](float v) { return v > 0.5f; }));
        QCOMPARE(alone.strokes.size(), full.strokes.size());
        QVERIFY(alone.tone.empty() && alone.highlights.empty() && alone.depth.empty() && alone.normal.empty()
            && alone.id.empty());
        look.dataPasses = true;
        renderFrame(mesh.vertices, mesh, frontCamera(), look, cache, alone);
        QCOMPARE(alone.tone, full.tone);
        QCOMPARE(alone.id, full.id);
        QCOMPARE(alone.normal.size(), full.normal.size());
    }

    void toonHasExactlyItsTones_data()
    {
        QTest::addColumn<int>("tones");
        QTest::newRow("2 tones") << 2;
        QTest::newRow("3 tones") << 3;
        QTest::newRow("5 tones") << 5;
    }
    void toonHasExactlyItsTones()
    {
        QFETCH(int, tones);
        const TriMesh mesh = sphere();
        RenderLook look = plainLook(Style::Toon);
        look.toneAntialiasing = ToneAntialiasing::Off;
        look.toon.thresholds.clear();
        look.toon.intensities.clear();
        for (int i = 0; i < tones; ++i) {
            look.toon.intensities.push_back(0.2f + 0.7f * float(i) / float(tones - 1));
            if (i > 0)
                look.toon.thresholds.push_back(float(i) / float(tones));
        }
        RenderCache cache;
        RenderPasses out;
        renderFrame(mesh.vertices, mesh, frontCamera(), look, cache, out);
        std::set<std::array<float, 3>> colours;
        for (int y = 0; y < out.beauty.height; ++y)
            for (int x = 0; x < out.beauty.width; ++x)
                if (out.id[size_t(y * out.beauty.width + x)] >= 0) {
                    const float* p = out.beauty.at(x, y);
                    colours.insert({p[0], p[1], p[2]});
                }
        // Without tone anti-aliasing: one colour per tone, no more, no less.
        QCOMPARE(int(colours.size()), tones);
    }

    void toneBoundaryWhereLambertCrossesThreshold()
    {
        // Default ramp: t = 0.5. Seen from +Z with the light at +Z, N.L = n.z = sqrt(1 - r^2) on the
        // unit sphere; the boundary is the circle r = sqrt(1 - 0.25) = 0.866.
        const TriMesh mesh = sphere(96, 192);
        RenderLook look = plainLook(Style::Toon);
        RenderCache cache;
        RenderPasses out;
        const RasterCamera camera = frontCamera(400);
        renderFrame(mesh.vertices, mesh, camera, look, cache, out);
        const int y = 200;
        double boundary = -1;
        for (int x = 200; x < 400; ++x) {
            if (out.tone[size_t(y * 400 + x)] < 0.5f && out.id[size_t(y * 400 + x)] >= 0) {
                boundary = (x + 0.5 - 200) * camera.orthoHeight / 400;
                break;
            }
        }
        QVERIFY(boundary > 0);
        QVERIFY2(std::abs(boundary - std::sqrt(0.75)) < 0.02, qPrintable(QString::number(boundary)));
    }

    void antialiasedToneBoundary()
    {
        // Issue 25: coverage blends only the pixels the hard boundary runs through, and agrees
        // with 4x supersampling of the tone.
        const TriMesh mesh = sphere();
        RenderLook look = plainLook(Style::Toon);
        RenderCache cache;
        RenderPasses hard, coverage, supersampled;
        look.toneAntialiasing = ToneAntialiasing::Off;
        renderFrame(mesh.vertices, mesh, frontCamera(), look, cache, hard);
        look.toneAntialiasing = ToneAntialiasing::Coverage;
        renderFrame(mesh.vertices, mesh, frontCamera(), look, cache, coverage);
        look.toneAntialiasing = ToneAntialiasing::Supersample4;
        renderFrame(mesh.vertices, mesh, frontCamera(), look, cache, supersampled);
        const int w = 200;
        int blended = 0, strayBlend = 0;
        double difference = 0;
        for (int y = 1; y + 1 < w; ++y)
            for (int x = 1; x + 1 < w; ++x) {
                const auto i = std::size_t(y * w + x);
                if (hard.id[i] < 0)
                    continue;
                const float c = coverage.tone[i];
                if (c == hard.tone[i])
                    continue;
                ++blended;
                difference += std::abs(double(c) - double(supersampled.tone[i]));
                bool boundary = false; // a neighbour of the other hard tone
                for (const int d : {-1, 1})
                    boundary = boundary || hard.tone[i + std::size_t(d)] != hard.tone[i]
                        || hard.tone[std::size_t(int(i) + d * w)] != hard.tone[i];
                strayBlend += boundary ? 0 : 1;
                QVERIFY(c > 0.25f && c < 0.75f);
            }
        // The boundary circle r = 0.866 is 2 * pi * 0.866 * (200 / 2.4) = 453 px long.
        qInfo("%d blended boundary pixels, %d away from the hard boundary, mean |coverage - 4x| %.3f", blended,
            strayBlend, blended ? difference / blended : 0.0);
        QVERIFY(blended > 200 && blended < 1400);
        QVERIFY(strayBlend <= blended / 20);
        QVERIFY(difference / blended < 0.15);
    }

    void shadingOffsetMovesTheBoundary()
    {
        const TriMesh mesh = sphere();
        RenderLook look = plainLook(Style::Toon);
        RenderCache cache;
        RenderPasses plain, offset;
        renderFrame(mesh.vertices, mesh, frontCamera(), look, cache, plain);
        const std::vector<float> offsets(size_t(mesh.vertexCount()), 0.3f); // paper 3, eq. 4.3
        look.shadingOffsets = &offsets;
        renderFrame(mesh.vertices, mesh, frontCamera(), look, cache, offset);
        auto bright = [](const RenderPasses& p) { return std::count(p.tone.begin(), p.tone.end(), 0.75f); };
        QVERIFY(bright(offset) > bright(plain));
    }

    void goochPixelMatchesTheFormula()
    {
        // At the sphere's centre n = (0,0,1) = l1: C = ka*Cb + (Cw - Cb*k1)*k2 (the cool term is 0).
        const TriMesh mesh = sphere();
        RenderLook look = plainLook(Style::Gooch);
        look.gooch.ka = 0.9f;
        look.gooch.k1 = look.gooch.k2 = look.gooch.k3 = look.gooch.k4 = 1.f;
        look.gooch.warm = Color(0.6f, 0.4f, 0.1f);
        RenderCache cache;
        RenderPasses out;
        renderFrame(mesh.vertices, mesh, frontCamera(), look, cache, out);
        const float* p = out.beauty.at(100, 100);
        const Color cb = look.defaultColor;
        const Color expected = (0.9f * cb + (look.gooch.warm - cb)).cwiseMax(0.f).cwiseMin(1.f);
        for (int c = 0; c < 3; ++c)
            QVERIFY2(std::abs(p[c] - expected[c]) < 0.01f,
                qPrintable(QStringLiteral("%1 vs %2").arg(p[c]).arg(expected[c])));
    }

    void perFaceAndPerVertexDiffer()
    {
        const TriMesh mesh = sphere(12, 24);
        RenderLook look = plainLook(Style::Toon);
        RenderCache cache;
        RenderPasses pixel, face, vertex;
        renderFrame(mesh.vertices, mesh, frontCamera(), look, cache, pixel);
        look.toonEvaluation = ToonEvaluation::PerFace;
        renderFrame(mesh.vertices, mesh, frontCamera(), look, cache, face);
        look.toonEvaluation = ToonEvaluation::PerVertexLut;
        renderFrame(mesh.vertices, mesh, frontCamera(), look, cache, vertex);
        QVERIFY(pixel.beauty.pixels != face.beauty.pixels);
        QVERIFY(pixel.beauty.pixels != vertex.beauty.pixels);
        // Per vertex interpolates the table values: intermediate intensities appear.
        std::set<float> intensities(vertex.tone.begin(), vertex.tone.end());
        QVERIFY(intensities.size() > 3);
    }

    void linesOutlineTheSphere()
    {
        const TriMesh mesh = sphere();
        RenderLook look = plainLook(Style::Toon);
        look.lines = true;
        RenderCache cache;
        RenderPasses out;
        renderFrame(mesh.vertices, mesh, frontCamera(), look, cache, out);
        // Lines on the rim (r ~ 1 => ~83 px from the centre), none in the middle.
        QVERIFY(out.lines[size_t(100 * 200 + 100)] == 0.f);
        float rim = 0.f;
        for (int x = 170; x < 200; ++x)
            rim = std::max(rim, out.lines[size_t(100 * 200 + x)]);
        QVERIFY(rim > 0.9f);
    }

    void passesAndDeterminism()
    {
        const TriMesh mesh = sphere();
        RenderLook look = plainLook(Style::Comic);
        look.lines = true;
        RenderCache cache;
        RenderPasses a, b;
        renderFrame(mesh.vertices, mesh, frontCamera(), look, cache, a);
        renderFrame(mesh.vertices, mesh, frontCamera(), look, cache, b);
        QVERIFY(a.beauty.pixels == b.beauty.pixels);
        QCOMPARE(a.tone.size(), size_t(200 * 200));
        QCOMPARE(a.highlights.size(), size_t(200 * 200));
        QVERIFY(std::all_of(a.highlights.begin(), a.highlights.end(), [](float v) { return v == 0.f; }));
        QVERIFY(std::isinf(a.depth[0]));
        QVERIFY(std::abs(a.depth[size_t(100 * 200 + 100)] - 5.f) < 0.01f); // eye at z=6, sphere front at z=1
        QVERIFY(a.normal[size_t(100 * 200 + 100)].isApprox(Eigen::Vector3f(0, 0, 1), 0.02f));
        QCOMPARE(a.id[0], -1);
    }

    void highlightsPass()
    {
        // Light and eye at +Z: the original highlight (Anjyo & Hiramitsu 2003, eq. 3) is the cap
        // N.H > 1 - epsilon around the sphere's front; a translation along du moves it towards +du.
        const TriMesh mesh = sphere();
        RenderLook look = plainLook(Style::Toon);
        RenderCache cache;
        RenderPasses plain;
        renderFrame(mesh.vertices, mesh, frontCamera(), look, cache, plain);
        QVERIFY(std::all_of(plain.highlights.begin(), plain.highlights.end(), [](float v) { return v == 0.f; }));

        RenderHighlight h;
        const Positions normals = vertexNormals(mesh.vertices, mesh.faces);
        QVERIFY(guideVertexFrames(mesh.vertices, mesh.faces, normals, {}, Eigen::Vector3f(1, 0, 0), 3, h.du, h.dv));
        h.layer.color = Color(1.f, 0.f, 0.f);
        look.highlights = {h};
        RenderPasses lit;
        renderFrame(mesh.vertices, mesh, frontCamera(), look, cache, lit);
        const std::size_t centre = 100 * 200 + 100;
        QCOMPARE(lit.highlights[centre], 1.f);
        QCOMPARE(lit.beauty.at(100, 100)[0], 1.f);
        QCOMPARE(lit.beauty.at(100, 100)[1], 0.f);
        QCOMPARE(lit.highlights[0], 0.f);
        QVERIFY(lit.tone == plain.tone);
        auto centroidX = [](const RenderPasses& p, double& area) {
            double sum = 0;
            area = 0;
            for (int y = 0; y < 200; ++y)
                for (int x = 0; x < 200; ++x) {
                    const float c = p.highlights[std::size_t(y * 200 + x)];
                    area += c;
                    sum += c * (x + 0.5);
                }
            return sum / std::max(area, 1e-9);
        };
        double area = 0;
        QVERIFY(std::abs(centroidX(lit, area) - 100.0) < 1.0);
        // The cap N.H > 0.95 with V towards the eye at z = 6 (not at infinity): its edge angle by
        // bisection on the meridian, seen orthographically as a disc of radius sin(angle).
        auto nDotH = [](double t) {
            const Eigen::Vector3d p(std::sin(t), 0, std::cos(t));
            const Eigen::Vector3d halfway = (Eigen::Vector3d(0, 0, 1) + (Eigen::Vector3d(0, 0, 6) - p).normalized());
            return p.dot(halfway.normalized());
        };
        double lo = 0, hi = 1.5;
        for (int i = 0; i < 60; ++i)
            (nDotH(0.5 * (lo + hi)) > 0.95 ? lo : hi) = 0.5 * (lo + hi);
        const double radius = std::sin(lo) * 200 / 2.4;
        const double expected = M_PI * radius * radius;
        QVERIFY2(std::abs(area - expected) < 0.05 * expected, qPrintable(QString::number(area)));

        look.highlights[0].layer.shape.operations = {HighlightOperation::translation(0.2f, 0.f)};
        RenderPasses moved;
        renderFrame(mesh.vertices, mesh, frontCamera(), look, cache, moved);
        double movedArea = 0;
        QVERIFY(centroidX(moved, movedArea) > 110.0);
    }
};

QTEST_GUILESS_MAIN(TestRender)
#include "test_render.moc"
