// Mesh import/export: vertex order kept per format, polygons triangulated, real meshes with their
// documented counts, every malformed file a clean IoError or a warning, bit-exact round trips.
#include "celform/model/data/io_error.h"
#include "celform/model/io/animation_io.h"
#include "celform/model/io/mesh_io.h"
#include "gltf_buffer_fixture.h"
#include "io_test_support.h"
#include "test_support.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>
#include <QtEndian>
#include <QtTest/QtTest>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstring>
#include <iterator>
#include <limits>
#include <mutex>
#include <random>
#include <thread>

#include <sys/stat.h> // mkfifo

using celform::algo::Faces;
using celform::algo::Positions;
using celform::algo::TriMesh;
using celform::model::importMesh;
using celform::model::IoError;
using celform::model::MeshImport;

namespace {

using celform::test::writeFile;

/// Four vertices in a deliberately non-sorted order and one quad: the fan must be (0 1 2), (0 2 3).
Positions quadPositions()
{
    Positions v(4, 3);
    v << 0.5f, -1.25f, 3.0f, //
        2.0f, 0.0f, 0.125f, //
        7.0f, 8.5f, -9.0f, //
        -4.0f, 1.0e-3f, 1.0e6f;
    return v;
}

Faces quadFan()
{
    Faces f(2, 3);
    f << 0, 1, 2, 0, 2, 3;
    return f;
}

template <typename T> void appendBinary(QByteArray& out, T value, bool bigEndian)
{
    char b[sizeof(T)];
    if (bigEndian)
        qToBigEndian(value, b);
    else
        qToLittleEndian(value, b);
    out.append(b, sizeof(T));
}

/// Binary PLY with double coordinates, an extra per-vertex property, an unknown element between
/// vertices and faces, and "list uchar uint": exercises the general (non-fast) paths.
QByteArray quadPlyBinary(bool bigEndian)
{
    QByteArray out = "ply\n";
    out += bigEndian ? "format binary_big_endian 1.0\n" : "format binary_little_endian 1.0\n";
    out += "comment test\nelement vertex 4\nproperty double x\nproperty uchar red\nproperty double y\n"
           "property double z\nelement edge 1\nproperty int vertex1\nproperty list uchar int extra\n"
           "element face 1\nproperty list uchar uint vertex_indices\nproperty float quality\nend_header\n";
    const Positions v = quadPositions();
    for (int i = 0; i < 4; ++i) {
        appendBinary<double>(out, v(i, 0), bigEndian);
        out.append(char(200));
        appendBinary<double>(out, v(i, 1), bigEndian);
        appendBinary<double>(out, v(i, 2), bigEndian);
    }
    appendBinary<qint32>(out, 0, bigEndian);
    out.append(char(2));
    appendBinary<qint32>(out, 5, bigEndian);
    appendBinary<qint32>(out, 6, bigEndian);
    out.append(char(4));
    for (quint32 i : {0u, 1u, 2u, 3u})
        appendBinary<quint32>(out, i, bigEndian);
    appendBinary<float>(out, 1.0f, bigEndian);
    return out;
}

QByteArray tightBinaryPly(int vertexCountInHeader, int verticesWritten)
{
    QByteArray out = "ply\nformat binary_little_endian 1.0\nelement vertex " + QByteArray::number(vertexCountInHeader)
        + "\nproperty float x\nproperty float y\nproperty float z\nelement face 1\n"
          "property list uchar int vertex_indices\nend_header\n";
    for (int i = 0; i < verticesWritten; ++i)
        for (int k = 0; k < 3; ++k)
            appendBinary<float>(out, float(i + k), false);
    out.append(char(3));
    for (qint32 i : {0, 1, 2})
        appendBinary<qint32>(out, i, false);
    return out;
}

/// Ends the run with a message when an import takes longer than a limit: a loader that hangs on a
/// regression input (an endless loop, a blocking open) then fails the suite at once, naming the
/// input, instead of stalling it until ctest's timeout.
class Watchdog {
public:
    Watchdog(const QString& what, std::chrono::seconds limit)
        : m_what(what.toLocal8Bit())
        , m_thread([this, limit] {
            std::unique_lock lock(m_mutex);
            if (!m_doneChanged.wait_for(lock, limit, [this] { return m_done; }))
                qFatal("%s: no answer within %lld s (hang)", m_what.constData(), static_cast<long long>(limit.count()));
        })
    { }
    Watchdog(const Watchdog&) = delete;
    Watchdog& operator=(const Watchdog&) = delete;
    ~Watchdog()
    {
        {
            const std::lock_guard lock(m_mutex);
            m_done = true;
        }
        m_doneChanged.notify_one();
        m_thread.join();
    }

private:
    QByteArray m_what;
    std::mutex m_mutex;
    std::condition_variable m_doneChanged;
    bool m_done = false;
    std::thread m_thread; // last: it starts once the members it uses exist
};

constexpr std::chrono::seconds kImportTimeLimit{20};

/// What each input under tests/data/fuzz-regressions/mesh must give: an IoError whose problem
/// contains `expected`, or (loads) a mesh with a warning containing it. Every file in the folder
/// needs a row here, and every row a file.
struct RegressionExpectation {
    const char* file;
    bool loads;
    const char* expected;
};

constexpr RegressionExpectation kMeshRegressions[] = {
    {"ply-ascii-second-vertex-element-heap-overflow.ply", false, "a second \"vertex\" element"},
    {"ply-binary-second-vertex-element-heap-overflow.ply", false, "a second \"vertex\" element"},
    {"ply-binary-propertyless-element-9e18-rows-hang.ply", false,
        "element \"junk\" has 9000000000000000000 rows but no properties"},
    {"obj-mtllib-dotdot-dev-zero-oom.obj", true, "is outside the folder of the OBJ file"},
    {"obj-mtllib-dotdot-dev-urandom-hang.obj", true, "is outside the folder of the OBJ file"},
    {"obj-face-index-99999999999-wraps.obj", false, "line 4: face 1 has the index 99999999999, which is too large"},
    {"ply-header-only-60m-faces.ply", false,
        "60000000 faces, more than the file holds and more than the 50000000 triangles Celform can load"},
    {"ply-header-only-60m-vertices.ply", false,
        "60000000 vertices and 1 faces, more than the file holds and more than the 50000000 vertices Celform can load"},
    {"off-header-only-60m-faces.off", false,
        "60000000 faces, more than the file holds and more than the 50000000 triangles Celform can load"},
    // Read by Assimp in a child process (celform/model/io/import_process.h): its crash, its allocation or its
    // endless loop ends the child, and the test process lives on to see a one-line refusal.
    // (AddressSanitizer catches the overflow itself, reports it and aborts: signal 6.)
    {"gltf-30000-nested-nodes-stack-overflow.gltf", false,
        celform::test::kAddressSanitizer ? "the importer crashed on it (signal 6"
                                         : "the importer crashed on it (signal 11"},
    {"glb-91-bytes-json-chunk-3.2-gb.glb", false,
        "its first chunk states 3200000000 bytes, but the file holds 71 bytes after its headers"},
    // Stopped by the time limit or the memory limit, whichever comes first.
    {"dae-comment-in-index-list-endless-loop.dae", false, "and was stopped (the limit is CELFORM_IMPORT_"},
};

void verifyQuad(const MeshImport& result)
{
    QCOMPARE(result.mesh.vertexCount(), 4);
    QVERIFY(result.mesh.vertices == quadPositions());
    QVERIFY(result.mesh.faces == quadFan());
}

} // namespace

