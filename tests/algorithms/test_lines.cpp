// Feature lines on meshes whose answers are known by hand (a cube seen from a corner, an open
// box, a fin), counts on real meshes, stroke chaining and the hand-drawn style; the visible parts
// of strokes and the outlines of pixel regions the SVG lines write.
#include "test_support.h"

#include "celform/algorithms/lines.h"
#include "celform/algorithms/mesh_analysis.h"
#include "celform/algorithms/region_outline.h"
#include "celform/algorithms/stroke_refine.h"
#include "celform/algorithms/stroke_visibility.h"
#include "celform/model/io/mesh_io.h"

#include <algorithm>
#include <limits>
#include <map>
#include <set>
#include <utility>

using namespace celform::algo;

namespace {

using EdgeSet = std::set<std::pair<int, int>>;

/// Cube [-1, 1]^3; vertex i has x = bit 0, y = bit 1, z = bit 2 (set = +1). Quads are listed
/// counter-clockwise seen from outside in the order +x, -x, +y, -y, +z, -z and split along their
/// first-third diagonal. skipQuad drops one quad (an open box).
TriMesh cube(int skipQuad = -1)
{
    TriMesh m;
    m.vertices.resize(8, 3);
    for (int i = 0; i < 8; ++i)
        m.vertices.row(i) << ((i & 1) ? 1.f : -1.f), ((i & 2) ? 1.f : -1.f), ((i & 4) ? 1.f : -1.f);
    const int quads[6][4] = {{1, 3, 7, 5}, {0, 4, 6, 2}, {2, 6, 7, 3}, {0, 1, 5, 4}, {4, 5, 7, 6}, {0, 2, 3, 1}};
    std::vector<std::array<int, 3>> tris;
    for (int q = 0; q < 6; ++q) {
        if (q == skipQuad)
            continue;
        tris.push_back({quads[q][0], quads[q][1], quads[q][2]});
        tris.push_back({quads[q][0], quads[q][2], quads[q][3]});
    }
    m.faces.resize(Eigen::Index(tris.size()), 3);
    for (std::size_t f = 0; f < tris.size(); ++f)
        m.faces.row(Eigen::Index(f)) << tris[f][0], tris[f][1], tris[f][2];
    return m;
}

/// The 12 cube edges: vertex indices differing in exactly one bit.
bool isCubeEdge(int a, int b)
{
    const int x = a ^ b;
    return x == 1 || x == 2 || x == 4;
}

EdgeSet edgesWith(const EdgeTopology& t, const FeatureEdges& fe, std::uint8_t bits)
{
    EdgeSet s;
    for (std::size_t i = 0; i < fe.edges.size(); ++i)
        if (fe.kinds[i] & bits)
            s.insert({t.edges(fe.edges[i], 0), t.edges(fe.edges[i], 1)});
    return s;
}

LineSettings only(std::uint8_t bits)
{
    LineSettings s;
    s.silhouettes = bits & kSilhouette;
    s.creases = bits & kCrease;
    s.borders = bits & kBorder;
    s.materialBoundaries = bits & kMaterialBoundary;
    return s;
}

LineView orthographic(const Eigen::Vector3f& direction)
{
    LineView v;
    v.orthographic = true;
    v.direction = direction.normalized();
    return v;
}

/// Looking along (-1, -2, -3): +x, +y, +z face the viewer, the outline is the hexagon of the six
/// corners other than (1, 1, 1) = 7 and (-1, -1, -1) = 0.
EdgeSet cubeHexagon()
{
    EdgeSet s;
    for (int a = 0; a < 8; ++a)
        for (int b = a + 1; b < 8; ++b)
            if (isCubeEdge(a, b) && a != 0 && b != 7)
                s.insert({a, b});
    return s;
}

/// Reference adjacency by a std::map, to check the bucketed build edge by edge.
std::map<std::pair<int, int>, std::vector<int>> referenceAdjacency(const Faces& faces)
{
    std::map<std::pair<int, int>, std::vector<int>> ref;
    for (int f = 0; f < faces.rows(); ++f) {
        const int t[3] = {faces(f, 0), faces(f, 1), faces(f, 2)};
        if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
            continue;
        for (int k = 0; k < 3; ++k)
            ref[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}].push_back(f);
    }
    return ref;
}

TriMesh load(const QString& path)
{
    return celform::model::importMesh(path).mesh;
}

/// A small screen projection: orthographic-like, 50 px per unit, rotated by `angle` about y.
std::vector<Eigen::Vector3f> project(const Positions& p, float angle, float depthOffset = 10.f)
{
    const Eigen::Matrix3f r = Eigen::AngleAxisf(angle, Eigen::Vector3f::UnitY()).toRotationMatrix();
    std::vector<Eigen::Vector3f> out(std::size_t(p.rows()));
    for (Eigen::Index v = 0; v < p.rows(); ++v) {
        const Eigen::Vector3f q = r * Eigen::Vector3f(p.row(v));
        out[std::size_t(v)] = Eigen::Vector3f(200.f + 50.f * q.x(), 200.f - 50.f * q.y(), depthOffset - q.z());
    }
    return out;
}

