// Animated base import: glTF skins, morph targets and LINEAR/STEP/CUBICSPLINE channels checked
// against positions worked out by hand, GLB against glTF, OBJ sequences, and bad files refused
// with the file named. The glTF files are built here with tinygltf's writer.
#include "celform/model/io/animation_io.h"
#include "celform/model/data/io_error.h"
#include "celform/model/io/project_file.h"
#include "gltf_buffer_fixture.h"
#include "io_test_support.h"
#include "test_support.h"

#include <tiny_gltf.h>

#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QtTest/QtTest>

#include <cmath>
#include <cstring>
#include <limits>

using celform::algo::Positions;
using celform::model::AnimatedImport;
using celform::model::IoError;
using celform::model::isAnimatedBaseFile;
using celform::model::loadProject;
using celform::model::newAnimatedProject;
using celform::model::ProjectData;
using celform::model::readAnimatedBase;
using celform::model::saveProject;

namespace {

constexpr double kPi = 3.14159265358979323846;

using celform::test::writeFile;

QByteArray readBytes(const QString& path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        qFatal("cannot read %s", qPrintable(path));
    return f.readAll();
}

/// A tinygltf model filled accessor by accessor, each over its own view of buffer 0.
struct GltfBuilder {
    tinygltf::Model m;

    GltfBuilder()
    {
        m.buffers.resize(1);
        m.scenes.resize(1);
        m.defaultScene = 0;
    }

