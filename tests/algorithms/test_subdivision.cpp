// Loop subdivision stencils: masks checked by hand on a tetrahedron and an open fan, positions
// against CGAL's Loop_subdivision to 1e-9, limit normals, partial updates and non-manifold input.
#include "test_meshes.h"
#include "test_support.h"

#include "celform/algorithms/subdivision.h"
#include "celform/model/io/mesh_io.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

using namespace celform::algo;
using celform::test::icosphere;
using celform::test::tetrahedronMesh;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// A flat disc: vertex 0 in the middle, n border vertices around it on the unit circle (z = 0).
TriMesh fan(int n, bool closed)
{
    TriMesh m;
    m.vertices.resize(n + 1, 3);
    m.vertices.row(0).setZero();
    const int spokes = closed ? n : n - 1;
    for (int i = 0; i < n; ++i) {
        const double a = (closed ? 2 * kPi : kPi) * i / spokes;
        m.vertices.row(i + 1) << float(std::cos(a)), float(std::sin(a)), 0.f;
    }
    m.faces.resize(spokes, 3);
    for (int i = 0; i < spokes; ++i)
        m.faces.row(i) << 0, i + 1, (i + 1) % n + 1;
    return m;
}

/// The weight of control vertex c in row r of a stencil (0 when absent).
double weight(const SparseRows& m, std::int32_t r, std::int32_t c)
{
    double w = 0;
    for (std::int32_t k = m.start[std::size_t(r)]; k < m.start[std::size_t(r) + 1]; ++k)
        if (m.cols[std::size_t(k)] == c)
            w += m.weights[std::size_t(k)];
    return w;
}

/// The edge point row of edge (a, b) at level 1: the row > V whose stencil reads a and b most.
std::int32_t edgeRow(const SubdivisionStencil& s, std::int32_t a, std::int32_t b)
{
    for (std::int32_t r = s.controlVertices; r < s.vertexCount(); ++r)
        if (weight(s.positions, r, a) >= 0.375 - 1e-12 && weight(s.positions, r, b) >= 0.375 - 1e-12)
            return r;
    for (std::int32_t r = s.controlVertices; r < s.vertexCount(); ++r)
        if (weight(s.positions, r, a) == 0.5 && weight(s.positions, r, b) == 0.5)
            return r;
    return -1;
}

/// Largest distance from each point of a to the nearest point of b (same counts), by sorting b on x.
double matchDistance(const Eigen::MatrixX3d& a, const Eigen::MatrixX3d& b)
{
    std::vector<Eigen::Index> order(std::size_t(b.rows()));
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](Eigen::Index x, Eigen::Index y) { return b(x, 0) < b(y, 0); });
    double worst = 0;
    for (Eigen::Index i = 0; i < a.rows(); ++i) {
        const auto lo = std::lower_bound(
            order.begin(), order.end(), a(i, 0) - 1e-7, [&](Eigen::Index j, double x) { return b(j, 0) < x; });
        double best = std::numeric_limits<double>::infinity();
        for (auto it = lo; it != order.end() && b(*it, 0) <= a(i, 0) + 1e-7; ++it)
            best = std::min(best, (a.row(i) - b.row(*it)).norm());
        worst = std::max(worst, best);
    }
    return worst;
}

void compareWithCgal(const TriMesh& mesh, int level)
{
    const Eigen::MatrixX3d control = mesh.vertices.cast<double>();
    Eigen::MatrixX3d reference;
    Faces referenceFaces;
    QVERIFY(cgalLoopSubdivision(control, mesh.faces, level, reference, referenceFaces));
    const SubdivisionStencil s = buildSubdivisionStencil(mesh.faces, std::int32_t(mesh.vertexCount()), level);
    Eigen::MatrixX3d mine;
    applySubdivision(s, control, mine);
    QCOMPARE(mine.rows(), reference.rows());
    QCOMPARE(s.faces.rows(), referenceFaces.rows());
    // CGAL keeps the control vertices first, as the stencil does.
    const double vertexPoints
        = (mine.topRows(control.rows()) - reference.topRows(control.rows())).cwiseAbs().maxCoeff();
    const double all = matchDistance(mine, reference);
    qInfo("level %d: %lld vertices, %lld faces; largest difference %.3g (vertex points %.3g)", level,
        qlonglong(mine.rows()), qlonglong(s.faces.rows()), all, vertexPoints);
    QVERIFY(vertexPoints <= 1e-9);
    QVERIFY(all <= 1e-9);
}

TriMesh noisy(TriMesh m, unsigned seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> d(-0.05f, 0.05f);
    for (Eigen::Index v = 0; v < m.vertices.rows(); ++v)
        for (int c = 0; c < 3; ++c)
            m.vertices(v, c) += d(rng);
    return m;
}