/// A fold along the x axis, `angles.size()` unit segments long: a flat flank (z = 0, y >= 0) and,
/// per segment, a flank of its own turned by angles[i] degrees about the axis, so the spine edge
/// of segment i has a dihedral angle of exactly angles[i]. The turned flanks do not share
/// vertices (their side edges are borders), so only the spine can be a crease.
TriMesh fold(const std::vector<float>& angles)
{
    const int n = int(angles.size());
    TriMesh m;
    m.vertices.resize(2 * (n + 1) + 2 * n, 3);
    for (int i = 0; i <= n; ++i) {
        m.vertices.row(i) << float(i), 0.f, 0.f; // spine
        m.vertices.row(n + 1 + i) << float(i), 1.f, 0.f; // flat flank
    }
    std::vector<std::array<int, 3>> tris;
    for (int i = 0; i < n; ++i) {
        const float phi = angles[std::size_t(i)] * float(M_PI / 180.0);
        const int b0 = 2 * (n + 1) + 2 * i, b1 = b0 + 1, a0 = n + 1 + i, a1 = a0 + 1;
        m.vertices.row(b0) << float(i), -std::cos(phi), std::sin(phi);
        m.vertices.row(b1) << float(i + 1), -std::cos(phi), std::sin(phi);
        tris.push_back({i, i + 1, a1});
        tris.push_back({i, a1, a0});
        tris.push_back({i + 1, i, b0});
        tris.push_back({i + 1, b0, b1});
    }
    m.faces.resize(Eigen::Index(tris.size()), 3);
    for (std::size_t f = 0; f < tris.size(); ++f)
        m.faces.row(Eigen::Index(f)) << tris[f][0], tris[f][1], tris[f][2];
    return m;
}

/// A straight styled stroke from a to b in `points` points, width 2, depth 10.
StyledStroke straight(const Eigen::Vector2f& a, const Eigen::Vector2f& b, int points = 5, std::uint8_t kinds = kCrease)
{
    StyledStroke s;
    s.kinds = kinds;
    for (int k = 0; k < points; ++k) {
        const float t = float(k) / float(points - 1);
        s.points.push_back((1.f - t) * a + t * b);
        s.depths.push_back(10.f);
        s.widths.push_back(2.f);
    }
    return s;
}

} // namespace

class TestLines : public QObject {
    Q_OBJECT
private slots:
    void cubeTopology()
    {
        const TriMesh m = cube();
        const EdgeTopology t = buildEdgeTopology(m.faces, 8);
        QCOMPARE(t.edges.rows(), 18); // 12 cube edges + 6 diagonals
        QCOMPARE(t.borderEdges, 0);
        QCOMPARE(t.nonManifoldEdges, 0);
        for (Eigen::Index e = 0; e < t.edges.rows(); ++e) {
            QVERIFY(t.edges(e, 0) < t.edges(e, 1));
            QVERIFY(t.faces(e, 0) < t.faces(e, 1)); // face order
            // Both faces really contain the edge.
            for (int k = 0; k < 2; ++k) {
                const auto f = m.faces.row(t.faces(e, k));
                QVERIFY((f.array() == t.edges(e, 0)).any() && (f.array() == t.edges(e, 1)).any());
            }
        }
        // Outward orientation of the test cube itself.
        for (Eigen::Index f = 0; f < m.faces.rows(); ++f) {
            const Eigen::Vector3f a = m.vertices.row(m.faces(f, 0)), b = m.vertices.row(m.faces(f, 1)),
                                  c = m.vertices.row(m.faces(f, 2));
            QVERIFY((b - a).cross(c - a).dot(a + b + c) > 0);
        }
    }

    void cubeSilhouetteFromCorner()
    {
        const TriMesh m = cube();
        const EdgeTopology t = buildEdgeTopology(m.faces, 8);
        FeatureEdges fe;
        extractFeatureEdges(m.vertices, m.faces, t, {}, orthographic({-1, -2, -3}), only(kSilhouette), fe);
        QCOMPARE(edgesWith(t, fe, kSilhouette), cubeHexagon());
        QCOMPARE(fe.edges.size(), std::size_t(6));
        // Looking the other way round gives the same outline.
        extractFeatureEdges(m.vertices, m.faces, t, {}, orthographic({1, 2, 3}), only(kSilhouette), fe);
        QCOMPARE(edgesWith(t, fe, kSilhouette), cubeHexagon());
    }