    template <typename T>
    int accessor(const std::vector<T>& values, int type, int componentType, bool normalized = false)
    {
        auto& data = m.buffers[0].data;
        while (data.size() % 4 != 0)
            data.push_back(0);
        tinygltf::BufferView view;
        view.buffer = 0;
        view.byteOffset = data.size();
        view.byteLength = values.size() * sizeof(T);
        const auto* bytes = reinterpret_cast<const unsigned char*>(values.data());
        data.insert(data.end(), bytes, bytes + view.byteLength);
        m.bufferViews.push_back(view);
        tinygltf::Accessor a;
        a.bufferView = int(m.bufferViews.size() - 1);
        a.componentType = componentType;
        a.type = type;
        a.normalized = normalized;
        a.count = values.size() / std::size_t(tinygltf::GetNumComponentsInType(std::uint32_t(type)));
        m.accessors.push_back(a);
        return int(m.accessors.size() - 1);
    }
    int floats(const std::vector<float>& values, int type)
    {
        return accessor(values, type, TINYGLTF_COMPONENT_TYPE_FLOAT);
    }
    int indices(const std::vector<std::uint16_t>& values)
    {
        return accessor(values, TINYGLTF_TYPE_SCALAR, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
    }
    /// A mesh of one triangle primitive; returns the mesh index.
    int mesh(int positions, int indexAccessor)
    {
        tinygltf::Primitive p;
        p.attributes["POSITION"] = positions;
        p.indices = indexAccessor;
        p.mode = TINYGLTF_MODE_TRIANGLES;
        tinygltf::Mesh mesh;
        mesh.primitives.push_back(p);
        m.meshes.push_back(mesh);
        return int(m.meshes.size() - 1);
    }
    int node(int mesh = -1)
    {
        tinygltf::Node n;
        n.mesh = mesh;
        m.nodes.push_back(n);
        return int(m.nodes.size() - 1);
    }
    /// A channel of the first animation with its own sampler.
    void channel(int node, const char* path, const std::vector<float>& times, const std::vector<float>& values,
        int valueType, const char* interpolation = "LINEAR")
    {
        if (m.animations.empty())
            m.animations.resize(1);
        tinygltf::Animation& a = m.animations[0];
        tinygltf::AnimationSampler s;
        s.input = floats(times, TINYGLTF_TYPE_SCALAR);
        s.output = floats(values, valueType);
        s.interpolation = interpolation;
        a.samplers.push_back(s);
        tinygltf::AnimationChannel c;
        c.sampler = int(a.samplers.size() - 1);
        c.target_node = node;
        c.target_path = path;
        a.channels.push_back(c);
    }
    QString write(const QTemporaryDir& dir, const QString& name) const
    {
        const QString path = dir.filePath(name);
        tinygltf::TinyGLTF writer;
        const bool binary = name.endsWith(QLatin1String(".glb"));
        if (!writer.WriteGltfSceneToFile(&m, QFile::encodeName(path).toStdString(), true, true, !binary, binary))
            qFatal("cannot write %s", qPrintable(path));
        return path;
    }
};

/// A strip of six vertices up the y axis, two triangles per unit: y = 0 follows joint 0, y = 1
/// both joints half and half, y = 2 joint 1 only. Joint 1 sits at y = 1 under joint 0 and turns
/// 90 degrees about z over the first second (LINEAR rotation). The skinned node is moved by
/// 100 in x, which glTF says to ignore.
GltfBuilder skinnedStrip(bool shortJointsAndByteWeights)
{
    GltfBuilder b;
    const int positions = b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 2, 0, 1, 2, 0}, TINYGLTF_TYPE_VEC3);
    const int mesh = b.mesh(positions, b.indices({0, 1, 3, 0, 3, 2, 2, 3, 5, 2, 5, 4}));
    tinygltf::Primitive& prim = b.m.meshes[std::size_t(mesh)].primitives[0];
    if (shortJointsAndByteWeights) {
        prim.attributes["JOINTS_0"] = b.accessor(
            std::vector<std::uint16_t>{0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0},
            TINYGLTF_TYPE_VEC4, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
        // Normalised bytes; 100 + 100 is not 255, so these are renormalised to one half each.
        prim.attributes["WEIGHTS_0"] = b.accessor(std::vector<std::uint8_t>{255, 0, 0, 0, 255, 0, 0, 0, 100, 100, 0, 0,
                                                      100, 100, 0, 0, 255, 0, 0, 0, 255, 0, 0, 0},
            TINYGLTF_TYPE_VEC4, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, true);
    } else {
        prim.attributes["JOINTS_0"] = b.accessor(
            std::vector<std::uint8_t>{0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0},
            TINYGLTF_TYPE_VEC4, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE);
        // Floats summing to 2 and to 0.5: renormalised to 1.
        prim.attributes["WEIGHTS_0"]
            = b.floats({2, 0, 0, 0, 2, 0, 0, 0, 0.25f, 0.25f, 0, 0, 0.25f, 0.25f, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0},
                TINYGLTF_TYPE_VEC4);
    }
    const int skinned = b.node(mesh);
    b.m.nodes[std::size_t(skinned)].translation = {100, 0, 0};
    b.m.nodes[std::size_t(skinned)].skin = 0;
    const int root = b.node();
    const int elbow = b.node();
    b.m.nodes[std::size_t(root)].children = {elbow};
    b.m.nodes[std::size_t(elbow)].translation = {0, 1, 0};
    b.m.scenes[0].nodes = {skinned, root};
    tinygltf::Skin skin;
    skin.joints = {root, elbow};
    skin.inverseBindMatrices
        = b.floats({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 0, 1},
            TINYGLTF_TYPE_MAT4);
    b.m.skins.push_back(skin);
    const float h = float(std::sqrt(0.5));
    b.channel(elbow, "rotation", {0, 1}, {0, 0, 0, 1, 0, 0, h, h}, TINYGLTF_TYPE_VEC4);
    return b;
}

/// The strip's vertices with joint 1 turned by angle (radians), worked out by hand: y = 2 turns
/// about (0, 1, 0); y = 1 averages the unmoved point and the turned one.
Positions expectedStrip(double angle)
{
    const auto c = float(std::cos(angle));
    const auto s = float(std::sin(angle));
    Positions p(6, 3);
    p << 0, 0, 0, //
        1, 0, 0, //
        0, 1, 0, //
        (1 + c) / 2, (2 + s) / 2, 0, //
        -s, 1 + c, 0, //
        c - s, 1 + s + c, 0;
    return p;
}

bool near(const Positions& a, const Positions& b, float tolerance = 1e-5f)
{
    return a.rows() == b.rows() && (a - b).cwiseAbs().maxCoeff() <= tolerance;
}

QByteArray rowsText(const Positions& p)
{
    QByteArray s;
    for (Eigen::Index i = 0; i < p.rows(); ++i)
        s += QByteArray::number(p(i, 0)) + ' ' + QByteArray::number(p(i, 1)) + ' ' + QByteArray::number(p(i, 2)) + "; ";
    return s;
}

/// Whether reading `read` is refused with an IoError naming `named` whose problem, on one line,
/// contains `problem`; message gets the error's one-line message (or says there was none).
bool refused(const QString& read, const QString& named, const QString& problem, QString& message)
{
    try {
        readAnimatedBase(read);
        message = QStringLiteral("no IoError");
        return false;
    } catch (const IoError& e) {
        message = e.message();
        return e.file() == named && e.problem().contains(problem) && !e.problem().contains(QLatin1Char('\n'));
    }
}

#define CELFORM_COMPARE_POSITIONS(got, expected)                                                                       \
    QVERIFY2(near(got, expected), ("got " + rowsText(got) + "expected " + rowsText(expected)).constData())

/// A triangle under a node at x = 1 with one morph target lifting every vertex by 1 in z.
GltfBuilder morphTriangle()
{
    GltfBuilder b;
    const int mesh = b.mesh(b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, TINYGLTF_TYPE_VEC3), b.indices({0, 1, 2}));
    b.m.meshes[std::size_t(mesh)].primitives[0].targets.push_back(
        {{"POSITION", b.floats({0, 0, 1, 0, 0, 1, 0, 0, 1}, TINYGLTF_TYPE_VEC3)}});
    b.m.meshes[std::size_t(mesh)].weights = {0.0};
    const int node = b.node(mesh);
    b.m.nodes[std::size_t(node)].translation = {1, 0, 0};
    b.m.scenes[0].nodes = {node};
    return b;
}

/// A triangle whose node is moved along x by a channel.
GltfBuilder movingTriangle(const std::vector<float>& times, const std::vector<float>& values, const char* interpolation)
{
    GltfBuilder b;
    const int node = b.node(b.mesh(b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, TINYGLTF_TYPE_VEC3), b.indices({0, 1, 2})));
    b.m.scenes[0].nodes = {node};
    b.channel(node, "translation", times, values, TINYGLTF_TYPE_VEC3, interpolation);
    return b;
}

Positions triangleAt(float x)
{
    Positions p(3, 3);
    p << x, 0, 0, x + 1, 0, 0, x, 1, 0;
    return p;
}