/// An icosphere with a cap of faces removed: an open mesh with one border loop.
TriMesh openSphere()
{
    TriMesh m = noisy(*icosphere(2), 3);
    std::vector<Eigen::Index> keep;
    for (Eigen::Index f = 0; f < m.faces.rows(); ++f) {
        const Eigen::Vector3f c
            = (m.vertices.row(m.faces(f, 0)) + m.vertices.row(m.faces(f, 1)) + m.vertices.row(m.faces(f, 2))) / 3;
        if (c.z() < 0.6f)
            keep.push_back(f);
    }
    Faces faces(Eigen::Index(keep.size()), 3);
    for (std::size_t i = 0; i < keep.size(); ++i)
        faces.row(Eigen::Index(i)) = m.faces.row(keep[i]);
    // Without the cap's vertices (CGAL takes no vertex without a face).
    std::vector<std::int32_t> index(std::size_t(m.vertexCount()), -1);
    Positions kept(m.vertexCount(), 3);
    std::int32_t count = 0;
    for (Eigen::Index f = 0; f < faces.rows(); ++f)
        for (int k = 0; k < 3; ++k) {
            auto& i = index[std::size_t(faces(f, k))];
            if (i < 0) {
                kept.row(count) = m.vertices.row(faces(f, k));
                i = count++;
            }
            faces(f, k) = i;
        }
    m.vertices = kept.topRows(count);
    m.faces = faces;
    return m;
}

} // namespace

class TestSubdivision : public QObject {
    Q_OBJECT
private slots:
    void tetrahedronMasksByHand()
    {
        const TriMesh m = tetrahedronMesh();
        const SubdivisionStencil s = buildSubdivisionStencil(m.faces, 4, 1);
        QCOMPARE(s.vertexCount(), 4 + 6);
        QCOMPARE(s.faceCount(), Eigen::Index(16));
        // Valence 3: Loop's beta = (5/8 - (3/8 + cos(120 deg) / 4)^2) / 3 = 3/16, itself 7/16.
        for (std::int32_t v = 0; v < 4; ++v)
            for (std::int32_t w = 0; w < 4; ++w)
                QVERIFY(std::abs(weight(s.positions, v, w) - (v == w ? 7.0 / 16 : 3.0 / 16)) < 1e-15);
        // Edge (0, 1): 3/8 of each end, 1/8 of the opposite vertices 2 and 3.
        const std::int32_t e = edgeRow(s, 0, 1);
        QVERIFY(e >= 4);
        QCOMPARE(weight(s.positions, e, 2), 0.125);
        QCOMPARE(weight(s.positions, e, 3), 0.125);
        QCOMPARE(s.creaseEdges, std::int64_t(0));
    }

    void openFanMasksByHand()
    {
        const TriMesh m = fan(5, true); // a disc of 5 triangles: the middle is interior, the rim a border
        const SubdivisionStencil s = buildSubdivisionStencil(m.faces, 6, 1);
        QCOMPARE(s.creaseEdges, std::int64_t(5));
        const double beta = (5.0 / 8 - std::pow(3.0 / 8 + std::cos(2 * kPi / 5) / 4, 2)) / 5;
        QVERIFY(std::abs(weight(s.positions, 0, 0) - (1 - 5 * beta)) < 1e-15);
        QVERIFY(std::abs(weight(s.positions, 0, 3) - beta) < 1e-15);
        // Rim vertex 1: 6/8 itself, 1/8 of its rim neighbours 2 and 5, nothing of the middle.
        QCOMPARE(weight(s.positions, 1, 1), 0.75);
        QCOMPARE(weight(s.positions, 1, 2), 0.125);
        QCOMPARE(weight(s.positions, 1, 5), 0.125);
        QCOMPARE(weight(s.positions, 1, 0), 0.0);
        // Rim edge (1, 2): its midpoint; spoke (0, 1): the interior mask.
        const std::int32_t rim = edgeRow(s, 1, 2), spoke = edgeRow(s, 0, 1);
        QCOMPARE(weight(s.positions, rim, 0), 0.0);
        QCOMPARE(weight(s.positions, spoke, 2), 0.125);
        QCOMPARE(weight(s.positions, spoke, 5), 0.125);
        // Every row is an affine combination.
        for (std::int32_t r = 0; r < s.vertexCount(); ++r) {
            double sum = 0;
            for (std::int32_t c = 0; c < 6; ++c)
                sum += weight(s.positions, r, c);
            QVERIFY(std::abs(sum - 1) < 1e-12);
        }
    }

    void matchesCgal_data()
    {
        QTest::addColumn<bool>("open");
        QTest::addColumn<int>("level");
        for (int level = 1; level <= 3; ++level) {
            QTest::addRow("closed %d", level) << false << level;
            QTest::addRow("open %d", level) << true << level;
        }
    }
    void matchesCgal()
    {
        QFETCH(bool, open);
        QFETCH(int, level);
        compareWithCgal(open ? openSphere() : noisy(*icosphere(2), 1), level);
    }

    void matchesCgalOnSharedElephant()
    {
        CELFORM_REQUIRE_SHARED(path, QStringLiteral("meshes/cgal_elephant.off"));
        compareWithCgal(celform::model::importMesh(path).mesh, 2);
    }