class TestMeshIo : public QObject {
    Q_OBJECT

private slots:
    void offVertexOrderAndFan_data();
    void offVertexOrderAndFan();
    void plyVertexOrderAndFan_data();
    void plyVertexOrderAndFan();
    void objVertexOrderUvsAndMaterials();
    void objRelativeIndices();
    void gltfNodeTransforms();
    void gltfBufferOutsideItsFolder();
    void gltfWithNonFiniteTokens();
    void malformed_data();
    void malformed();
    void realMeshes_data();
    void realMeshes();
    void dragonTopology();
    void badFiles_data();
    void badFiles();
    void stlIsWelded();
    void roundTrip_data();
    void roundTrip();
    void exportErrors();
    void suffixesAndFilter();
    void fuzzRegressions_data();
    void fuzzRegressions();
    void sizeLimits_data();
    void sizeLimits();
    void notRegularFile_data();
    void notRegularFile();
    void objMaterialLibraries_data();
    void objMaterialLibraries();
    void gltfBuffersAreRegularFiles_data();
    void gltfBuffersAreRegularFiles();
};

void TestMeshIo::offVertexOrderAndFan_data()
{
    QTest::addColumn<QByteArray>("text");
    const QByteArray body = "0.5 -1.25 3\n2 0 0.125\n7 8.5 -9\n-4 0.001 1e6\n4 0 1 2 3\n";
    QTest::newRow("OFF") << QByteArray("OFF\n# comment line\n4 1 0\n" + body);
    QTest::newRow("counts on header line") << QByteArray("OFF 4 1 0\n" + body);
    QTest::newRow("no edge count, CRLF") << QByteArray("OFF\r\n4 1\r\n" + QByteArray(body).replace("\n", "\r\n"));
    QTest::newRow("COFF with colours") << QByteArray(
        "COFF\n4 1 0\n0.5 -1.25 3 255 0 0 255\n2 0 0.125 0 255 0 255\n7 8.5 -9 0 0 255 255\n"
        "-4 0.001 1e6 9 9 9 255\n4 0 1 2 3 1 0 0\n");
    QTest::newRow("NOFF with normals and comments")
        << QByteArray("NOFF # header\n4 1 0 # counts\n0.5 -1.25 3 0 0 1 # v0\n\n2 0 0.125 0 0 1\n7 8.5 -9 0 0 1\n"
                      "-4 0.001 1e6 0 0 1\n# faces\n4 0 1 2 3\n");
    QTest::newRow("headerless") << QByteArray("4 1 0\n" + body);
}

void TestMeshIo::offVertexOrderAndFan()
{
    QFETCH(QByteArray, text);
    QTemporaryDir dir;
    CELFORM_IMPORT_OR_FAIL(result, importMesh(writeFile(dir, QStringLiteral("quad.off"), text)))
    verifyQuad(result);
    QCOMPARE(result.topology.boundaryLoops, 1);
    QVERIFY(!result.warnings.isEmpty()); // an open quad has a hole
}