/// A frame of the square sequence as OBJ, or as ASCII PLY when the name ends in .ply: one quad.
QByteArray squareFrame(const QString& name, const Positions& v)
{
    const bool ply = name.endsWith(QLatin1String(".ply"));
    QByteArray s = ply ? "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                         "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                       : "";
    for (Eigen::Index i = 0; i < v.rows(); ++i)
        s += (ply ? "" : "v ") + QByteArray::number(v(i, 0)) + ' ' + QByteArray::number(v(i, 1)) + ' '
            + QByteArray::number(v(i, 2)) + '\n';
    return s + (ply ? "4 0 1 2 3\n" : "f 1 2 3 4\n");
}

} // namespace

class TestAnimationIo : public QObject {
    Q_OBJECT
private slots:
    void skinnedStripRotatingJoint_data();
    void skinnedStripRotatingJoint();
    void glbRoundTrip();
    void morphWeightsLinear();
    void stepAndCubicSpline_data();
    void stepAndCubicSpline();
    void sparseAndStride();
    void mergeOrder();
    void animatedParentMovesChild();
    void sequence_data();
    void sequence();
    void sequenceGaps();
    void sequenceMemoryIsLinear();
    void sequenceMismatch_data();
    void sequenceMismatch();
    void badFiles_data();
    void badFiles();
    void buffersAreRegularFiles_data();
    void buffersAreRegularFiles();
    void realFiles();
};

void TestAnimationIo::skinnedStripRotatingJoint_data()
{
    QTest::addColumn<bool>("shortJoints");
    QTest::newRow("byte joints, float weights") << false;
    QTest::newRow("short joints, normalised byte weights") << true;
}

void TestAnimationIo::skinnedStripRotatingJoint()
{
    QFETCH(bool, shortJoints);
    QTemporaryDir dir;
    const QString path = skinnedStrip(shortJoints).write(dir, QStringLiteral("strip.gltf"));
    QVERIFY(isAnimatedBaseFile(path));
    CELFORM_IMPORT_OR_FAIL(r, readAnimatedBase(path, 24.0))
    QCOMPARE(r.fps, 24.0);
    QCOMPARE(r.animation.firstFrame, 0);
    QCOMPARE(r.animation.frameCount, 25); // t = 0 .. 1 s at 24 fps, both ends included
    QCOMPARE(r.animation.jointCount, 2);
    QCOMPARE(r.mesh->faceCount(), 4);
    // The rest pose is the bind pose: the skinned node's own translation is ignored.
    CELFORM_COMPARE_POSITIONS(r.mesh->vertices, expectedStrip(0.0));
    Positions out;
    for (int frame : {0, 6, 12, 24}) {
        r.animation.evaluate(r.mesh->vertices, frame, out);
        CELFORM_COMPARE_POSITIONS(out, expectedStrip(kPi / 2 * frame / 24.0));
    }
    r.animation.evaluate(r.mesh->vertices, 40, out); // after the end: held
    CELFORM_COMPARE_POSITIONS(out, expectedStrip(kPi / 2));
}

void TestAnimationIo::glbRoundTrip()
{
    QTemporaryDir dir;
    const GltfBuilder b = skinnedStrip(false);
    CELFORM_IMPORT_OR_FAIL(text, readAnimatedBase(b.write(dir, QStringLiteral("strip.gltf")), 30.0))
    const QString glb = b.write(dir, QStringLiteral("strip.glb"));
    QVERIFY(readBytes(glb).startsWith("glTF"));
    QVERIFY(isAnimatedBaseFile(glb));
    CELFORM_IMPORT_OR_FAIL(binary, readAnimatedBase(glb, 30.0))
    QCOMPARE(binary.animation.frameCount, 31);
    QVERIFY(*binary.mesh == *text.mesh);
    QVERIFY(binary.animation == text.animation);
}

void TestAnimationIo::morphWeightsLinear()
{
    QTemporaryDir dir;
    GltfBuilder b = morphTriangle();
    b.channel(0, "weights", {0, 1}, {0, 1}, TINYGLTF_TYPE_SCALAR);
    const QString path = b.write(dir, QStringLiteral("morph.gltf"));
    QVERIFY(isAnimatedBaseFile(path));
    CELFORM_IMPORT_OR_FAIL(r, readAnimatedBase(path))
    QCOMPARE(r.animation.frameCount, 25);
    QCOMPARE(r.animation.morphTargets.size(), std::size_t(1));
    QVERIFY(!r.animation.skinned()); // a morph alone needs no joints
    CELFORM_COMPARE_POSITIONS(r.mesh->vertices, triangleAt(1)); // the node's translation applied
    Positions out;
    Positions expected = triangleAt(1);
    expected.col(2).setConstant(0.5f);
    r.animation.evaluate(r.mesh->vertices, 12, out);
    CELFORM_COMPARE_POSITIONS(out, expected);
    expected.col(2).setConstant(1.0f);
    r.animation.evaluate(r.mesh->vertices, 24, out);
    CELFORM_COMPARE_POSITIONS(out, expected);

    // Without a channel the mesh's default weight holds at the one sample.
    GltfBuilder still = morphTriangle();
    still.m.meshes[0].weights = {0.25};
    CELFORM_IMPORT_OR_FAIL(s, readAnimatedBase(still.write(dir, QStringLiteral("still.gltf"))))
    QCOMPARE(s.animation.frameCount, 1);
    s.animation.evaluate(s.mesh->vertices, 0, out);
    expected.col(2).setConstant(0.25f);
    CELFORM_COMPARE_POSITIONS(out, expected);
}