    void cubeCreases()
    {
        const TriMesh m = cube();
        const EdgeTopology t = buildEdgeTopology(m.faces, 8);
        FeatureEdges fe;
        extractFeatureEdges(m.vertices, m.faces, t, {}, orthographic({-1, -2, -3}), only(kCrease), fe);
        const EdgeSet creases = edgesWith(t, fe, kCrease);
        QCOMPARE(creases.size(), std::size_t(12));
        for (const auto& [a, b] : creases)
            QVERIFY(isCubeEdge(a, b)); // no face diagonal
        // Flags combine: all settings on, the hexagon is silhouette and crease at once.
        extractFeatureEdges(m.vertices, m.faces, t, {}, orthographic({-1, -2, -3}), LineSettings{}, fe);
        QCOMPARE(fe.edges.size(), std::size_t(12));
        QCOMPARE(edgesWith(t, fe, kSilhouette), cubeHexagon());
        for (std::size_t i = 0; i < fe.edges.size(); ++i) {
            const std::pair<int, int> e{t.edges(fe.edges[i], 0), t.edges(fe.edges[i], 1)};
            const std::uint8_t expected = cubeHexagon().count(e) ? (kSilhouette | kCrease) : kCrease;
            QCOMPARE(int(fe.kinds[i]), int(expected));
        }
        // Just above 90 degrees nothing is a crease.
        LineSettings wide = only(kCrease);
        wide.creaseAngleDegrees = 91.f;
        extractFeatureEdges(m.vertices, m.faces, t, {}, orthographic({-1, -2, -3}), wide, fe);
        QVERIFY(fe.edges.empty());
    }

    void perspectiveEyeCloseToFace()
    {
        // Orthographically along -z the side faces would be edge-on; with per-triangle view vectors
        // (paper 3, section 4.2.2) an eye just in front of +z sees the sides from behind.
        const TriMesh m = cube();
        const EdgeTopology t = buildEdgeTopology(m.faces, 8);
        LineView view;
        view.eye = Eigen::Vector3f(0.2f, -0.1f, 1.5f);
        FeatureEdges fe;
        extractFeatureEdges(m.vertices, m.faces, t, {}, view, only(kSilhouette), fe);
        QCOMPARE(edgesWith(t, fe, kSilhouette), (EdgeSet{{4, 5}, {5, 7}, {6, 7}, {4, 6}}));
        // Far away on the corner diagonal the perspective outline is the hexagon again.
        view.eye = Eigen::Vector3f(10.f, 20.f, 30.f);
        extractFeatureEdges(m.vertices, m.faces, t, {}, view, only(kSilhouette), fe);
        QCOMPARE(edgesWith(t, fe, kSilhouette), cubeHexagon());
    }

    void openBoxBorders()
    {
        const TriMesh m = cube(4); // without +z
        const EdgeTopology t = buildEdgeTopology(m.faces, 8);
        QCOMPARE(t.borderEdges, 4);
        QCOMPARE(t.edges.rows(), 17); // the +z diagonal is gone, its rim edges stay
        FeatureEdges fe;
        extractFeatureEdges(m.vertices, m.faces, t, {}, orthographic({-1, -2, -3}), only(kBorder), fe);
        const EdgeSet rim{{4, 5}, {5, 7}, {6, 7}, {4, 6}};
        QCOMPARE(edgesWith(t, fe, kBorder), rim);
        for (const std::int32_t e : fe.edges)
            QCOMPARE(t.faces(e, 1), -1);
        // The rim closes into one outline loop.
        const std::vector<Stroke> strokes = chainStrokes(t, fe);
        QCOMPARE(strokes.size(), std::size_t(1));
        QVERIFY(strokes[0].closed);
        QCOMPARE(strokes[0].vertices.size(), std::size_t(4));
        QCOMPARE(int(strokes[0].kinds), int(kBorder));
    }

    void materialBoundaries()
    {
        const TriMesh m = cube();
        const EdgeTopology t = buildEdgeTopology(m.faces, 8);
        std::vector<std::int32_t> materials(12, 0);
        materials[8] = materials[9] = 1; // the +z quad
        FeatureEdges fe;
        extractFeatureEdges(m.vertices, m.faces, t, materials, orthographic({-1, -2, -3}), only(kMaterialBoundary), fe);
        QCOMPARE(edgesWith(t, fe, kMaterialBoundary), (EdgeSet{{4, 5}, {5, 7}, {6, 7}, {4, 6}}));
        QCOMPARE(fe.edges.size(), std::size_t(4));
        // No materials: no boundaries, even when asked for.
        extractFeatureEdges(m.vertices, m.faces, t, {}, orthographic({-1, -2, -3}), only(kMaterialBoundary), fe);
        QVERIFY(fe.edges.empty());
    }

    void nonManifoldAndDegenerate()
    {
        // Three triangles on edge (0, 1), and a degenerate face that must add no edge.
        Positions p(5, 3);
        p << 0, 0, 0, 1, 0, 0, 0.5f, 1, 0, 0.5f, -1, 0, 0.5f, 0, 1;
        Faces f(4, 3);
        f << 0, 1, 2, 1, 0, 3, 0, 1, 4, 2, 2, 3;
        const EdgeTopology t = buildEdgeTopology(f, 5);
        QCOMPARE(t.edges.rows(), 7);
        QCOMPARE(t.nonManifoldEdges, 1);
        QCOMPARE(t.borderEdges, 6);
        QCOMPARE(t.edges(0, 0), 0);
        QCOMPARE(t.edges(0, 1), 1);
        QCOMPARE(int(t.nonManifold[0]), 1);
        QCOMPARE(t.faces(0, 0), 0); // the first two faces, in face order
        QCOMPARE(t.faces(0, 1), 1);
        FeatureEdges fe;
        extractFeatureEdges(p, f, t, {}, orthographic({0, 0, -1}), only(kCrease), fe);
        QCOMPARE(fe.edges, std::vector<std::int32_t>{0});
        QCOMPARE(int(fe.kinds[0]), int(kCrease));
        extractFeatureEdges(p, f, t, {}, orthographic({0, 0, -1}), only(kSilhouette), fe);
        QVERIFY(fe.edges.empty());
    }