void TestMeshIo::plyVertexOrderAndFan_data()
{
    QTest::addColumn<QByteArray>("bytes");
    QTest::newRow("ascii") << QByteArray(
        "ply\nformat ascii 1.0\ncomment x\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
        "property uchar red\nelement face 1\nproperty list uchar int vertex_index\nend_header\n"
        "0.5 -1.25 3 1\n2 0 0.125 2\n7 8.5 -9 3\n-4 0.001 1e6 4\n4 0 1 2 3\n");
    QTest::newRow("binary little endian") << quadPlyBinary(false);
    QTest::newRow("binary big endian") << quadPlyBinary(true);
}

void TestMeshIo::plyVertexOrderAndFan()
{
    QFETCH(QByteArray, bytes);
    QTemporaryDir dir;
    CELFORM_IMPORT_OR_FAIL(result, importMesh(writeFile(dir, QStringLiteral("quad.ply"), bytes)))
    verifyQuad(result);
}

void TestMeshIo::objVertexOrderUvsAndMaterials()
{
    QTemporaryDir dir;
    writeFile(dir, QStringLiteral("quad.mtl"), "newmtl red\nKd 1 0 0\nnewmtl blue\nKd 0 0 0.5\n");
    const QString path = writeFile(dir, QStringLiteral("quad.obj"),
        "mtllib quad.mtl\n"
        "v 0.5 -1.25 3\nv 2 0 0.125\nv 7 8.5 -9\nv -4 0.001 1e6\nv 1 1 1\n"
        "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
        "usemtl blue\nf 1/4 2/3 3/2 4/1\nusemtl red\nf 1/1 3/2 5/3\n");
    CELFORM_IMPORT_OR_FAIL(r, importMesh(path))
    QCOMPARE(r.mesh.vertexCount(), 5);
    QVERIFY(r.mesh.vertices.topRows(4) == quadPositions());
    Faces expected(3, 3);
    expected << 0, 1, 2, 0, 2, 3, 0, 2, 4;
    QVERIFY(r.mesh.faces == expected);
    QVERIFY(r.mesh.hasUvs());
    Faces expectedUv(3, 3);
    expectedUv << 3, 2, 1, 3, 1, 0, 0, 1, 2;
    QVERIFY(r.mesh.uvFaces == expectedUv);
    QCOMPARE(r.mesh.uvs(2, 0), 1.0f);
    QCOMPARE(r.mesh.uvs(2, 1), 1.0f);
    QCOMPARE(int(r.mesh.materials.size()), 2);
    QCOMPARE(r.mesh.materials[0].name, std::string("red"));
    QCOMPARE(r.mesh.materials[1].baseColor, Eigen::Vector3f(0, 0, 0.5f));
    QCOMPARE(r.mesh.faceMaterials, (std::vector<std::int32_t>{1, 1, 0}));
}

void TestMeshIo::objRelativeIndices()
{
    QTemporaryDir dir;
    CELFORM_IMPORT_OR_FAIL(
        r, importMesh(writeFile(dir, QStringLiteral("rel.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n")))
    Faces expected(1, 3);
    expected << 0, 1, 2;
    QVERIFY(r.mesh.faces == expected);
    QVERIFY(!r.mesh.hasUvs());
    QVERIFY(r.mesh.materials.empty());
}

void TestMeshIo::gltfNodeTransforms()
{
    // One triangle under a child node (translate 10 in x) of a root scaled by 2.
    QByteArray buffer;
    for (float c : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f})
        appendBinary<float>(buffer, c, false);
    for (quint16 i : {0, 1, 2, 0})
        appendBinary<quint16>(buffer, i, false);
    const QByteArray json = R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],
      "nodes":[{"scale":[2,2,2],"children":[1]},{"translation":[10,0,0],"mesh":0}],
      "meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],
      "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},
                   {"bufferView":1,"componentType":5123,"count":3,"type":"SCALAR"}],
      "bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":6}],
      "buffers":[{"byteLength":44,"uri":"data:application/octet-stream;base64,)"
        + buffer.toBase64() + R"("}]})";
    QTemporaryDir dir;
    CELFORM_IMPORT_OR_FAIL(r, importMesh(writeFile(dir, QStringLiteral("tri.gltf"), json)))
    QCOMPARE(r.mesh.vertexCount(), 3);
    QCOMPARE(r.mesh.faceCount(), 1);
    const Eigen::AlignedBox3d box = celform::algo::boundingBox(r.mesh.vertices);
    QCOMPARE(box.min().x(), 20.0);
    QCOMPARE(box.max().x(), 22.0);
    QCOMPARE(box.max().y(), 2.0);
}