void TestAnimationIo::stepAndCubicSpline_data()
{
    QTest::addColumn<QString>("interpolation");
    QTest::addColumn<QVector<float>>("values");
    QTest::addColumn<QVector<int>>("frames");
    QTest::addColumn<QVector<float>>("x");
    QTest::newRow("STEP") << "STEP" << QVector<float>{0, 0, 0, 2, 0, 0} << QVector<int>{0, 12, 23, 24}
                          << QVector<float>{0, 0, 0, 2};
    // Keys 0 at t = 0 (out-tangent 2 per second) and 1 at t = 1 (in-tangent 0): the Hermite
    // basis at u = 1/4 gives 0.140625 * 2 + 0.15625 * 1 = 0.4375, at u = 1/2 0.125 * 2 + 0.5 = 0.75.
    QTest::newRow("CUBICSPLINE") << "CUBICSPLINE"
                                 << QVector<float>{0, 0, 0, 0, 0, 0, 2, 0, 0, 0, 0, 0, 1, 0, 0, 5, 0, 0}
                                 << QVector<int>{0, 6, 12, 24} << QVector<float>{0, 0.4375f, 0.75f, 1};
}

void TestAnimationIo::stepAndCubicSpline()
{
    QFETCH(QString, interpolation);
    QFETCH(QVector<float>, values);
    QFETCH(QVector<int>, frames);
    QFETCH(QVector<float>, x);
    QTemporaryDir dir;
    const QString path
        = movingTriangle({0, 1}, std::vector<float>(values.begin(), values.end()), interpolation.toLatin1().constData())
              .write(dir, QStringLiteral("moving.gltf"));
    CELFORM_IMPORT_OR_FAIL(r, readAnimatedBase(path))
    QCOMPARE(r.animation.frameCount, 25);
    QVERIFY(r.animation.skinned()); // a moving unskinned node is one joint
    Positions out;
    for (int i = 0; i < frames.size(); ++i) {
        r.animation.evaluate(r.mesh->vertices, frames[i], out);
        CELFORM_COMPARE_POSITIONS(out, triangleAt(x[i]));
    }
}

void TestAnimationIo::sparseAndStride()
{
    // Positions interleaved with a 4-byte pad (byteStride 16), and a sparse morph target over an
    // accessor without a buffer view: only vertex 2 moves, by (0, 0, 3).
    GltfBuilder b;
    const int positions = b.floats({0, 0, 0, -1, 1, 0, 0, -1, 0, 1, 0, -1}, TINYGLTF_TYPE_VEC3);
    b.m.accessors[std::size_t(positions)].count = 3;
    b.m.bufferViews[std::size_t(b.m.accessors[std::size_t(positions)].bufferView)].byteStride = 16;
    const int mesh = b.mesh(positions, b.indices({0, 1, 2}));
    const int sparseIndices = b.indices({2});
    const int sparseValues = b.floats({0, 0, 3}, TINYGLTF_TYPE_VEC3);
    tinygltf::Accessor delta;
    delta.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    delta.type = TINYGLTF_TYPE_VEC3;
    delta.count = 3;
    delta.sparse.isSparse = true;
    delta.sparse.count = 1;
    delta.sparse.indices.bufferView = b.m.accessors[std::size_t(sparseIndices)].bufferView;
    delta.sparse.indices.byteOffset = 0;
    delta.sparse.indices.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
    delta.sparse.values.bufferView = b.m.accessors[std::size_t(sparseValues)].bufferView;
    delta.sparse.values.byteOffset = 0;
    b.m.accessors.push_back(delta);
    b.m.meshes[std::size_t(mesh)].primitives[0].targets.push_back({{"POSITION", int(b.m.accessors.size() - 1)}});
    b.m.meshes[std::size_t(mesh)].weights = {1.0};
    b.m.scenes[0].nodes = {b.node(mesh)};
    QTemporaryDir dir;
    CELFORM_IMPORT_OR_FAIL(r, readAnimatedBase(b.write(dir, QStringLiteral("sparse.gltf"))))
    CELFORM_COMPARE_POSITIONS(r.mesh->vertices, triangleAt(0));
    Positions out;
    r.animation.evaluate(r.mesh->vertices, 0, out);
    Positions expected = triangleAt(0);
    expected(2, 2) = 3;
    CELFORM_COMPARE_POSITIONS(out, expected);
}