    void limitNormalsAreOutwardAndSmooth()
    {
        // A flat fan, closed and open: every limit normal is +z (border masks included).
        for (const bool closed : {true, false})
            for (int level = 0; level <= 2; ++level) {
                const TriMesh m = fan(7, closed);
                const SubdivisionStencil s = buildSubdivisionStencil(m.faces, 8, level);
                Positions p, n;
                applySubdivision(s, m.vertices, p);
                limitNormals(s, p, n);
                for (Eigen::Index v = 0; v < n.rows(); ++v)
                    QVERIFY2(n(v, 2) > 0.9999f, qPrintable(QStringLiteral("level %1 vertex %2").arg(level).arg(v)));
            }
        // A sphere: limit normals point outwards, close to radial.
        const auto sphere = icosphere(2);
        const SubdivisionStencil s = buildSubdivisionStencil(sphere->faces, std::int32_t(sphere->vertexCount()), 2);
        Positions p, n;
        applySubdivision(s, sphere->vertices, p);
        limitNormals(s, p, n);
        float worst = 1;
        for (Eigen::Index v = 0; v < n.rows(); ++v)
            worst = std::min(worst, n.row(v).dot(p.row(v).normalized()));
        QVERIFY(worst > 0.999f);
        QVERIFY(s.fallbackVertices.empty());
    }

    void partialUpdateMatchesFull()
    {
        const TriMesh m = openSphere();
        const SubdivisionStencil s = buildSubdivisionStencil(m.faces, std::int32_t(m.vertexCount()), 2);
        Positions p, n;
        applySubdivision(s, m.vertices, p);
        limitNormals(s, p, n);
        Positions moved = m.vertices;
        std::vector<std::uint32_t> changed = {0, 5, 17, std::uint32_t(m.vertexCount() - 1)};
        for (const auto v : changed)
            moved.row(v) += Eigen::RowVector3f(0.1f, -0.2f, 0.05f);
        SubdivisionScratch scratch;
        const std::size_t rows = updateSubdivision(s, moved, changed, p, n, scratch);
        QVERIFY(rows > 0 && rows < std::size_t(s.vertexCount()) / 4);
        Positions fullP, fullN;
        applySubdivision(s, moved, fullP);
        limitNormals(s, fullP, fullN);
        QCOMPARE(p, fullP);
        QVERIFY((n - fullN).cwiseAbs().maxCoeff() < 1e-6f);
    }

    void attributesFollowTheStencil()
    {
        TriMesh m = tetrahedronMesh();
        const SubdivisionStencil s = buildSubdivisionStencil(m.faces, 4, 2);
        // Shading offsets: an affine stencil keeps constants and interpolates the rest.
        std::vector<float> offsets = {0.25f, 0.25f, 0.25f, 0.25f}, out;
        applySubdivision(s, offsets, out);
        QCOMPARE(int(out.size()), s.vertexCount());
        for (const float o : out)
            QVERIFY(std::abs(o - 0.25f) < 1e-6f);
        // Children know their parent: 16 per face, consecutive.
        for (Eigen::Index f = 0; f < s.faceCount(); ++f)
            QCOMPARE(s.parentFace[std::size_t(f)], std::int32_t(f / 16));
        QCOMPARE(subdividedFaceSet(s, {2}).front(), 32);
        QCOMPARE(int(subdividedFaceSet(s, {1, 3}).size()), 32);
        // UVs interpolate linearly inside the control face.
        TexCoords uvs(3, 2);
        uvs << 0, 0, 1, 0, 0, 1;
        Faces uvFaces(4, 3);
        uvFaces << 0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2;
        const TexCoords corner = subdividedCornerUvs(s, uvs, uvFaces);
        QCOMPARE(corner.rows(), s.faceCount() * 3);
        for (Eigen::Index r = 0; r < corner.rows(); ++r)
            QVERIFY(corner(r, 0) >= 0 && corner(r, 1) >= 0 && corner(r, 0) + corner(r, 1) <= 1.0001f);
    }

    void nonManifoldInputDoesNotCrash()
    {
        // Three faces on edge (0, 1), a pinched vertex (two fans meeting at 0) and a degenerate face.
        TriMesh m;
        m.vertices.resize(8, 3);
        m.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, -1, -1, -1, -1, 0, -1, 0.5f, 0.5f, 0.5f;
        m.faces.resize(6, 3);
        m.faces << 0, 1, 2, 1, 0, 3, 0, 1, 4, 0, 5, 6, 7, 7, 2, 0, 6, 5;
        for (int level = 0; level <= 3; ++level) {
            const SubdivisionStencil s = buildSubdivisionStencil(m.faces, 8, level);
            QCOMPARE(s.faceCount(), Eigen::Index(6) << (2 * level));
            Positions p, n;
            applySubdivision(s, m.vertices, p);
            limitNormals(s, p, n);
            QVERIFY(p.allFinite());
            QVERIFY(n.allFinite());
            if (level > 0)
                QVERIFY(s.nonManifoldEdges >= 1);
        }
        QCOMPARE(subdividedFaceCount(5, 3), std::int64_t(320));
        QVERIFY(subdividedVertexBound(4, 4, 2) >= 4 + 6 + 24);
    }
};

QTEST_GUILESS_MAIN(TestSubdivision)
#include "test_subdivision.moc"