// Issue 27, item 8: a glTF buffer named "../x.bin" lies outside the model's folder: refused by
// default, naming it; read when CELFORM_ALLOW_OUTSIDE_REFERENCES=1; a buffer beside it is read.
// Issue 27: NaN and Infinity are no JSON; such a glTF fell through to Assimp's "No suitable reader".
// Both readers (the mesh's, the animated base's) name the JSON error and its byte offset.
void TestMeshIo::gltfWithNonFiniteTokens()
{
    QTemporaryDir dir;
    for (const char* token : {"NaN", "Infinity", "-Infinity"}) {
        const QByteArray json = QByteArray(R"({"asset":{"version":"2.0"},"accessors":[{"count":3,"max":[)") + token
            + R"(,1,0],"min":[0,0,0]}]})";
        const QString path = writeFile(dir, QStringLiteral("bad_%1.gltf").arg(QLatin1String(token)), json);
        const qsizetype offset = json.indexOf(QByteArray(token).replace("-", "")); // where the letters start
        for (int reader = 0; reader < 2; ++reader) {
            try {
                if (reader == 0)
                    importMesh(path);
                else
                    celform::model::readAnimatedBase(path);
                QFAIL("no IoError");
            } catch (const IoError& e) {
                QCOMPARE(e.file(), path);
                QVERIFY2(e.problem().contains(QStringLiteral("JSON")) && e.problem().contains(QStringLiteral("NaN"))
                        && e.problem().contains(QStringLiteral("byte %1").arg(offset)),
                    qPrintable(e.message()));
            }
        }
    }
}

void TestMeshIo::gltfBufferOutsideItsFolder()
{
    QByteArray buffer;
    for (float c : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f})
        appendBinary<float>(buffer, c, false);
    for (quint16 i : {0, 1, 2, 0})
        appendBinary<quint16>(buffer, i, false);
    auto json = [](const char* uri) {
        return QByteArray(R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],
          "meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],
          "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},
                       {"bufferView":1,"componentType":5123,"count":3,"type":"SCALAR"}],
          "bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":6}],
          "buffers":[{"byteLength":44,"uri":")")
            + uri + R"("}]})";
    };
    QTemporaryDir dir;
    QVERIFY(QDir(dir.path()).mkdir(QStringLiteral("model")));
    writeFile(dir, QStringLiteral("secret.bin"), buffer);
    writeFile(dir, QStringLiteral("model/tri.bin"), buffer);
    const QString outside = writeFile(dir, QStringLiteral("model/outside.gltf"), json("../secret.bin"));
    const QString beside = writeFile(dir, QStringLiteral("model/beside.gltf"), json("tri.bin"));
    try {
        importMesh(outside);
        QFAIL("no IoError");
    } catch (const IoError& e) {
        QCOMPARE(e.file(), outside);
        QVERIFY2(e.problem().contains(QStringLiteral("secret.bin")) && e.problem().contains(QStringLiteral("outside")),
            qPrintable(e.message()));
    }
    CELFORM_IMPORT_OR_FAIL(r, importMesh(beside))
    QCOMPARE(r.mesh.faceCount(), 1);
    qputenv("CELFORM_ALLOW_OUTSIDE_REFERENCES", "1");
    CELFORM_IMPORT_OR_FAIL(allowed, importMesh(outside))
    qunsetenv("CELFORM_ALLOW_OUTSIDE_REFERENCES");
    QCOMPARE(allowed.mesh.faceCount(), 1);
}