    void realMeshTopology_data()
    {
        QTest::addColumn<QString>("file");
        QTest::newRow("npm bunny") << QStringLiteral("meshes/npm_bunny.off");
        QTest::newRow("cgal bunny") << QStringLiteral("meshes/cgal_bunny00.off");
        QTest::newRow("elephant") << QStringLiteral("meshes/cgal_elephant.off");
        QTest::newRow("refined elephant") << QStringLiteral("meshes/cgal_refined_elephant.off");
    }
    void realMeshTopology()
    {
        QFETCH(QString, file);
        CELFORM_REQUIRE_SHARED(path, file);
        const TriMesh m = load(path);
        const EdgeTopology t = buildEdgeTopology(m.faces, std::int32_t(m.vertexCount()));
        QCOMPARE(t.borderEdges, 0);
        QCOMPARE(t.nonManifoldEdges, 0);
        QCOMPARE(2 * t.edges.rows(), 3 * m.faceCount()); // closed manifold: E = 3F/2
        const TopologyReport report = analyseTopology(m);
        QCOMPARE(t.borderEdges, report.boundaryEdges);
        QCOMPARE(t.nonManifoldEdges, report.nonManifoldEdges);
        // Edge by edge against a std::map reference, in the same (v0, v1) order.
        const auto ref = referenceAdjacency(m.faces);
        QCOMPARE(std::size_t(t.edges.rows()), ref.size());
        Eigen::Index e = 0;
        for (const auto& [key, faces] : ref) {
            QCOMPARE(t.edges(e, 0), key.first);
            QCOMPARE(t.edges(e, 1), key.second);
            QCOMPARE(t.faces(e, 0), faces[0]);
            QCOMPARE(t.faces(e, 1), faces.size() > 1 ? faces[1] : -1);
            ++e;
        }
    }

    void fandiskCreases()
    {
        CELFORM_REQUIRE_SHARED(path, QStringLiteral("meshes/cgal_fandisk.off"));
        const TriMesh m = load(path);
        const EdgeTopology t = buildEdgeTopology(m.faces, std::int32_t(m.vertexCount()));
        LineSettings s = only(kCrease);
        FeatureEdges at45, at20;
        extractFeatureEdges(m.vertices, m.faces, t, {}, orthographic({0, 0, -1}), s, at45);
        s.creaseAngleDegrees = 20.f;
        extractFeatureEdges(m.vertices, m.faces, t, {}, orthographic({0, 0, -1}), s, at20);
        qInfo("fandisk: %lld edges, %zu creases at 45 degrees, %zu at 20 degrees", qlonglong(t.edges.rows()),
            at45.edges.size(), at20.edges.size());
        QVERIFY(at20.edges.size() > at45.edges.size());
        QVERIFY(at45.edges.size() >= 300 && at45.edges.size() <= 1200);
        QVERIFY(at20.edges.size() >= 400 && at20.edges.size() <= 2000);
        for (const std::int32_t e : at20.edges)
            QVERIFY(t.faces(e, 1) >= 0 && !t.nonManifold[std::size_t(e)]);
        // Every 45-degree crease is a 20-degree crease.
        QVERIFY(std::includes(at20.edges.begin(), at20.edges.end(), at45.edges.begin(), at45.edges.end()));
    }

    void cubeCreasesSurviveHysteresis()
    {
        const TriMesh m = cube();
        const EdgeTopology t = buildEdgeTopology(m.faces, 8);
        LineSettings s = only(kCrease);
        s.creaseAngleDegrees = 45.f;
        s.creaseLowAngleDegrees = 30.f;
        FeatureEdges fe;
        extractFeatureEdges(m.vertices, m.faces, t, {}, orthographic({-1, -2, -3}), s, fe);
        const EdgeSet creases = edgesWith(t, fe, kCrease);
        QCOMPARE(creases.size(), std::size_t(12));
        for (const auto& [a, b] : creases)
            QVERIFY(isCubeEdge(a, b));
        for (const std::uint8_t k : fe.kinds)
            QCOMPARE(int(k), int(kCrease)); // the internal weak mark never leaks out
        // Without a seed above the high angle, hysteresis adds nothing.
        s.creaseAngleDegrees = 100.f;
        s.creaseLowAngleDegrees = 30.f;
        extractFeatureEdges(m.vertices, m.faces, t, {}, orthographic({-1, -2, -3}), s, fe);
        QVERIFY(fe.edges.empty());
    }