// The documented vertex order: the scene's nodes depth first (the root's child before the next
// root), each node's primitives in order; strips and fans triangulated with glTF's winding;
// materials with a default one appended for a primitive without; UVs flipped to v up.
void TestAnimationIo::mergeOrder()
{
    GltfBuilder b;
    const int a = b.mesh(b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, TINYGLTF_TYPE_VEC3), b.indices({0, 1, 2}));
    tinygltf::Primitive& first = b.m.meshes[std::size_t(a)].primitives[0];
    first.material = 1;
    first.attributes["TEXCOORD_0"] = b.floats({0, 0, 1, 0, 0, 1}, TINYGLTF_TYPE_VEC2);
    tinygltf::Primitive strip;
    strip.attributes["POSITION"] = b.floats({0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1}, TINYGLTF_TYPE_VEC3);
    strip.mode = TINYGLTF_MODE_TRIANGLE_STRIP;
    b.m.meshes[std::size_t(a)].primitives.push_back(strip);
    const int fan = b.mesh(b.floats({0, 0, 2, 1, 0, 2, 1, 1, 2, 0, 1, 2}, TINYGLTF_TYPE_VEC3), -1);
    b.m.meshes[std::size_t(fan)].primitives[0].mode = TINYGLTF_MODE_TRIANGLE_FAN;
    b.m.meshes[std::size_t(fan)].primitives[0].material = 0;
    const int nodeB = b.node(fan);
    const int root = b.node();
    const int nodeA = b.node(a);
    b.m.nodes[std::size_t(root)].children = {nodeA};
    b.m.nodes[std::size_t(root)].translation = {0, 0, 5};
    b.m.scenes[0].nodes = {root, nodeB};
    b.m.materials.resize(2);
    b.m.materials[0].pbrMetallicRoughness.baseColorFactor = {1, 0, 0, 1};
    b.m.materials[1].pbrMetallicRoughness.baseColorFactor = {0, 0.5, 1, 1};
    QTemporaryDir dir;
    CELFORM_IMPORT_OR_FAIL(r, readAnimatedBase(b.write(dir, QStringLiteral("merge.gltf"))))
    QVERIFY(!isAnimatedBaseFile(dir.filePath(QStringLiteral("merge.gltf"))));
    Positions expected(11, 3);
    expected << 0, 0, 5, 1, 0, 5, 0, 1, 5, // node A, primitive 0, moved by the root
        0, 0, 6, 1, 0, 6, 0, 1, 6, 1, 1, 6, // node A, the strip
        0, 0, 2, 1, 0, 2, 1, 1, 2, 0, 1, 2; // node B, the fan
    CELFORM_COMPARE_POSITIONS(r.mesh->vertices, expected);
    celform::algo::Faces faces(5, 3);
    faces << 0, 1, 2, 3, 4, 5, 4, 6, 5, 8, 9, 7, 9, 10, 7;
    QCOMPARE(r.mesh->faces, faces);
    QCOMPARE(r.mesh->faceMaterials, (std::vector<std::int32_t>{1, 2, 2, 0, 0}));
    QCOMPARE(r.mesh->materials.size(), std::size_t(3));
    QCOMPARE(r.mesh->materials[1].baseColor, Eigen::Vector3f(0, 0.5f, 1));
    QVERIFY(r.mesh->hasUvs());
    QCOMPARE(r.mesh->uvs.rows(), 11);
    QCOMPARE(r.mesh->uvs.row(0), Eigen::RowVector2f(0, 1));
    QCOMPARE(r.mesh->uvs.row(2), Eigen::RowVector2f(0, 0));
    QCOMPARE(r.mesh->uvFaces, r.mesh->faces);
    QCOMPARE(r.animation.frameCount, 1);
    QVERIFY(!r.animation.skinned());
}

// An unskinned mesh under an animated node: its rest positions have the rest transforms applied,
// and it follows its parent (one joint: the global transform now times the inverse of the rest).
void TestAnimationIo::animatedParentMovesChild()
{
    GltfBuilder b;
    const int child = b.node(b.mesh(b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, TINYGLTF_TYPE_VEC3), b.indices({0, 1, 2})));
    b.m.nodes[std::size_t(child)].translation = {1, 0, 0};
    const int parent = b.node();
    b.m.nodes[std::size_t(parent)].children = {child};
    b.m.nodes[std::size_t(parent)].scale = {2, 2, 2};
    b.m.scenes[0].nodes = {parent};
    b.channel(parent, "translation", {0, 1}, {0, 0, 0, 0, 0, 3}, TINYGLTF_TYPE_VEC3);
    QTemporaryDir dir;
    CELFORM_IMPORT_OR_FAIL(r, readAnimatedBase(b.write(dir, QStringLiteral("parent.gltf"))))
    Positions rest(3, 3);
    rest << 2, 0, 0, 4, 0, 0, 2, 2, 0; // scaled by 2 after the child's translation
    CELFORM_COMPARE_POSITIONS(r.mesh->vertices, rest);
    Positions out;
    r.animation.evaluate(r.mesh->vertices, 12, out);
    Positions expected = rest;
    expected.col(2).setConstant(1.5f);
    CELFORM_COMPARE_POSITIONS(out, expected);
}

void TestAnimationIo::sequence_data()
{
    QTest::addColumn<QStringList>("files");
    QTest::addColumn<QString>("given");
    QTest::newRow("pattern") << QStringList{"walk_0001.obj", "walk_0002.obj", "walk_0003.obj"} << "walk_####.obj";
    QTest::newRow("middle file") << QStringList{"walk_0001.obj", "walk_0002.obj", "walk_0003.obj"} << "walk_0002.obj";
    QTest::newRow("unpadded, numeric order") << QStringList{"run9.obj", "run10.obj", "run11.obj"} << "run10.obj";
    QTest::newRow("PLY") << QStringList{"f.000.ply", "f.001.ply", "f.002.ply"} << "f.###.ply";
}