void TestMeshIo::malformed_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<QString>("expected"); // a piece of the problem text
    const QByteArray tri = "3 0 1 2\n";
    QTest::newRow("empty off") << "empty.off" << QByteArray() << "empty";
    QTest::newRow("off NaN") << "nan.off" << QByteArray("OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n" + tri) << "vertex 2";
    QTest::newRow("off inf") << "inf.off" << QByteArray("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 inf\n" + tri) << "finite";
    QTest::newRow("off float overflow") << "big.off" << QByteArray("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 1e300\n" + tri)
                                        << "finite";
    QTest::newRow("off index out of range")
        << "range.off" << QByteArray("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n") << "vertex 3";
    QTest::newRow("off negative index") << "neg.off" << QByteArray("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n")
                                        << "vertex -1";
    QTest::newRow("off too few vertex lines")
        << "short.off" << QByteArray("OFF\n30 1 0\n0 0 0\n1 0 0\n0 1 0\n" + tri) << "30";
    QTest::newRow("off too few faces") << "shortf.off"
                                       << QByteArray(
                                              "OFF\n3 2 0\n0.0000 0.0000 0\n1.0000 0.0000 0\n0.0000 1.0000 0\n" + tri)
                                       << "1 of 2 faces";
    QTest::newRow("off huge counts") << "huge.off" << QByteArray("OFF\n1000000000000 1000000000000 0\n0 0 0\n")
                                     << "more than the file";
    QTest::newRow("off garbage") << "garbage.off" << QByteArray("OFF\n3 1 0\n0 0 0\n1 x 0\n0 1 0\n" + tri) << "line 4";
    QTest::newRow("off no header") << "text.off" << QByteArray("hello world\n") << "OFF";
    QTest::newRow("off no faces") << "nofaces.off" << QByteArray("OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n") << "no faces";
    QTest::newRow("ply truncated binary") << "trunc.ply" << tightBinaryPly(10, 2) << "10 vertices";
    QTest::newRow("ply truncated faces") << "truncf.ply" << tightBinaryPly(3, 3).chopped(5) << "truncated";
    QTest::newRow("ply huge count") << "huge.ply" << tightBinaryPly(2000000000, 3) << "more than the file";
    QTest::newRow("ply binary NaN") << "nan.ply" << [] {
        QByteArray b = tightBinaryPly(3, 3);
        const float nan = std::numeric_limits<float>::quiet_NaN();
        std::memcpy(b.data() + b.indexOf("end_header\n") + 11 + 4, &nan, 4);
        return b;
    }() << "vertex 1";
    QTest::newRow("ply binary index range") << "range.ply" << [] {
        QByteArray b = tightBinaryPly(3, 3);
        b[b.size() - 4] = 7;
        return b;
    }() << "vertex 7";
    QTest::newRow("ply ascii inf")
        << "inf.ply"
        << QByteArray(
               "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
               "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 -inf 0\n3 0 1 2\n")
        << "finite";
    QTest::newRow("ply ascii truncated")
        << "trunc_ascii.ply"
        << QByteArray(
               "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
               "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1\n")
        << "ends early";
    QTest::newRow("ply no end_header") << "noend.ply" << QByteArray("ply\nformat ascii 1.0\nelement vertex 3\n")
                                       << "end_header";
    QTest::newRow("ply bad type") << "type.ply"
                                  << QByteArray(
                                         "ply\nformat ascii 1.0\nelement vertex 1\nproperty quux x\nend_header\n")
                                  << "type";
    QTest::newRow("ply not ply") << "not.ply" << QByteArray("solid x\n") << "PLY";
    QTest::newRow("obj out of range") << "range.obj" << QByteArray("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n")
                                      << "vertex 8";
    QTest::newRow("obj negative out of range")
        << "neg.obj" << QByteArray("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -10\n") << "vertex -7";
    QTest::newRow("obj zero index") << "zero.obj" << QByteArray("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n") << "OBJ";
    QTest::newRow("obj texcoord out of range")
        << "vt.obj" << QByteArray("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/5\n") << "texture";
    QTest::newRow("obj float overflow") << "big.obj" << QByteArray("v 0 0 0\nv 1 0 0\nv 0 1e39 0\nf 1 2 3\n")
                                        << "vertex 3";
    QTest::newRow("obj NaN") << "nan.obj" << QByteArray("v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n") << "vertex 2";
    QTest::newRow("obj index wraps to a valid one")
        << "wrap.obj" << QByteArray("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4294967299\n") << "index 4294967299, which";
    QTest::newRow("obj negative index overflow")
        << "negwrap.obj" << QByteArray("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -99999999999\n") << "-99999999999";
    QTest::newRow("obj texcoord index overflow")
        << "vtwrap.obj" << QByteArray("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/4294967297\n")
        << "line 5: face 1 has the index 4294967297";
    QTest::newRow("obj index of 30 digits")
        << "digits.obj" << QByteArray("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 123456789012345678901234567890\n")
        << "123456789012345678901234567890";
    QTest::newRow("ply second face element")
        << "faces2.ply"
        << QByteArray("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                      "element face 1\nproperty list uchar int vertex_indices\n"
                      "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                      "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 2\n")
        << "PLY header line 9: a second \"face\" element";
    QTest::newRow("ply ascii element without properties")
        << "noprops.ply"
        << QByteArray("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                      "element junk 5\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                      "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
        << "PLY header line 7: element \"junk\" has 5 rows but no properties";
    QTest::newRow("obj no faces") << "nofaces.obj" << QByteArray("v 0 0 0\n") << "no faces";
    QTest::newRow("stl garbage") << "garbage.stl" << QByteArray("this is not an stl file at all, not even close\n")
                                 << "STL";
    QTest::newRow("unknown suffix") << "mesh.xyz" << QByteArray("1 2 3\n") << "xyz";
}

void TestMeshIo::malformed()
{
    QFETCH(QString, name);
    QFETCH(QByteArray, bytes);
    QFETCH(QString, expected);
    QTemporaryDir dir;
    const QString path = writeFile(dir, name, bytes);
    try {
        importMesh(path);
        QFAIL("no IoError");
    } catch (const IoError& e) {
        QCOMPARE(e.file(), path);
        QVERIFY2(e.problem().contains(expected), qPrintable(e.message()));
        QVERIFY2(!e.problem().contains(QLatin1Char('\n')), qPrintable(e.message()));
    }
}

void TestMeshIo::realMeshes_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<int>("vertices");
    QTest::addColumn<int>("triangles");
    QTest::addColumn<bool>("clean");
    QTest::newRow("bunny") << "meshes/npm_bunny.off" << 1839 << 3674 << true;
    QTest::newRow("elephant") << "meshes/cgal_elephant.off" << 2775 << 5558 << true;
    QTest::newRow("fandisk") << "meshes/cgal_fandisk.off" << 6475 << 12946 << true;
    QTest::newRow("armadillo") << "meshes/cgal_armadillo.off" << 26002 << 52000 << true;
    QTest::newRow("bunny00") << "meshes/cgal_bunny00.off" << 37706 << 75408 << true;
    QTest::newRow("refined elephant") << "meshes/cgal_refined_elephant.off" << 44460 << 88928 << true;
    QTest::newRow("dragon") << "meshes/stanford_dragon.ply" << 437645 << 871414 << false;
}

void TestMeshIo::realMeshes()
{
    QFETCH(QString, file);
    QFETCH(int, vertices);
    QFETCH(int, triangles);
    QFETCH(bool, clean);
    CELFORM_REQUIRE_SHARED(path, file);
    CELFORM_IMPORT_OR_FAIL(r, importMesh(path))
    QCOMPARE(r.mesh.vertexCount(), vertices);
    QCOMPARE(r.mesh.faceCount(), triangles);
    QCOMPARE(r.topology.isClean(), clean);
    QCOMPARE(r.warnings.isEmpty(), clean);
}