    void noisyCreaseChainDoesNotBreak()
    {
        // Ten spine edges at 50 degrees, one of them at 42: just under the 45-degree crease angle.
        std::vector<float> angles(10, 50.f);
        angles[4] = 42.f;
        const TriMesh m = fold(angles);
        const EdgeTopology t = buildEdgeTopology(m.faces, std::int32_t(m.vertexCount()));
        LineSettings s = only(kCrease);
        FeatureEdges fe;
        s.creaseLowAngleDegrees = s.creaseAngleDegrees; // no hysteresis: the chain breaks in two
        extractFeatureEdges(m.vertices, m.faces, t, {}, orthographic({0, -1, -1}), s, fe);
        QCOMPARE(fe.edges.size(), std::size_t(9));
        QCOMPARE(chainStrokes(t, fe).size(), std::size_t(2));
        s.creaseLowAngleDegrees = 30.f; // hysteresis: one stroke of ten edges along the spine
        extractFeatureEdges(m.vertices, m.faces, t, {}, orthographic({0, -1, -1}), s, fe);
        QCOMPARE(fe.edges.size(), std::size_t(10));
        const std::vector<Stroke> strokes = chainStrokes(t, fe);
        QCOMPARE(strokes.size(), std::size_t(1));
        QCOMPARE(strokes[0].vertices.size(), std::size_t(11));
        // A weak edge that reaches no crease is no crease: all at 42 degrees, nothing.
        const TriMesh weak = fold(std::vector<float>(10, 42.f));
        extractFeatureEdges(weak.vertices, weak.faces, buildEdgeTopology(weak.faces, std::int32_t(weak.vertexCount())),
            {}, orthographic({0, -1, -1}), s, fe);
        QVERIFY(fe.edges.empty());
    }

    void gapsJoinedUpToTheirWidth()
    {
        // 1.5 px apart: one stroke; 3 px apart: two (the gap is 2 px).
        std::vector<StyledStroke> near{straight({0, 0}, {20, 0}), straight({21.5f, 0}, {40, 0})};
        joinStrokeGaps(near, 2.f);
        QCOMPARE(near.size(), std::size_t(1));
        QCOMPARE(near[0].points.front(), Eigen::Vector2f(0, 0));
        QCOMPARE(near[0].points.back(), Eigen::Vector2f(40, 0));
        QCOMPARE(near[0].points.size(), near[0].widths.size());
        QCOMPARE(near[0].points.size(), near[0].depths.size());
        std::vector<StyledStroke> far{straight({0, 0}, {20, 0}), straight({23.f, 0}, {40, 0})};
        joinStrokeGaps(far, 2.f);
        QCOMPARE(far.size(), std::size_t(2));
        // Reversed pieces are joined end to end too, and outlines never join inner lines.
        std::vector<StyledStroke> reversed{straight({0, 0}, {20, 0}), straight({40, 0}, {21.f, 0})};
        joinStrokeGaps(reversed, 2.f);
        QCOMPARE(reversed.size(), std::size_t(1));
        QCOMPARE(strokeLength(reversed[0]), 40.f);
        std::vector<StyledStroke> classes{straight({0, 0}, {20, 0}), straight({21.f, 0}, {40, 0}, 5, kSilhouette)};
        joinStrokeGaps(classes, 2.f);
        QCOMPARE(classes.size(), std::size_t(2));
    }

    void shortStrokesDropped()
    {
        std::vector<StyledStroke> strokes{straight({0, 0}, {5, 0}), straight({0, 10}, {30, 10})};
        dropShortStrokes(strokes, 10.f);
        QCOMPARE(strokes.size(), std::size_t(1));
        QCOMPARE(strokeLength(strokes[0]), 30.f);
        // refineStrokes: minLength is a fraction of the image height (10 px of 1000).
        std::vector<StyledStroke> again{straight({0, 0}, {5, 0}), straight({0, 10}, {30, 10})};
        LineStyle style;
        style.minLength = 0.01f;
        refineStrokes(again, style, 1000);
        QCOMPARE(again.size(), std::size_t(1));
    }

    void taperNarrowsTheEnds()
    {
        std::vector<StyledStroke> strokes{straight({0, 0}, {100, 0}, 21)};
        taperStrokes(strokes, 12.f);
        const StyledStroke& s = strokes[0];
        QCOMPARE(s.widths.front(), 2.f * kTaperTip);
        QCOMPARE(s.widths.back(), 2.f * kTaperTip);
        QCOMPARE(s.widths[10], 2.f); // the middle keeps its width
        QVERIFY(s.widths[1] > s.widths[0] && s.widths[2] > s.widths[1]);
        // Closed strokes have no ends.
        StyledStroke ring = straight({0, 0}, {10, 0}, 3);
        ring.closed = true;
        std::vector<StyledStroke> rings{ring};
        taperStrokes(rings, 12.f);
        QCOMPARE(rings[0].widths, ring.widths);
    }

    void reductionThinsFarLines()
    {
        StyledStroke nearStroke = straight({0, 0}, {20, 0});
        StyledStroke farStroke = straight({0, 10}, {20, 10});
        std::fill(farStroke.depths.begin(), farStroke.depths.end(), 30.f);
        std::vector<StyledStroke> strokes{nearStroke, farStroke};
        reduceWidthWithDepth(strokes, 0.5f);
        QCOMPARE(strokes[0].widths.front(), 2.f);
        QCOMPARE(strokes[1].widths.front(), 1.f);
    }