void TestAnimationIo::sequence()
{
    QFETCH(QStringList, files);
    QFETCH(QString, given);
    QTemporaryDir dir;
    Positions frame0(4, 3);
    frame0 << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
    Positions frame1 = frame0;
    frame1(2, 1) += 1.0f;
    Positions frame2 = frame0;
    frame2.col(2).array() += 0.5f;
    writeFile(dir, files[0], squareFrame(files[0], frame0));
    writeFile(dir, files[1], squareFrame(files[1], frame1));
    writeFile(dir, files[2], squareFrame(files[2], frame2));
    writeFile(dir, QStringLiteral("walk_notes.txt"), "not a frame");
    const QString path = dir.filePath(given);
    QVERIFY(isAnimatedBaseFile(path));
    CELFORM_IMPORT_OR_FAIL(r, readAnimatedBase(path, 12.0))
    QCOMPARE(r.fps, 12.0);
    QCOMPARE(r.animation.frameCount, 3);
    QCOMPARE(r.mesh->faceCount(), 2);
    CELFORM_COMPARE_POSITIONS(r.mesh->vertices, frame0);
    // Issue 27: stored as what it is, one position array per file (no morph targets).
    QVERIFY(r.animation.morphTargets.empty());
    QVERIFY(r.animation.morphWeights.empty());
    QCOMPARE(r.animation.storedFrameCount(4), Eigen::Index(3));
    CELFORM_COMPARE_POSITIONS(Positions(r.animation.vertexFrames.middleRows(4, 4)), frame1);
    QCOMPARE(r.animation.vertexFrameOfSample, (std::vector<std::int32_t>{0, 1, 2}));
    QVERIFY(r.animation.problem(4).empty());
    Positions out;
    r.animation.evaluate(r.mesh->vertices, 1, out);
    CELFORM_COMPARE_POSITIONS(out, frame1);
    r.animation.evaluate(r.mesh->vertices, 2, out);
    CELFORM_COMPARE_POSITIONS(out, frame2);
    QVERIFY_THROWS_EXCEPTION(IoError, readAnimatedBase(path, 0.0)); // no frame rate
}

// Issue 27: the file numbers are frames. Frames 1, 2, 4, 5 are five frames, number 3 holding number
// 2's shape, with a warning naming 3; they were closed up into four. A range beyond what Celform
// loads (walk_0000 and walk_9999999) is refused naming both numbers.
void TestAnimationIo::sequenceGaps()
{
    QTemporaryDir dir;
    Positions shape(4, 3);
    shape << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
    std::vector<Positions> shapes;
    for (int n : {1, 2, 4, 5}) {
        shapes.push_back(shape);
        shapes.back()(2, 2) = float(n);
        const QString name = QStringLiteral("walk_%1.obj").arg(n, 4, 10, QLatin1Char('0'));
        writeFile(dir, name, squareFrame(name, shapes.back()));
    }
    CELFORM_IMPORT_OR_FAIL(r, readAnimatedBase(dir.filePath(QStringLiteral("walk_####.obj")), 24.0))
    QCOMPARE(r.animation.frameCount, 5);
    QCOMPARE(r.warnings.size(), 1);
    QVERIFY2(r.warnings[0].contains(QStringLiteral("numbered 3;")), qPrintable(r.warnings[0]));
    Positions out;
    const int fileOfFrame[] = {0, 1, 1, 2, 3};
    for (int frame = 0; frame < 5; ++frame) {
        r.animation.evaluate(r.mesh->vertices, frame, out);
        CELFORM_COMPARE_POSITIONS(out, shapes[std::size_t(fileOfFrame[frame])]);
    }

    QTemporaryDir far;
    writeFile(far, QStringLiteral("walk_0000.obj"), squareFrame(QStringLiteral("walk_0000.obj"), shape));
    writeFile(far, QStringLiteral("walk_9999999.obj"), squareFrame(QStringLiteral("walk_9999999.obj"), shape));
    try {
        readAnimatedBase(far.filePath(QStringLiteral("walk_0000.obj")), 24.0);
        QFAIL("no IoError");
    } catch (const IoError& e) {
        QVERIFY2(e.problem().contains(QStringLiteral("from 0 to 9999999")), qPrintable(e.message()));
    }
}

// Issue 27, item 6: a sequence was one morph target per file with one-hot weights, so its weights
// grew with the square of its length (21,000 three-vertex frames made a 1.77 GB project). Now its
// memory and its project file are linear: 3,000 frames of 4 vertices hold 3,000 x 4 positions and
// one frame number per sample, and the project stays within a few bytes per coordinate.
void TestAnimationIo::sequenceMemoryIsLinear()
{
    QTemporaryDir dir;
    constexpr int kFrames = 3000;
    Positions shape(4, 3);
    shape << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
    for (int n = 0; n < kFrames; ++n) {
        shape(2, 2) = float(n) * 0.001f;
        const QString name = QStringLiteral("long_%1.obj").arg(n, 5, 10, QLatin1Char('0'));
        writeFile(dir, name, squareFrame(name, shape));
    }
    CELFORM_IMPORT_OR_FAIL(r, readAnimatedBase(dir.filePath(QStringLiteral("long_#####.obj")), 24.0))
    QCOMPARE(r.animation.frameCount, kFrames);
    QCOMPARE(r.animation.vertexFrames.rows(), Eigen::Index(kFrames) * 4);
    QCOMPARE(r.animation.vertexFrameOfSample.size(), std::size_t(kFrames));
    QVERIFY(r.animation.morphWeights.empty());
    Positions out;
    r.animation.evaluate(r.mesh->vertices, 1234, out);
    QCOMPARE(out(2, 2), 1234 * 0.001f);

    // One-hot weights would be kFrames^2 floats (36 MB) in the file alone; the positions are
    // kFrames x 4 x 12 bytes (144 KB) and the frame numbers 12 KB.
    const QString project = dir.filePath(QStringLiteral("long.celform"));
    const ProjectData data = newAnimatedProject(std::move(r), QStringLiteral("long_#####.obj"));
    saveProject(data, project);
    const qint64 size = QFileInfo(project).size();
    QVERIFY2(size < 400 * 1024, qPrintable(QStringLiteral("%1 bytes").arg(size)));
    const ProjectData read = loadProject(project);
    QVERIFY(read.baseAnimation && *read.baseAnimation == *data.baseAnimation);
}