void TestMeshIo::dragonTopology()
{
    CELFORM_REQUIRE_SHARED(path, QStringLiteral("meshes/stanford_dragon.ply"));
    CELFORM_IMPORT_OR_FAIL(r, importMesh(path))
    QCOMPARE(r.topology.components, 151);
    QVERIFY(r.topology.boundaryLoops > 0);
    QVERIFY2(r.warnings.first().contains(QStringLiteral("151 component")), qPrintable(r.warnings.join('|')));
    // The first vertex of the file stays first (the converted dragon starts at this position).
    QFile f(path);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QByteArray bytes = f.readAll();
    const int body = bytes.indexOf("end_header\n") + 11;
    float first[3];
    std::memcpy(first, bytes.constData() + body, sizeof first);
    QCOMPARE(r.mesh.vertices(0, 0), first[0]);
    QCOMPARE(r.mesh.vertices(0, 2), first[2]);
}

void TestMeshIo::badFiles_data()
{
    QTest::addColumn<QString>("path");
    const QString dir = celform::test::sharedDataPath(QStringLiteral("bad"));
    if (dir.isEmpty()) {
        QTest::newRow("absent") << QString();
        return;
    }
    for (const QFileInfo& info : QDir(dir).entryInfoList(QDir::Files, QDir::Name))
        QTest::newRow(qPrintable(info.fileName())) << info.absoluteFilePath();
}

void TestMeshIo::badFiles()
{
    QFETCH(QString, path);
    if (path.isEmpty())
        QSKIP("shared test data not found: ../shared/data/bad");
    const QString name = QFileInfo(path).fileName();
    try {
        const MeshImport r = importMesh(path);
        QVERIFY2(!r.warnings.isEmpty(), "a bad file loaded without any warning");
        qInfo("%s -> warning: %s", qPrintable(name), qPrintable(r.warnings.join(QStringLiteral(" | "))));
    } catch (const IoError& e) {
        QVERIFY2(e.message().contains(name), qPrintable(e.message()));
        qInfo("%s -> error: %s", qPrintable(name), qPrintable(e.problem()));
    }
}

void TestMeshIo::stlIsWelded()
{
    CELFORM_REQUIRE_SHARED(path, QStringLiteral("bad/sphereWithHole.stl"));
    CELFORM_IMPORT_OR_FAIL(r, importMesh(path))
    QVERIFY(r.mesh.faceCount() > 100);
    // A welded closed-ish sphere has about half as many vertices as faces, a soup three times.
    QVERIFY2(r.mesh.vertexCount() < r.mesh.faceCount(),
        qPrintable(QStringLiteral("%1 vertices, %2 faces").arg(r.mesh.vertexCount()).arg(r.mesh.faceCount())));
    QCOMPARE(r.topology.boundaryLoops, 1);
    QCOMPARE(r.topology.components, 1);
}

void TestMeshIo::roundTrip_data()
{
    QTest::addColumn<QString>("suffix");
    QTest::newRow("ply") << "ply";
    QTest::newRow("obj") << "obj";
}

void TestMeshIo::roundTrip()
{
    QFETCH(QString, suffix);
    // Awkward floats: subnormal-free random bits over many magnitudes, negatives, exact integers.
    std::mt19937 rng(42);
    std::uniform_real_distribution<float> mantissa(-1.0f, 1.0f);
    std::uniform_int_distribution<int> exponent(-30, 30);
    TriMesh mesh;
    mesh.vertices.resize(300, 3);
    for (Eigen::Index i = 0; i < mesh.vertices.size(); ++i)
        mesh.vertices.data()[i] = std::ldexp(mantissa(rng), exponent(rng));
    mesh.vertices.row(0) << 0.1f, -0.0f, 16777216.0f;
    mesh.faces.resize(299 - 1, 3);
    for (int f = 0; f < mesh.faces.rows(); ++f)
        mesh.faces.row(f) << f, f + 1, f + 2;

    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("round.") + suffix);
    celform::model::exportMesh(mesh, path);
    CELFORM_IMPORT_OR_FAIL(r, importMesh(path))
    QCOMPARE(r.mesh.vertexCount(), mesh.vertexCount());
    QVERIFY(std::memcmp(r.mesh.vertices.data(), mesh.vertices.data(), sizeof(float) * std::size_t(mesh.vertices.size()))
        == 0);
    QVERIFY(r.mesh.faces == mesh.faces);
}

void TestMeshIo::exportErrors()
{
    TriMesh mesh;
    mesh.vertices = quadPositions();
    mesh.faces = quadFan();
    QTemporaryDir dir;
    QVERIFY_THROWS_EXCEPTION(IoError, celform::model::exportMesh(mesh, dir.filePath(QStringLiteral("a.stl"))));
    QVERIFY_THROWS_EXCEPTION(
        IoError, celform::model::exportMesh(mesh, dir.filePath(QStringLiteral("no/such/dir/a.ply"))));
    QVERIFY(!QFileInfo::exists(dir.filePath(QStringLiteral("a.stl"))));
    QVERIFY_THROWS_EXCEPTION(IoError, importMesh(dir.filePath(QStringLiteral("missing.ply"))));
}

void TestMeshIo::suffixesAndFilter()
{
    const QStringList s = celform::model::meshSuffixes();
    for (const char* needed : {"obj", "ply", "off", "stl", "gltf", "glb"})
        QVERIFY(s.contains(QLatin1String(needed)));
    QVERIFY(celform::model::meshFileFilter().contains(QStringLiteral("*.ply")));
}