    void smoothingKeepsEndsAndCorners()
    {
        // A gentle arc gets rounder; a right angle stays a corner; ends stay put.
        StyledStroke arc;
        arc.kinds = kCrease;
        for (int k = 0; k <= 8; ++k) {
            const float a = float(k) * 0.1f;
            arc.points.emplace_back(100.f * std::cos(a), 100.f * std::sin(a));
            arc.depths.push_back(10.f);
            arc.widths.push_back(2.f);
        }
        StyledStroke corner = straight({0, 0}, {20, 0}, 3);
        corner.points.emplace_back(20.f, 20.f);
        corner.depths.push_back(10.f);
        corner.widths.push_back(2.f);
        std::vector<StyledStroke> strokes{arc, corner};
        smoothStrokes(strokes, 2);
        QCOMPARE(strokes[0].points.front(), arc.points.front());
        QCOMPARE(strokes[0].points.back(), arc.points.back());
        QVERIFY(strokes[0].points.size() > arc.points.size());
        QVERIFY(std::count(strokes[1].points.begin(), strokes[1].points.end(), Eigen::Vector2f(20, 0)) == 1);
        QCOMPARE(strokes[1].points.size(), strokes[1].widths.size());
    }

    void chainCubeHexagon()
    {
        const TriMesh m = cube();
        const EdgeTopology t = buildEdgeTopology(m.faces, 8);
        FeatureEdges fe;
        extractFeatureEdges(m.vertices, m.faces, t, {}, orthographic({-1, -2, -3}), only(kSilhouette), fe);
        const std::vector<Stroke> strokes = chainStrokes(t, fe);
        QCOMPARE(strokes.size(), std::size_t(1));
        const Stroke& s = strokes[0];
        QVERIFY(s.closed);
        QCOMPARE(s.vertices.size(), std::size_t(6));
        QCOMPARE(int(s.kinds), int(kSilhouette));
        EdgeSet walked;
        for (std::size_t i = 0; i < 6; ++i) {
            const int a = s.vertices[i], b = s.vertices[(i + 1) % 6];
            walked.insert({std::min(a, b), std::max(a, b)});
        }
        QCOMPARE(walked, cubeHexagon());

        // All lines on: the hexagon (silhouette + crease) stays one outline loop; the six creases
        // into corners 0 and 7 meet at those junctions and become six one-edge inner strokes.
        extractFeatureEdges(m.vertices, m.faces, t, {}, orthographic({-1, -2, -3}), LineSettings{}, fe);
        const std::vector<Stroke> all = chainStrokes(t, fe);
        QCOMPARE(all.size(), std::size_t(7));
        int closedOutlines = 0, innerSegments = 0;
        for (const Stroke& st : all) {
            if (st.closed && st.vertices.size() == 6 && st.kinds == (kSilhouette | kCrease))
                ++closedOutlines;
            if (!st.closed && st.vertices.size() == 2 && st.kinds == kCrease)
                ++innerSegments;
        }
        QCOMPARE(closedOutlines, 1);
        QCOMPARE(innerSegments, 6);
        // Deterministic.
        const std::vector<Stroke> again = chainStrokes(t, fe);
        for (std::size_t i = 0; i < all.size(); ++i)
            QCOMPARE(again[i].vertices, all[i].vertices);
    }

    void chainOpenPolylineAndJunction()
    {
        // A path 0-1-2-3 and a branch 2-4: vertex 2 is a junction (degree 3).
        EdgeTopology t;
        t.edges.resize(4, 2);
        t.edges << 0, 1, 1, 2, 2, 3, 2, 4;
        t.faces.setConstant(4, 2, -1);
        t.nonManifold.assign(4, 0);
        FeatureEdges fe{{0, 1, 2, 3}, {kCrease, kMaterialBoundary, kCrease, kCrease}};
        std::vector<Stroke> s = chainStrokes(t, fe);
        QCOMPARE(s.size(), std::size_t(3));
        QCOMPARE(s[0].vertices, (std::vector<std::int32_t>{0, 1, 2}));
        QCOMPARE(int(s[0].kinds), int(kCrease | kMaterialBoundary));
        QVERIFY(!s[0].closed);
        QCOMPARE(s[1].vertices, (std::vector<std::int32_t>{2, 3}));
        QCOMPARE(s[2].vertices, (std::vector<std::int32_t>{2, 4}));
        // Make 2-4 an outline: classes do not join, so 0-1-2-3 is now one inner stroke.
        fe.kinds[3] = kSilhouette;
        s = chainStrokes(t, fe);
        QCOMPARE(s.size(), std::size_t(2));
        QCOMPARE(s[0].vertices, (std::vector<std::int32_t>{0, 1, 2, 3}));
        QCOMPARE(s[1].vertices, (std::vector<std::int32_t>{2, 4}));
        QCOMPARE(int(s[1].kinds), int(kSilhouette));
    }