void TestAnimationIo::sequenceMismatch_data()
{
    QTest::addColumn<QByteArray>("third");
    QTest::addColumn<QString>("problem");
    QTest::newRow("vertex count") << QByteArray("v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n")
                                  << "3 vertices, the first frame (walk_0001.obj) has 4";
    QTest::newRow("faces") << QByteArray("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 4 3\n")
                           << "triangle 1 is (0, 1, 3), the first frame's (walk_0001.obj) is (0, 1, 2)";
    QTest::newRow("unreadable") << QByteArray("v 0 0 0\nv 1 0 nan\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n") << "vertex 2";
}

void TestAnimationIo::sequenceMismatch()
{
    QFETCH(QByteArray, third);
    QFETCH(QString, problem);
    QTemporaryDir dir;
    const QByteArray square = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
    writeFile(dir, QStringLiteral("walk_0001.obj"), square);
    writeFile(dir, QStringLiteral("walk_0002.obj"), square);
    const QString bad = writeFile(dir, QStringLiteral("walk_0003.obj"), third);
    writeFile(dir, QStringLiteral("walk_0004.obj"), square);
    QString message;
    QVERIFY2(refused(dir.filePath(QStringLiteral("walk_####.obj")), bad, problem, message), qPrintable(message));
}

void TestAnimationIo::badFiles_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<QString>("problem");
    QTemporaryDir dir;
    const auto bytesOf
        = [&](const GltfBuilder& b, const char* name) { return readBytes(b.write(dir, QLatin1String(name))); };

    QTest::newRow("empty") << "empty.gltf" << QByteArray() << "empty";
    QTest::newRow("malformed JSON") << "bad.gltf" << QByteArray("{\"asset\": {\"version\": \"2.0\"}, \"nodes\": [")
                                    << "not a readable glTF file";
    const QByteArray glb = bytesOf(skinnedStrip(false), "strip.glb");
    QTest::newRow("truncated GLB") << "cut.glb" << glb.left(glb.size() / 2) << "not a readable glTF file";
    const QByteArray gltf = bytesOf(skinnedStrip(false), "strip.gltf");
    QTest::newRow("truncated glTF") << "cut.gltf" << gltf.left(gltf.size() - 40) << "not a readable glTF file";

    GltfBuilder range = skinnedStrip(false);
    range.m.accessors[0].count = 7; // six positions in the view
    QTest::newRow("accessor out of range") << "range.gltf" << bytesOf(range, "r.gltf") << "cannot fit in buffer view";
    GltfBuilder huge = skinnedStrip(false);
    huge.m.accessors[0].count = 4000000000u;
    QTest::newRow("huge count") << "huge.gltf" << bytesOf(huge, "h.gltf") << "4000000000 elements";
    GltfBuilder noView = skinnedStrip(false);
    noView.m.accessors[0].bufferView = -1;
    noView.m.accessors[0].count = 4000000000u;
    QTest::newRow("huge count without data") << "noview.gltf" << bytesOf(noView, "n.gltf") << "without a buffer view";

    GltfBuilder nan = morphTriangle();
    const float qnan = std::numeric_limits<float>::quiet_NaN();
    const int nanPositions = nan.m.meshes[0].primitives[0].attributes["POSITION"];
    const auto& nanView = nan.m.bufferViews[std::size_t(nan.m.accessors[std::size_t(nanPositions)].bufferView)];
    std::memcpy(nan.m.buffers[0].data.data() + nanView.byteOffset + 4, &qnan, 4); // vertex 0's y
    QTest::newRow("NaN position") << "nan.gltf" << bytesOf(nan, "nan.gltf") << "vertex 0 has a coordinate";

    GltfBuilder joint = skinnedStrip(false);
    const auto& jointView = joint.m.bufferViews[std::size_t(
        joint.m.accessors[std::size_t(joint.m.meshes[0].primitives[0].attributes["JOINTS_0"])].bufferView)];
    joint.m.buffers[0].data[jointView.byteOffset + 4 * 5] = 7; // vertex 5 names joint 7 of 2
    QTest::newRow("joint out of range") << "joint.gltf" << bytesOf(joint, "j.gltf")
                                        << "names joint 7, but the skin has 2";

    GltfBuilder weights = skinnedStrip(false);
    weights.m.accessors[std::size_t(weights.m.meshes[0].primitives[0].attributes["WEIGHTS_0"])].count = 4;
    QTest::newRow("weights count") << "weights.gltf" << bytesOf(weights, "w.gltf") << "give 6 and 4 vertices";

    GltfBuilder morphWeights = morphTriangle();
    morphWeights.m.meshes[0].weights = {0.5, 0.5};
    QTest::newRow("morph weights count") << "mw.gltf" << bytesOf(morphWeights, "mw.gltf") << "gives 2 morph weights";

    GltfBuilder points = morphTriangle();
    points.m.meshes[0].primitives[0].mode = TINYGLTF_MODE_POINTS;
    QTest::newRow("no triangles") << "points.gltf" << bytesOf(points, "p.gltf") << "no triangle primitive";

    GltfBuilder keys = movingTriangle({0, 1}, {0, 0, 0}, "LINEAR");
    QTest::newRow("sampler output count") << "keys.gltf" << bytesOf(keys, "k.gltf") << "has 3 output values for 2 keys";

    GltfBuilder cycle = morphTriangle();
    cycle.m.nodes.resize(2);
    cycle.m.nodes[0].children = {1};
    cycle.m.nodes[1].children = {0};
    QTest::newRow("node cycle") << "cycle.gltf" << bytesOf(cycle, "c.gltf") << "cycle";

    // Issue 27, item 8: sampler times must increase strictly (glTF 2.0, 3.11), not merely not fall.
    GltfBuilder repeated = movingTriangle({0.5f, 0.5f, 0.5f}, {0, 0, 0, 1, 0, 0, 2, 0, 0}, "LINEAR");
    QTest::newRow("repeated sampler times")
        << "same.gltf" << bytesOf(repeated, "s.gltf") << "key 1 has time 0.5, not after the key before it";
    GltfBuilder endless = movingTriangle({0, 1e30f}, {0, 0, 0, 1, 0, 0}, "LINEAR");
    QTest::newRow("endless animation") << "forever.gltf" << bytesOf(endless, "f.gltf") << "frames Celform can load";
    GltfBuilder draco = morphTriangle();
    draco.m.extensionsUsed = {"KHR_draco_mesh_compression"};
    draco.m.extensionsRequired = {"KHR_draco_mesh_compression"};
    QTest::newRow("compressed") << "draco.gltf" << bytesOf(draco, "d.gltf") << "KHR_draco_mesh_compression";
    QTest::newRow("deeply nested JSON") << "deep.gltf" << QByteArray(200000, '[') << "nested more than 100 levels";
    QTest::newRow("deep balanced JSON") << "deep2.gltf" << QByteArray(100000, '[') + QByteArray(100000, ']')
                                        << "nested more than 100 levels";
    QTest::newRow("deep extras") << "extras.gltf"
                                 << R"({"asset":{"version":"2.0","extras":)" + QByteArray(100000, '[')
            + QByteArray(100000, ']') + "}}"
                                 << "nested more than 100 levels";
    QTest::newRow("no numbered file") << "plain.obj" << QByteArray("v 0 0 0\n") << "not an animated base";
}