void TestMeshIo::fuzzRegressions_data()
{
    QTest::addColumn<QString>("path");
    QTest::addColumn<bool>("listed");
    QTest::addColumn<bool>("loads");
    QTest::addColumn<QString>("expected");
    const QDir dir(celform::test::testDataPath(QStringLiteral("fuzz-regressions/mesh")));
    QStringList files = dir.entryList(QDir::Files, QDir::Name);
    for (const RegressionExpectation& r : kMeshRegressions)
        if (!files.contains(QLatin1String(r.file)))
            files << QLatin1String(r.file); // a listed file that is missing fails below
    for (const QString& file : files) {
        const auto it = std::find_if(std::begin(kMeshRegressions), std::end(kMeshRegressions),
            [&](const RegressionExpectation& r) { return file == QLatin1String(r.file); });
        const bool listed = it != std::end(kMeshRegressions);
        QTest::newRow(qPrintable(file)) << dir.filePath(file) << listed << (listed && it->loads)
                                        << (listed ? QString::fromUtf8(it->expected) : QString());
    }
}

void TestMeshIo::fuzzRegressions()
{
    QFETCH(QString, path);
    QFETCH(bool, listed);
    QFETCH(bool, loads);
    QFETCH(QString, expected);
    QVERIFY2(listed, "no row in kMeshRegressions for this file");
    QVERIFY2(QFileInfo(path).isFile(), qPrintable(QStringLiteral("missing: ") + path));
    const Watchdog watchdog(path, kImportTimeLimit);
    try {
        const MeshImport r = importMesh(path);
        QVERIFY2(loads, qPrintable(QStringLiteral("loaded, but should be refused with: ") + expected));
        const QString warnings = r.warnings.join(QStringLiteral(" | "));
        QVERIFY2(warnings.contains(expected), qPrintable(QStringLiteral("warnings: ") + warnings));
    } catch (const IoError& e) {
        QVERIFY2(!loads, qPrintable(QStringLiteral("refused, but should load: ") + e.message()));
        QCOMPARE(e.file(), path);
        QVERIFY2(e.problem().contains(expected), qPrintable(e.message()));
        QVERIFY2(!e.problem().contains(QLatin1Char('\n')), qPrintable(e.message()));
    }
}

void TestMeshIo::sizeLimits_data()
{
    // Headers whose counts the file's size could hold: a zero-filled (sparse) body makes them
    // plausible, so only the size limit stands between the count and the allocation.
    QTest::addColumn<QString>("name");
    QTest::addColumn<QByteArray>("header");
    QTest::addColumn<qint64>("bodyBytes");
    QTest::addColumn<QString>("expected");
    const QByteArray vertices = "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
    QTest::newRow("ply faces") << "faces.ply"
                               << QByteArray("ply\nformat binary_little_endian 1.0\n" + vertices
                                      + "element face 60000000\nproperty list uchar int vertex_indices\nend_header\n")
                               << qint64(36 + 60000000)
                               << "the file has 60000000 faces, more than the 50000000 triangles";
    QTest::newRow("ply vertices")
        << "vertices.ply"
        << QByteArray("ply\nformat binary_little_endian 1.0\nelement vertex 60000000\nproperty float x\n"
                      "property float y\nproperty float z\nend_header\n")
        << qint64(720000000) << "the file has 60000000 vertices, more than the 50000000 vertices";
    QTest::newRow("off faces") << "faces.off" << QByteArray("OFF\n3 60000000 0\n") << qint64(500000000)
                               << "the file has 60000000 faces, more than the 50000000 triangles";
    QTest::newRow("ply polygon of 60 M corners")
        << "polygon.ply"
        << QByteArray("ply\nformat ascii 1.0\n" + vertices
               + "element face 1\nproperty list uint int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n60000000 ")
        << qint64(60000000) << "face 1 makes more than the 50000000 triangles";
}

void TestMeshIo::sizeLimits()
{
    QFETCH(QString, name);
    QFETCH(QByteArray, header);
    QFETCH(qint64, bodyBytes);
    QFETCH(QString, expected);
    QTemporaryDir dir;
    const QString path = writeFile(dir, name, header);
    {
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadWrite) && file.resize(header.size() + bodyBytes)); // sparse
    }
    const Watchdog watchdog(path, kImportTimeLimit);
    try {
        importMesh(path);
        QFAIL("no IoError");
    } catch (const IoError& e) {
        QCOMPARE(e.file(), path);
        QVERIFY2(e.problem().contains(expected), qPrintable(e.message()));
    }
}

void TestMeshIo::notRegularFile_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("kind");
    QTest::newRow("fifo ply") << "pipe.ply"
                              << "fifo";
    QTest::newRow("fifo stl (Assimp)") << "pipe.stl"
                                       << "fifo";
    QTest::newRow("directory obj") << "folder.obj"
                                   << "directory";
    QTest::newRow("link to a device") << "zero.off"
                                      << "device";
}