    void styleWithoutEffectsIsExact()
    {
        const TriMesh m = cube();
        const EdgeTopology t = buildEdgeTopology(m.faces, 8);
        FeatureEdges fe;
        extractFeatureEdges(m.vertices, m.faces, t, {}, orthographic({-1, -2, -3}), LineSettings{}, fe);
        const std::vector<Stroke> strokes = chainStrokes(t, fe);
        const std::vector<Eigen::Vector3f> proj = project(m.vertices, 0.3f);
        LineStyle style;
        const std::vector<StyledStroke> styled = styleProjectedStrokes(strokes, proj, style);
        QCOMPARE(styled.size(), strokes.size());
        for (std::size_t i = 0; i < styled.size(); ++i) {
            const Stroke& s = strokes[i];
            const StyledStroke& st = styled[i];
            const std::size_t n = s.vertices.size() + (s.closed ? 1 : 0); // closed: first point repeated
            QCOMPARE(st.points.size(), n);
            QCOMPARE(st.depths.size(), n);
            QCOMPARE(st.widths.size(), n);
            const float width = (s.kinds & (kSilhouette | kBorder)) ? style.outlineWidth : style.innerWidth;
            for (std::size_t k = 0; k < n; ++k) {
                const Eigen::Vector3f& p = proj[std::size_t(s.vertices[k % s.vertices.size()])];
                QCOMPARE(st.points[k], Eigen::Vector2f(p.head<2>()));
                QCOMPARE(st.depths[k], p.z());
                QCOMPARE(st.widths[k], width);
            }
        }
        // The template projects through the callback the same way.
        const auto viaTemplate = styleStrokes(
            strokes, m.vertices, style, [](const Eigen::Vector3f& p) { return Eigen::Vector3f(p.x(), p.y(), 5.f); });
        QCOMPARE(viaTemplate[0].points[0], Eigen::Vector2f(m.vertices.row(strokes[0].vertices[0]).head<2>()));
    }

    void jitterIsDeterministicAndAnchored()
    {
        const TriMesh m = cube();
        const EdgeTopology t = buildEdgeTopology(m.faces, 8);
        FeatureEdges fe;
        extractFeatureEdges(m.vertices, m.faces, t, {}, orthographic({-1, -2, -3}), LineSettings{}, fe);
        const std::vector<Stroke> strokes = chainStrokes(t, fe);
        LineStyle style;
        style.jitter = 2.f;
        style.widthVariation = 0.4f;
        style.seed = 7;
        const auto projA = project(m.vertices, 0.30f), projB = project(m.vertices, 0.32f);
        const auto a = styleProjectedStrokes(strokes, projA, style);
        const auto a2 = styleProjectedStrokes(strokes, projA, style);
        const auto b = styleProjectedStrokes(strokes, projB, style);
        QCOMPARE(a.size(), strokes.size());
        int moved = 0;
        for (std::size_t i = 0; i < a.size(); ++i) {
            QCOMPARE(a2[i].points, a[i].points);
            QCOMPARE(a2[i].widths, a[i].widths);
            for (std::size_t k = 0; k < strokes[i].vertices.size(); ++k) {
                const auto v = std::size_t(strokes[i].vertices[k]);
                const float offA = (a[i].points[k] - projA[v].head<2>()).norm();
                const float offB = (b[i].points[k] - projB[v].head<2>()).norm();
                QVERIFY(offA <= style.jitter + 1e-4f);
                QVERIFY(std::abs(offA - offB) < 1e-3f); // anchored to the vertex, not the screen
                QVERIFY((a[i].points[k] - b[i].points[k]).norm() < 5.f); // a small camera move, a small change
                moved += offA > 0.05f ? 1 : 0;
                const float base = (strokes[i].kinds & (kSilhouette | kBorder)) ? style.outlineWidth : style.innerWidth;
                QVERIFY(a[i].widths[k] >= base * (1.f - style.widthVariation) - 1e-5f);
                QVERIFY(a[i].widths[k] <= base * (1.f + style.widthVariation) + 1e-5f);
                QCOMPARE(a[i].widths[k], b[i].widths[k]); // widths depend on vertices only
            }
        }
        QVERIFY(moved > 6);
        // Another seed, another look.
        style.seed = 8;
        const auto c = styleProjectedStrokes(strokes, projA, style);
        QVERIFY(c[0].points != a[0].points);
    }

    void overshootExtendsOpenStrokes()
    {
        // A straight open stroke along x and the cube's closed hexagon.
        const std::vector<Eigen::Vector3f> proj{{10, 10, 1}, {20, 10, 1}, {30, 10, 1}, {30, 20, 1}};
        std::vector<Stroke> strokes(2);
        strokes[0].vertices = {0, 1, 2};
        strokes[0].kinds = kCrease;
        strokes[1].vertices = {0, 1, 2, 3};
        strokes[1].kinds = kSilhouette;
        strokes[1].closed = true;
        LineStyle style;
        style.overshoot = 4.f;
        const auto styled = styleProjectedStrokes(strokes, proj, style);
        QCOMPARE(styled.size(), std::size_t(2));
        const StyledStroke& open = styled[0];
        QCOMPARE(open.points.size(), std::size_t(5));
        QVERIFY(open.points.front().isApprox(Eigen::Vector2f(6, 10)));
        QVERIFY(open.points.back().isApprox(Eigen::Vector2f(34, 10)));
        QCOMPARE((open.points[1] - open.points[0]).norm(), 4.f);
        QCOMPARE(open.widths.front(), style.innerWidth * 0.6f);
        QCOMPARE(open.widths.back(), style.innerWidth * 0.6f);
        QCOMPARE(open.widths[2], style.innerWidth);
        // Closed strokes have no ends to extend.
        QCOMPARE(styled[1].points.size(), std::size_t(5));
        QCOMPARE(styled[1].points.front(), styled[1].points.back());
    }