void TestAnimationIo::badFiles()
{
    QFETCH(QString, name);
    QFETCH(QByteArray, bytes);
    QFETCH(QString, problem);
    QTemporaryDir dir;
    const QString path = writeFile(dir, name, bytes);
    QString message;
    QVERIFY2(refused(path, path, problem, message), qPrintable(message));
    qInfo("%s", qPrintable(message));
    // A missing file is named too.
    const QString missing = dir.filePath(QStringLiteral("missing.glb"));
    QVERIFY(!isAnimatedBaseFile(missing));
    QVERIFY_THROWS_EXCEPTION(IoError, readAnimatedBase(missing));
}

void TestAnimationIo::buffersAreRegularFiles_data()
{
    celform::test::addBufferUriRows();
    QTest::newRow("missing") << "absent.bin";
}

// As for importMesh: a buffer naming a FIFO would block the read for ever, /dev/zero
// would be read without end. Only regular files are opened.
void TestAnimationIo::buffersAreRegularFiles()
{
    QFETCH(QString, uri);
    QTemporaryDir dir;
    QVERIFY(celform::test::makeBufferTargets(dir));
    const QByteArray json = celform::test::gltfWithBufferUri(uri);
    const QString path = writeFile(dir, QStringLiteral("buffer.gltf"), json);
    QString message;
    QVERIFY2(refused(path, path, QStringLiteral("not a readable glTF file"), message), qPrintable(message));
}

// The glTF files the repository holds (static ones: one sample, no joints), and the fuzz
// regression of 30,000 nested nodes, which must not take the stack.
void TestAnimationIo::realFiles()
{
    for (const char* relative : {"fuzz-corpus/glb/cube.glb", "fuzz-corpus/gltf/cube.gltf"}) {
        const QString path = celform::test::testDataPath(QLatin1String(relative));
        QVERIFY(!isAnimatedBaseFile(path));
        CELFORM_IMPORT_OR_FAIL(r, readAnimatedBase(path))
        QCOMPARE(r.animation.frameCount, 1);
        QVERIFY(r.mesh->faceCount() >= 12);
        QVERIFY(r.animation.problem(r.mesh->vertexCount()).empty());
    }
    const QString nested = celform::test::testDataPath(
        QStringLiteral("fuzz-regressions/mesh/gltf-30000-nested-nodes-stack-overflow.gltf"));
    try {
        const AnimatedImport r = readAnimatedBase(nested);
        QVERIFY(r.mesh->faceCount() > 0);
    } catch (const IoError& e) {
        QCOMPARE(e.file(), nested);
        qInfo("%s", qPrintable(e.problem()));
    }
}

QTEST_GUILESS_MAIN(TestAnimationIo)
#include "test_animation_io.moc"