void TestMeshIo::notRegularFile()
{
    QFETCH(QString, name);
    QFETCH(QString, kind);
    QTemporaryDir dir;
    const QString path = dir.filePath(name);
    if (kind == QLatin1String("fifo"))
        QVERIFY(::mkfifo(QFile::encodeName(path).constData(), 0600) == 0);
    else if (kind == QLatin1String("directory"))
        QVERIFY(QDir(dir.path()).mkdir(name));
    else
        QVERIFY(QFile::link(QStringLiteral("/dev/zero"), path));
    // Opening a FIFO with no writer blocks: the refusal must come before any open().
    const Watchdog watchdog(path, kImportTimeLimit);
    try {
        importMesh(path);
        QFAIL("no IoError");
    } catch (const IoError& e) {
        QCOMPARE(e.file(), path);
        QVERIFY2(e.problem().contains(QStringLiteral("not a regular file")), qPrintable(e.message()));
    }
}

void TestMeshIo::objMaterialLibraries_data()
{
    QTest::addColumn<QString>("mtllib");
    QTest::addColumn<QString>("warning"); // empty: the materials load
    QTest::newRow("sub-folder") << "mats/quad.mtl" << QString();
    QTest::newRow("absolute") << "/dev/zero"
                              << "\"/dev/zero\" is outside the folder of the OBJ file";
    QTest::newRow("absolute to a file") << "@/mats/quad.mtl"
                                        << "is outside the folder of the OBJ file";
    QTest::newRow("dot-dot inside") << "mats/../mats/quad.mtl" << QString();
    QTest::newRow("dot-dot") << "../quad.mtl"
                             << "is outside the folder of the OBJ file";
    QTest::newRow("missing") << "none.mtl"
                             << "\"none.mtl\" does not exist";
    QTest::newRow("fifo") << "pipe.mtl"
                          << "\"pipe.mtl\" is not a regular file";
    QTest::newRow("folder") << "mats"
                            << "\"mats\" is not a regular file";
    QTest::newRow("too large") << "big.mtl"
                               << "\"big.mtl\" is larger than";
}

void TestMeshIo::objMaterialLibraries()
{
    QFETCH(QString, mtllib);
    QFETCH(QString, warning);
    QTemporaryDir dir;
    QVERIFY(QDir(dir.path()).mkpath(QStringLiteral("obj/mats")));
    const QByteArray mtl = "newmtl red\nKd 1 0 0\n";
    writeFile(dir, QStringLiteral("quad.mtl"), mtl); // beside the OBJ's folder: out of reach
    writeFile(dir, QStringLiteral("obj/mats/quad.mtl"), mtl);
    QVERIFY(::mkfifo(QFile::encodeName(dir.filePath(QStringLiteral("obj/pipe.mtl"))).constData(), 0600) == 0);
    {
        QFile big(dir.filePath(QStringLiteral("obj/big.mtl")));
        QVERIFY(big.open(QIODevice::WriteOnly) && big.resize(qint64(64) << 20)); // sparse
    }
    mtllib.replace(QLatin1Char('@'), dir.filePath(QStringLiteral("obj")));
    const QString path = writeFile(dir, QStringLiteral("obj/tri.obj"),
        "mtllib " + mtllib.toUtf8() + "\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n");
    const Watchdog watchdog(path, kImportTimeLimit);
    CELFORM_IMPORT_OR_FAIL(r, importMesh(path))
    QCOMPARE(r.mesh.faceCount(), 1);
    if (warning.isEmpty()) {
        QVERIFY2(r.warnings.filter(QStringLiteral("material")).isEmpty(), qPrintable(r.warnings.join('|')));
        QCOMPARE(int(r.mesh.materials.size()), 1);
        QCOMPARE(r.mesh.materials[0].name, std::string("red"));
    } else {
        QVERIFY2(r.warnings.join('|').contains(warning), qPrintable(r.warnings.join('|')));
        QVERIFY(r.mesh.materials.empty()); // default materials
        for (const QString& w : r.warnings)
            QVERIFY2(!w.contains(QLatin1Char('\n')), qPrintable(w));
    }
}

void TestMeshIo::gltfBuffersAreRegularFiles_data()
{
    celform::test::addBufferUriRows();
}

// A glTF buffer whose uri names a FIFO blocked Assimp's open for ever (/dev/zero, with a
// byteLength of 4 GB, read without end). Assimp opens only regular files now, and a hang would be
// stopped by the child's time limit in any case.
void TestMeshIo::gltfBuffersAreRegularFiles()
{
    QFETCH(QString, uri);
    QTemporaryDir dir;
    QVERIFY(celform::test::makeBufferTargets(dir));
    const QByteArray json = celform::test::gltfWithBufferUri(uri);
    const QString path = writeFile(dir, QStringLiteral("buffer.gltf"), json);
    const Watchdog watchdog(path, kImportTimeLimit);
    QElapsedTimer timer;
    timer.start();
    try {
        importMesh(path);
        QFAIL("no IoError");
    } catch (const IoError& e) {
        QCOMPARE(e.file(), path);
        QVERIFY2(
            !e.problem().contains(QStringLiteral("was stopped")), qPrintable(e.message())); // refused, not timed out
        QVERIFY2(!e.problem().contains(QLatin1Char('\n')), qPrintable(e.message()));
        qInfo("%s -> %s (%lld ms)", qPrintable(uri), qPrintable(e.problem()), timer.elapsed());
    }
}

QTEST_GUILESS_MAIN(TestMeshIo)
#include "test_mesh_io.moc"