    void behindCameraSplits()
    {
        std::vector<Eigen::Vector3f> proj{{0, 0, 1}, {1, 0, 1}, {2, 0, -1}, {3, 0, 1}, {4, 0, 1}, {5, 0, 0}};
        std::vector<Stroke> strokes(2);
        strokes[0].vertices = {0, 1, 2, 3, 4};
        strokes[1].vertices = {3, 4, 5, 0, 1}; // closed; hidden point 5 opens it
        strokes[1].closed = true;
        const auto styled = styleProjectedStrokes(strokes, proj, LineStyle{});
        QCOMPARE(styled.size(), std::size_t(3));
        QCOMPARE(styled[0].points.size(), std::size_t(2));
        QCOMPARE(styled[0].points[1], Eigen::Vector2f(1, 0));
        QCOMPARE(styled[1].points.size(), std::size_t(2));
        QCOMPARE(styled[1].points[0], Eigen::Vector2f(3, 0));
        // The closed stroke becomes one open run 0-1-3-4 across its seam.
        QCOMPARE(styled[2].points.size(), std::size_t(4));
        QCOMPARE(styled[2].points[0], Eigen::Vector2f(0, 0));
        QCOMPARE(styled[2].points[3], Eigen::Vector2f(4, 0));
    }

    // A stroke across a depth buffer whose middle columns are a surface in front of it: two
    // visible runs, cut half way between the samples on either side of each edge, keeping their
    // widths; a stroke in front stays whole, and one closed over the image stays closed.
    void visiblePartsCutAtTheSurface()
    {
        const int w = 20, h = 5;
        std::vector<float> depth(std::size_t(w * h), std::numeric_limits<float>::infinity());
        std::vector<std::int32_t> id(depth.size(), -1);
        for (int y = 0; y < h; ++y)
            for (int x = 8; x < 12; ++x) {
                depth[std::size_t(y * w + x)] = 1.f;
                id[std::size_t(y * w + x)] = 0;
            }
        StyledStroke behind;
        behind.points = {{1.f, 2.5f}, {19.f, 2.5f}};
        behind.depths = {2.f, 2.f};
        behind.widths = {1.f, 1.f};
        behind.kinds = kCrease;
        StyledStroke front = behind;
        front.depths = {0.5f, 0.5f};
        const auto parts = visibleStrokeParts({behind, front}, depth, id, w, h);
        QCOMPARE(parts.size(), std::size_t(3));
        QCOMPARE(parts[0].points.front().x(), 1.f);
        QVERIFY(std::abs(parts[0].points.back().x() - 7.75f) < 0.3f);
        QVERIFY(std::abs(parts[1].points.front().x() - 12.f) < 0.3f);
        QCOMPARE(parts[1].points.back().x(), 19.f);
        QCOMPARE(parts[0].kinds, std::uint8_t(kCrease));
        QCOMPARE(parts[2].points.size(), std::size_t(2));
        QCOMPARE(parts[2].widths[0], 1.f);
    }

    // Outlines along pixel edges: a square with a hole is an outer loop and a reversed inner one,
    // and two pixels touching at a corner are two loops.
    void regionOutlinesFollowPixelEdges()
    {
        const int w = 5, h = 5;
        std::vector<char> mask(std::size_t(w * h), 0);
        for (int y = 1; y < 4; ++y)
            for (int x = 1; x < 4; ++x)
                mask[std::size_t(y * w + x)] = !(x == 2 && y == 2);
        auto loops = traceRegionOutlines(mask, w, h);
        QCOMPARE(loops.size(), std::size_t(2));
        auto area = [](const std::vector<Eigen::Vector2i>& loop) {
            int twice = 0;
            for (std::size_t k = 0; k < loop.size(); ++k) {
                const Eigen::Vector2i a = loop[k], b = loop[(k + 1) % loop.size()];
                twice += a.x() * b.y() - b.x() * a.y();
            }
            return twice / 2;
        };
        QCOMPARE(loops[0].size(), std::size_t(4)); // corners only
        QCOMPARE(std::abs(area(loops[0])), 9);
        QCOMPARE(std::abs(area(loops[1])), 1);
        QVERIFY(area(loops[0]) * area(loops[1]) < 0); // the hole runs the other way
        std::vector<char> diagonal(std::size_t(w * h), 0);
        diagonal[std::size_t(1 * w + 1)] = diagonal[std::size_t(2 * w + 2)] = 1;
        loops = traceRegionOutlines(diagonal, w, h);
        QCOMPARE(loops.size(), std::size_t(2));
        QCOMPARE(loops[0].size(), std::size_t(4));
        QCOMPARE(loops[1].size(), std::size_t(4));
    }
};

QTEST_GUILESS_MAIN(TestLines)
#include "test_lines.moc"
