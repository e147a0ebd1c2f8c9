// Mesh validation and topology statistics on meshes whose answers are known by hand.
#include "test_meshes.h"
#include "test_support.h"

#include "celform/algorithms/mesh_analysis.h"

using namespace celform::algo;

using celform::test::tetrahedronMesh;

class TestMeshAnalysis : public QObject {
    Q_OBJECT
private slots:
    void closedTetrahedronIsClean()
    {
        const TopologyReport r = analyseTopology(tetrahedronMesh());
        QCOMPARE(r.components, 1);
        QCOMPARE(r.boundaryEdges, 0);
        QCOMPARE(r.nonManifoldEdges, 0);
        QCOMPARE(r.inconsistentEdges, 0);
        QVERIFY(r.isClean());
        QVERIFY(r.summary().empty());
    }

    void openFaceMakesOneHole()
    {
        TriMesh m = tetrahedronMesh();
        m.faces.conservativeResize(3, 3); // drop one face: a triangular hole
        const TopologyReport r = analyseTopology(m);
        QCOMPARE(r.boundaryEdges, 3);
        QCOMPARE(r.boundaryLoops, 1);
        QCOMPARE(QString::fromStdString(r.summary()), QStringLiteral("1 hole"));
    }

    void twoPiecesAndNonManifoldEdge()
    {
        TriMesh m = tetrahedronMesh();
        // A second tetrahedron far away, then a fin sharing edge (0,1) of the first: 3 faces there.
        m.vertices.conservativeResize(9, 3);
        m.vertices.bottomRows(5) << 10, 0, 0, 11, 0, 0, 10, 1, 0, 10, 0, 1, 0.5f, -1, 0;
        m.faces.conservativeResize(9, 3);
        m.faces.bottomRows(5) << 4, 6, 5, 4, 5, 7, 4, 7, 6, 5, 6, 7, 0, 1, 8;
        const TopologyReport r = analyseTopology(m);
        QCOMPARE(r.components, 2);
        QCOMPARE(r.nonManifoldEdges, 1);
        QVERIFY(!r.isClean());
    }

    void flippedFaceIsInconsistent()
    {
        TriMesh m = tetrahedronMesh();
        m.faces.row(3) << 1, 3, 2;
        QCOMPARE(analyseTopology(m).inconsistentEdges, 3);
    }

    void degenerateFaces()
    {
        TriMesh m = tetrahedronMesh();
        m.faces.row(0) << 0, 0, 1;
        QCOMPARE(analyseTopology(m).degenerateFaces, 1);
    }

    // Found by fuzz_off and fuzz_ply: with no face of three distinct corners there is no edge, and
    // the edge buckets were walked from a null pointer (UBSan: non-zero offset to null pointer).
    void noFaceWithThreeCorners()
    {
        TriMesh m = tetrahedronMesh();
        for (Eigen::Index f = 0; f < m.faces.rows(); ++f)
            m.faces(f, 1) = m.faces(f, 0);
        const TopologyReport r = analyseTopology(m);
        QCOMPARE(r.boundaryEdges, 0);
        QCOMPARE(r.nonManifoldEdges, 0);
    }

    void fatalDefects()
    {
        TriMesh m = tetrahedronMesh();
        QVERIFY(!findFatalDefect(m));
        m.vertices(2, 1) = std::numeric_limits<float>::quiet_NaN();
        QVERIFY(findFatalDefect(m)->find("vertex 2") != std::string::npos);
        m = tetrahedronMesh();
        m.faces(1, 2) = 4;
        QVERIFY(findFatalDefect(m)->find("face 1") != std::string::npos);
        m.faces(1, 2) = -1;
        QVERIFY(findFatalDefect(m));
        QVERIFY(findFatalDefect(TriMesh{}));
    }

    void centroidAndBounds()
    {
        const TriMesh m = tetrahedronMesh();
        QVERIFY(centroid(m.vertices).isApprox(Eigen::Vector3d(0.25, 0.25, 0.25)));
        const auto box = boundingBox(m.vertices);
        QVERIFY(box.min().isApprox(Eigen::Vector3d::Zero()));
        QVERIFY(box.max().isApprox(Eigen::Vector3d::Ones()));
        const Positions n = vertexNormals(m.vertices, m.faces);
        // Vertex 3 (0,0,1) touches faces with normals -y, -x and (1,1,1)/sqrt3: its normal points away from the
        // centroid.
        QVERIFY(n.row(3).dot(Eigen::RowVector3f(0, 0, 1) - Eigen::RowVector3f(0.25f, 0.25f, 0.25f)) > 0);
        QVERIFY(std::abs(n.row(3).norm() - 1.f) < 1e-6f);
    }
};

QTEST_GUILESS_MAIN(TestMeshAnalysis)
#include "test_mesh_analysis.moc"
