// `celform export` run as a user runs it: a PC2 cache whose every frame is
// the shape `celform eval --frame F` writes, an OBJ per frame, glTF files read back (targets,
// samples, weights against `celform eval --json`) and passed by the Khronos glTF Validator, and
// the exit codes of bad options and unwritable files; USD layers read by TinyUSDZ (npm package
// tinyusdz) and their time samples, read from the text, against `celform eval`.
#include "cli_run.h"
#include "test_meshes.h"

#include "celform/model/export/export.h"
#include "celform/model/io/mesh_io.h"
#include "celform/model/io/project_file.h"

#include <tiny_gltf.h>

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <Eigen/Geometry>

#include <charconv>
#include <cstring>

using namespace celform;

namespace {

constexpr int kFrames = 12; // the turntable's revolution, and the project's range

/// The PC2 file as read back: header fields and the positions of every sample.
struct Pc2 {
    char signature[12] = {};
    std::int32_t version = 0, points = 0, samples = 0;
    float startFrame = 0, sampleRate = 0;
    std::vector<float> positions;
    qint64 size = 0;
};

Pc2 readPc2(const QString& path)
{
    QFile f(path);
    Pc2 p;
    if (!f.open(QIODevice::ReadOnly))
        return p;
    const QByteArray bytes = f.readAll();
    p.size = bytes.size();
    if (bytes.size() < 32)
        return p;
    const char* d = bytes.constData();
    std::memcpy(p.signature, d, 12);
    std::memcpy(&p.version, d + 12, 4);
    std::memcpy(&p.points, d + 16, 4);
    std::memcpy(&p.startFrame, d + 20, 4);
    std::memcpy(&p.sampleRate, d + 24, 4);
    std::memcpy(&p.samples, d + 28, 4);
    p.positions.resize(std::size_t(bytes.size() - 32) / 4);
    std::memcpy(p.positions.data(), d + 32, p.positions.size() * 4);
    return p;
}

/// The accessor's floats.
std::vector<float> floats(const tinygltf::Model& m, int accessor)
{
    const tinygltf::Accessor& a = m.accessors[std::size_t(accessor)];
    const tinygltf::BufferView& v = m.bufferViews[std::size_t(a.bufferView)];
    const int components = tinygltf::GetNumComponentsInType(std::uint32_t(a.type));
    std::vector<float> out(a.count * std::size_t(components));
    std::memcpy(out.data(), m.buffers[std::size_t(v.buffer)].data.data() + v.byteOffset + a.byteOffset,
        out.size() * sizeof(float));
    return out;
}

/// A glTF file read back, or an empty model (with a failure message) when it cannot be.
tinygltf::Model loadGltf(const QString& path, std::string& err)
{
    tinygltf::TinyGLTF loader;
    tinygltf::Model m;
    std::string warn;
    const bool ok = path.endsWith(QLatin1String(".glb"))
        ? loader.LoadBinaryFromFile(&m, &err, &warn, path.toStdString())
        : loader.LoadASCIIFromFile(&m, &err, &warn, path.toStdString());
    if (!ok)
        m = tinygltf::Model{};
    return m;
}

/// The sampler output of the animation channel with this target path, empty when none.
std::vector<float> channelOutput(const tinygltf::Model& m, const char* path)
{
    for (const tinygltf::AnimationChannel& c : m.animations.at(0).channels)
        if (c.target_path == path)
            return floats(m, m.animations[0].samplers[std::size_t(c.sampler)].output);
    return {};
}

/// The largest difference between the shape a glTF viewer shows at each sampled frame (base
/// POSITION plus every target times its animated weight) and the PC2 cache's frames. The file
/// has no UV seams (its vertices are the base's, in order).
double gltfAgainstCache(const tinygltf::Model& m, const Pc2& pc2)
{
    const tinygltf::Primitive& p = m.meshes.at(0).primitives.at(0);
    const std::vector<float> base = floats(m, p.attributes.at("POSITION"));
    std::vector<std::vector<float>> targets;
    for (const auto& t : p.targets)
        targets.push_back(floats(m, t.at("POSITION")));
    const std::vector<float> weights = channelOutput(m, "weights");
    const std::size_t count = base.size();
    double worst = 0.0;
    for (std::size_t f = 0; f < std::size_t(pc2.samples); ++f)
        for (std::size_t i = 0; i < count; ++i) {
            double x = base[i];
            for (std::size_t t = 0; t < targets.size(); ++t)
                x += double(weights[f * targets.size() + t]) * targets[t][i];
            worst = std::max(worst, std::abs(x - pc2.positions[f * count + i]));
        }
    return worst;
}

/// Where the npm packages are: the environment's CELFORM_GLTF_VALIDATOR_PREFIX, else
/// build/tools in the checkout (scripts/setup.sh installs the validator and tinyusdz there).
QString validatorPrefix()
{
    const QString env = qEnvironmentVariable("CELFORM_GLTF_VALIDATOR_PREFIX");
    return env.isEmpty() ? QStringLiteral(CELFORM_SOURCE_DIR "/build/tools") : env;
}

/// The numbers of a USDA value starting at text[at] (an array of tuples, a tuple or a number) up
/// to the end of its line.
std::vector<float> usdaNumbers(const QByteArray& text, qsizetype at)
{
    std::vector<float> out;
    const char* p = text.constData() + at;
    const char* end = text.constData() + text.size();
    while (p < end && *p != '\n') {
        if ((*p >= '0' && *p <= '9') || *p == '-' || *p == '.') {
            float v = 0;
            const auto r = std::from_chars(p, end, v);
            if (r.ec != std::errc())
                return {};
            out.push_back(v);
            p = r.ptr;
        } else
            ++p;
    }
    return out;
}

/// The value of an attribute's sample at a frame: the numbers of the line "F: ..." inside the
/// block "<declaration>.timeSamples = {". Empty when there is none.
std::vector<float> usdaSample(const QByteArray& text, const char* declaration, int frame)
{
    const qsizetype block = text.indexOf(QByteArray(declaration) + ".timeSamples = {\n");
    if (block < 0)
        return {};
    const qsizetype close = text.indexOf("\n", block);
    const QByteArray key = ' ' + QByteArray::number(frame) + ": ";
    for (qsizetype line = close + 1; line < text.size();) {
        const qsizetype next = text.indexOf('\n', line);
        const QByteArray head = text.mid(line, std::min<qsizetype>(next - line, 64)).trimmed();
        if (head.startsWith('}'))
            return {};
        if ((' ' + head).startsWith(key))
            return usdaNumbers(text, line + text.mid(line, next - line).indexOf(':') + 1);
        line = next + 1;
    }
    return {};
}

/// The numbers of an attribute's default value: "<declaration> = ...".
std::vector<float> usdaValue(const QByteArray& text, const QByteArray& declaration, qsizetype from = 0)
{
    const qsizetype at = text.indexOf(declaration + " = ", from);
    return at < 0 ? std::vector<float>{} : usdaNumbers(text, at + declaration.size() + 3);
}

QByteArray readAll(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

} // namespace

class TestExport : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        // A sphere with two keys pulled in different directions, on a 12-frame turntable.
        algo::TriMesh sphere = *test::icosphere(2);
        const QString mesh = m_dir.filePath(QStringLiteral("sphere.obj"));
        model::exportMesh(sphere, mesh);
        m_project = m_dir.filePath(QStringLiteral("two_keys.celform"));
        auto run = [](const QStringList& args) {
            const Run r = runCelform(args);
            if (r.exitCode != 0)
                qWarning() << args << r.err;
            return r.exitCode;
        };
        QCOMPARE(run({"new", mesh, "--out", m_project}), 0);
        QCOMPARE(run({"key", "add", m_project, "--name", "side", "--from-base", "--view", "1,0,0"}), 0);
        QCOMPARE(run({"key", "add", m_project, "--name", "front", "--from-base", "--view", "0,0,1"}), 0);
        QCOMPARE(
            run({"brush", m_project, "--key", "side", "--vertex", "3", "--radius", "0.6", "--drag", "0.1,0.2"}), 0);
        QCOMPARE(run({"brush", m_project, "--key", "front", "--vertex", "7", "--radius", "0.6", "--push", "-0.15"}), 0);
        QCOMPARE(run({"camera", m_project, "--turntable", QString::number(kFrames)}), 0);
        m_vertices = int(sphere.vertexCount());
    }

    void pc2MatchesEvalAtEveryFrame()
    {
        const QString out = m_dir.filePath(QStringLiteral("shot.pc2"));
        const Run r = runCelform({"export", m_project, "--format", "pc2", "--out", out, "--json"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonObject json = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QCOMPARE(json.value("frames").toInt(), kFrames);
        const Pc2 pc2 = readPc2(out);
        QCOMPARE(QByteArray(pc2.signature, 12), QByteArray("POINTCACHE2\0", 12));
        QCOMPARE(pc2.version, 1);
        QCOMPARE(pc2.points, m_vertices);
        QCOMPARE(pc2.startFrame, 0.0f);
        QCOMPARE(pc2.sampleRate, 1.0f);
        QCOMPARE(pc2.samples, kFrames);
        QCOMPARE(pc2.size, 32 + qint64(kFrames) * m_vertices * 12);
        bool moved = false;
        for (int f = 0; f < kFrames; ++f) {
            const QString obj = m_dir.filePath(QStringLiteral("eval_%1.obj").arg(f));
            const Run e = runCelform({"eval", m_project, "--frame", QString::number(f), "--out", obj});
            QVERIFY2(e.exitCode == 0, qPrintable(e.err));
            const algo::TriMesh evaluated = model::importMesh(obj, model::ImportIsolation::ThisProcess).mesh;
            QCOMPARE(int(evaluated.vertexCount()), m_vertices);
            double worst = 0.0;
            for (int v = 0; v < m_vertices; ++v)
                for (int c = 0; c < 3; ++c) {
                    const float cached = pc2.positions[(std::size_t(f) * std::size_t(m_vertices) + std::size_t(v)) * 3
                        + std::size_t(c)];
                    worst = std::max(worst, double(std::abs(cached - evaluated.vertices(v, c))));
                    if (f > 0)
                        moved = moved || cached != pc2.positions[std::size_t(v) * 3 + std::size_t(c)];
                }
            QVERIFY2(worst <= 1e-6, qPrintable(QStringLiteral("frame %1 differs by %2").arg(f).arg(worst)));
        }
        QVERIFY2(moved, "the turntable should change the blended shape between frames");
    }

    void objSequence()
    {
        QDir(m_dir.path()).mkpath(QStringLiteral("seq"));
        const QString pattern = m_dir.filePath(QStringLiteral("seq/shot_###.obj"));
        const Run r = runCelform({"export", m_project, "--format", "obj-seq", "--frames", "2-5", "--out", pattern});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QStringList files = QDir(m_dir.filePath(QStringLiteral("seq"))).entryList(QDir::Files, QDir::Name);
        QCOMPARE(files, (QStringList{"shot_002.obj", "shot_003.obj", "shot_004.obj", "shot_005.obj"}));
        const QString obj = m_dir.filePath(QStringLiteral("eval_seq.obj"));
        QCOMPARE(runCelform({"eval", m_project, "--frame", "4", "--out", obj}).exitCode, 0);
        QFile a(m_dir.filePath(QStringLiteral("seq/shot_004.obj"))), b(obj);
        QVERIFY(a.open(QIODevice::ReadOnly) && b.open(QIODevice::ReadOnly));
        QCOMPARE(a.readAll(), b.readAll());

        // Without #, _FFFF goes before the suffix.
        const Run plain = runCelform({"export", m_project, "--format", "obj-seq", "--frames", "0-1", "--out",
            m_dir.filePath(QStringLiteral("seq/take.obj"))});
        QVERIFY2(plain.exitCode == 0, qPrintable(plain.err));
        QVERIFY(QFile::exists(m_dir.filePath(QStringLiteral("seq/take_0000.obj"))));
        QVERIFY(QFile::exists(m_dir.filePath(QStringLiteral("seq/take_0001.obj"))));
    }

    void gltfReadsBack_data()
    {
        QTest::addColumn<QString>("format");
        QTest::newRow("gltf") << "gltf";
        QTest::newRow("glb") << "glb";
    }

    void gltfReadsBack()
    {
        QFETCH(QString, format);
        const QString out = m_dir.filePath(QStringLiteral("shot.") + format);
        const Run r = runCelform({"export", m_project, "--format", format, "--out", out});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));

        std::string err;
        const tinygltf::Model m = loadGltf(out, err);
        QVERIFY2(!m.meshes.empty(), err.c_str());
        QCOMPARE(m.meshes.size(), std::size_t(1));
        const tinygltf::Primitive& primitive = m.meshes[0].primitives.at(0);
        QCOMPARE(primitive.targets.size(), std::size_t(2)); // the two enabled keys
        const tinygltf::Value& names = m.meshes[0].extras.Get("targetNames");
        QCOMPARE(names.ArrayLen(), std::size_t(2));
        QCOMPARE(m.cameras.size(), std::size_t(1));
        QCOMPARE(m.animations.size(), std::size_t(1));
        const tinygltf::Animation& animation = m.animations[0];
        int weightsSampler = -1;
        for (const tinygltf::AnimationChannel& c : animation.channels)
            if (c.target_path == "weights")
                weightsSampler = c.sampler;
        QVERIFY(weightsSampler >= 0);
        for (const tinygltf::AnimationSampler& s : animation.samplers)
            QCOMPARE(int(m.accessors[std::size_t(s.input)].count), kFrames);
        const std::vector<float> weights = floats(m, animation.samplers[std::size_t(weightsSampler)].output);
        QCOMPARE(int(weights.size()), kFrames * 2);
        for (int f : {0, 3, 7}) {
            const Run e = runCelform({"eval", m_project, "--frame", QString::number(f), "--json"});
            QVERIFY2(e.exitCode == 0, qPrintable(e.err));
            const QJsonArray keys = QJsonDocument::fromJson(e.out.toUtf8()).object().value("keys").toArray();
            for (std::size_t t = 0; t < 2; ++t) {
                double expected = 0.0;
                for (const QJsonValue& k : keys)
                    if (k.toObject().value("key").toString().toStdString() == names.Get(int(t)).Get<std::string>())
                        expected = k.toObject().value("weight").toDouble();
                QVERIFY2(std::abs(weights[std::size_t(f) * 2 + t] - expected) <= 1e-5,
                    qPrintable(QStringLiteral("frame %1 target %2: %3 against eval's %4")
                                   .arg(f)
                                   .arg(t)
                                   .arg(weights[std::size_t(f) * 2 + t])
                                   .arg(expected)));
            }
        }
        // The camera node looks down its -Z at the sphere's centre (the turntable's target).
        const std::vector<float> eyes = channelOutput(m, "translation");
        const std::vector<float> turns = channelOutput(m, "rotation");
        QCOMPARE(int(eyes.size()), kFrames * 3);
        for (int f = 0; f < kFrames; ++f) {
            const Eigen::Quaternionf q(turns[std::size_t(f) * 4 + 3], turns[std::size_t(f) * 4],
                turns[std::size_t(f) * 4 + 1], turns[std::size_t(f) * 4 + 2]);
            const Eigen::Vector3f eye(
                eyes[std::size_t(f) * 3], eyes[std::size_t(f) * 3 + 1], eyes[std::size_t(f) * 3 + 2]);
            QVERIFY((q * Eigen::Vector3f(0, 0, -1)).dot(-eye.normalized()) > 0.999f);
        }
        // What a viewer shows is the shape Celform evaluates (the keys are keyed at one frame).
        const QString cache = m_dir.filePath(QStringLiteral("compare.pc2"));
        QCOMPARE(runCelform({"export", m_project, "--format", "pc2", "--out", cache}).exitCode, 0);
        const double worst = gltfAgainstCache(m, readPc2(cache));
        QVERIFY2(worst < 1e-5, qPrintable(QString::number(worst)));
        validate(out);
    }

    void animatedBaseRidesInTheWeights()
    {
        // A base moved by one morph target over six frames, and a key; seen from a turntable.
        auto mesh = test::icosphere(1);
        model::ProjectData data = model::newProject(mesh, QStringLiteral("sphere.obj"));
        model::KeyViewpoint key;
        key.id = data.nextId++;
        key.name = QStringLiteral("side");
        key.direction = Eigen::Vector3d::UnitX();
        key.camera.eye = Eigen::Vector3d(5, 0, 0);
        key.offsetsByFrame[0].indices = {0, 5};
        key.offsetsByFrame[0].deltas = {Eigen::Vector3f(0.2f, 0, 0), Eigen::Vector3f(0, 0.3f, 0)};
        data.keys.push_back(key);
        auto animation = std::make_shared<algo::BaseAnimation>();
        animation->firstFrame = 0;
        animation->frameCount = 6;
        algo::Positions stretch = mesh->vertices;
        stretch.col(0).setZero();
        stretch.col(2).setZero(); // stretched along y
        animation->morphTargets = {stretch};
        animation->morphWeights = {0.0f, 0.2f, 0.4f, 0.6f, 0.8f, 1.0f};
        data.baseAnimation = animation;
        model::Turntable turntable;
        turntable.frames = 6;
        data.look.cameraPath = model::turntablePath(turntable, Eigen::Vector3d::Zero(), 6.0, model::Camera{});
        data.time.lastFrame = 5;

        model::ExportJob job;
        job.lastFrame = 5;
        job.format = model::ExportFormat::Pc2;
        job.output = m_dir.filePath(QStringLiteral("animated.pc2"));
        QCOMPARE(model::exportProject(data, QStringLiteral("animated"), job).frames, 6);
        job.format = model::ExportFormat::Glb;
        job.output = m_dir.filePath(QStringLiteral("animated.glb"));
        const model::ExportResult result = model::exportProject(data, QStringLiteral("animated"), job);
        QVERIFY(result.warnings.isEmpty()); // morph targets only: nothing lost
        std::string err;
        const tinygltf::Model m = loadGltf(job.output, err);
        QVERIFY2(!m.meshes.empty(), err.c_str());
        QCOMPARE(m.meshes[0].primitives[0].targets.size(), std::size_t(2)); // the key, then the base's target
        QCOMPARE(m.meshes[0].extras.Get("targetNames").Get(1).Get<std::string>(), std::string("base:0"));
        const Pc2 pc2 = readPc2(m_dir.filePath(QStringLiteral("animated.pc2")));
        const double worst = gltfAgainstCache(m, pc2);
        QVERIFY2(worst < 1e-5, qPrintable(QString::number(worst)));
        validate(job.output);

        // A vertex sequence (issue 27: stored frames, no morph targets of its own): each stored
        // frame becomes a target weighted 1 where it is shown, and the glTF plays as the cache.
        auto sequence = std::make_shared<algo::BaseAnimation>();
        sequence->frameCount = 6;
        sequence->vertexFrames.resize(3 * mesh->vertexCount(), 3);
        for (Eigen::Index k = 0; k < 3; ++k)
            sequence->vertexFrames.middleRows(k * mesh->vertexCount(), mesh->vertexCount())
                = mesh->vertices * (1.0f + 0.1f * float(k));
        sequence->vertexFrameOfSample = {0, 1, 1, 2, 2, 0};
        QVERIFY(sequence->problem(mesh->vertexCount()).empty());
        data.baseAnimation = sequence;
        job.format = model::ExportFormat::Pc2;
        job.output = m_dir.filePath(QStringLiteral("sequence.pc2"));
        QCOMPARE(model::exportProject(data, QStringLiteral("sequence"), job).frames, 6);
        job.format = model::ExportFormat::Glb;
        job.output = m_dir.filePath(QStringLiteral("sequence.glb"));
        QVERIFY(model::exportProject(data, QStringLiteral("sequence"), job).warnings.isEmpty());
        const tinygltf::Model seq = loadGltf(job.output, err);
        QVERIFY2(!seq.meshes.empty(), err.c_str());
        QCOMPARE(seq.meshes[0].primitives[0].targets.size(), std::size_t(4)); // the key, then 3 stored frames
        QCOMPARE(seq.meshes[0].extras.Get("targetNames").Get(3).Get<std::string>(), std::string("base:frame:2"));
        const double seqWorst = gltfAgainstCache(seq, readPc2(m_dir.filePath(QStringLiteral("sequence.pc2"))));
        QVERIFY2(seqWorst < 1e-5, qPrintable(QString::number(seqWorst)));
        validate(job.output);
        data.baseAnimation = animation;
        job.format = model::ExportFormat::Glb;
        job.output = m_dir.filePath(QStringLiteral("animated.glb"));

        // A skinned base: glTF says what it leaves out.
        auto skinned = std::make_shared<algo::BaseAnimation>(*animation);
        skinned->jointCount = 1;
        skinned->joints.assign(std::size_t(mesh->vertexCount()), {0, 0, 0, 0});
        skinned->jointWeights.assign(std::size_t(mesh->vertexCount()), Eigen::Vector4f(1, 0, 0, 0));
        skinned->skinMatrices.assign(6, algo::SkinMatrix::Identity());
        data.baseAnimation = skinned;
        QVERIFY(data.baseAnimation->problem(mesh->vertexCount()).empty());
        QCOMPARE(model::exportProject(data, QStringLiteral("animated"), job).warnings.size(), 1);
    }

    void usdaOfTheSampleTurntableMatchesEval()
    {
        // The bundled sample on a short turntable: TinyUSDZ reads the layer, and the points of
        // every frame are the shape `celform eval --frame F` writes, float for float.
        const QString p = m_dir.filePath(QStringLiteral("sample.celform"));
        QVERIFY(QFile::copy(QStringLiteral(CELFORM_SOURCE_DIR "/resources/samples/elephant.celform"), p));
        QFile::setPermissions(p, QFile::ReadOwner | QFile::WriteOwner);
        QCOMPARE(runCelform({"camera", p, "--turntable", "3"}).exitCode, 0);
        const QString out = m_dir.filePath(QStringLiteral("sample.usda"));
        const Run r = runCelform({"export", p, "--format", "usda", "--out", out, "--json"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(QJsonDocument::fromJson(r.out.toUtf8()).object().value("frames").toInt(), 3);
        const QByteArray text = readAll(out);
        QVERIFY(text.startsWith("#usda 1.0\n"));
        for (const char* metadata : {"upAxis = \"Y\"", "metersPerUnit = 1", "timeCodesPerSecond = 24",
                 "startTimeCode = 0", "endTimeCode = 2", "def Camera \"camera\"", "normal3f[] normals.timeSamples"})
            QVERIFY2(text.contains(metadata), metadata);
        std::size_t faces = 0;
        for (int f = 0; f < 3; ++f) {
            const QString obj = m_dir.filePath(QStringLiteral("sample_eval_%1.obj").arg(f));
            const Run e = runCelform({"eval", p, "--frame", QString::number(f), "--out", obj});
            QVERIFY2(e.exitCode == 0, qPrintable(e.err));
            const algo::TriMesh evaluated = model::importMesh(obj, model::ImportIsolation::ThisProcess).mesh;
            faces = std::size_t(evaluated.faceCount());
            const std::vector<float> points = usdaSample(text, "point3f[] points", f);
            QCOMPARE(points.size(), std::size_t(evaluated.vertices.size()));
            for (std::size_t i = 0; i < points.size(); ++i)
                QVERIFY2(points[i] == evaluated.vertices.data()[i],
                    qPrintable(QStringLiteral("frame %1 value %2: %3 against eval's %4")
                                   .arg(f)
                                   .arg(i)
                                   .arg(points[i])
                                   .arg(evaluated.vertices.data()[i])));
            // The camera: a transform and a lens at every frame.
            QCOMPARE(usdaSample(text, "matrix4d xformOp:transform", f).size(), std::size_t(16));
            QCOMPARE(usdaSample(text, "float focalLength", f).size(), std::size_t(1));
        }
        QCOMPARE(usdaValue(text, "int[] faceVertexIndices").size(), faces * 3);
        QVERIFY(usdaSample(text, "point3f[] points", 0) != usdaSample(text, "point3f[] points", 1));
        QVERIFY(usdaSample(text, "point3f[] points", 3).empty());
        QString report;
        readUsd(out, &report);
        QVERIFY2(report.contains(QStringLiteral("faceVertexIndices %1").arg(faces * 3)), qPrintable(report));
    }

    void usdaBlendShapesAddUpToTheShape()
    {
        // --blend-shapes: points + the keys' offsets times their animated weights is the cache.
        const QString out = m_dir.filePath(QStringLiteral("shapes.usda"));
        const Run r = runCelform({"export", m_project, "--format", "usda", "--blend-shapes", "--out", out});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QString cache = m_dir.filePath(QStringLiteral("shapes.pc2"));
        QCOMPARE(runCelform({"export", m_project, "--format", "pc2", "--out", cache}).exitCode, 0);
        const Pc2 pc2 = readPc2(cache);
        const QByteArray text = readAll(out);
        QVERIFY(text.contains("uniform token[] skel:blendShapes = [\"side\", \"front\"]"));
        QVERIFY(text.contains("def SkelAnimation"));
        double worst = 0.0;
        bool weighted = false;
        for (int f = 0; f < kFrames; ++f) {
            std::vector<float> shape = usdaSample(text, "point3f[] points", f);
            const std::vector<float> weights = usdaSample(text, "float[] blendShapeWeights", f);
            QCOMPARE(int(shape.size()), m_vertices * 3);
            QCOMPARE(weights.size(), std::size_t(2));
            qsizetype at = 0;
            for (std::size_t k = 0; k < 2; ++k) {
                at = text.indexOf("def BlendShape", at + 1);
                const std::vector<float> offsets = usdaValue(text, "uniform vector3f[] offsets", at);
                const std::vector<float> indices = usdaValue(text, "uniform int[] pointIndices", at);
                QCOMPARE(offsets.size(), indices.size() * 3);
                for (std::size_t i = 0; i < indices.size(); ++i)
                    for (std::size_t c = 0; c < 3; ++c)
                        shape[std::size_t(indices[i]) * 3 + c] += weights[k] * offsets[i * 3 + c];
                weighted = weighted || weights[k] > 0.0f;
            }
            for (std::size_t i = 0; i < shape.size(); ++i)
                worst = std::max(worst, double(std::abs(shape[i] - pc2.positions[std::size_t(f) * shape.size() + i])));
        }
        QVERIFY(weighted);
        QVERIFY2(worst < 1e-5, qPrintable(QString::number(worst)));
        readUsd(out);

        // A subdivided surface: the PC2 cache's points at the same level, exactly.
        const QString smooth = m_dir.filePath(QStringLiteral("smooth.usda"));
        QCOMPARE(runCelform({"export", m_project, "--format", "usda", "--subdivision", "1", "--frames", "2-3", "--out",
                                smooth})
                     .exitCode,
            0);
        QCOMPARE(runCelform(
                     {"export", m_project, "--format", "pc2", "--subdivision", "1", "--frames", "2-3", "--out", cache})
                     .exitCode,
            0);
        const Pc2 level1 = readPc2(cache);
        const QByteArray smoothText = readAll(smooth);
        const std::vector<float> points = usdaSample(smoothText, "point3f[] points", 3);
        QCOMPARE(int(points.size()), level1.points * 3);
        QVERIFY(std::equal(points.begin(), points.end(), level1.positions.begin() + std::ptrdiff_t(points.size())));
        readUsd(smooth);
    }

    void usdaCancelledLeavesNoFile()
    {
        // Cancelled in the first walk (the points) and in the second (the normals): no file.
        struct CancelAfter : algo::Progress {
            std::int64_t after = 0, reports = 0, total = 0;
            void progress(std::int64_t, std::int64_t t, const std::string&) override
            {
                ++reports;
                total = t;
            }
            bool isCancelRequested() const override { return reports >= after; }
        };
        const model::ProjectData data = model::loadProject(m_project, model::DrawingImages::Skip);
        model::ExportJob job;
        job.format = model::ExportFormat::Usda;
        job.lastFrame = 5;
        job.output = m_dir.filePath(QStringLiteral("cancelled.usda"));
        for (const std::int64_t after : {2, 8}) {
            CancelAfter progress;
            progress.after = after;
            const model::ExportResult result = model::exportProject(data, QStringLiteral("sphere"), job, &progress);
            QVERIFY(result.cancelled);
            QCOMPARE(progress.total, std::int64_t(12)); // both walks on one bar
            QVERIFY(!QFile::exists(job.output));
        }
        QCOMPARE(
            QDir(m_dir.path()).entryList({QStringLiteral("cancelled*")}, QDir::Files | QDir::Hidden), QStringList());
    }

    void badOptions_data()
    {
        QTest::addColumn<QStringList>("extra");
        QTest::newRow("unknown format") << QStringList{"--format", "fbx", "--out", "x.fbx"};
        QTest::newRow("no format") << QStringList{"--out", "x.pc2"};
        QTest::newRow("no out") << QStringList{"--format", "pc2"};
        QTest::newRow("reversed frames") << QStringList{"--format", "pc2", "--frames", "5-2", "--out", "x.pc2"};
        QTest::newRow("frames not a range") << QStringList{"--format", "pc2", "--frames", "abc", "--out", "x.pc2"};
        QTest::newRow("frames with a step") << QStringList{"--format", "pc2", "--frames", "0-8:2", "--out", "x.pc2"};
        QTest::newRow("suffix unlike format") << QStringList{"--format", "glb", "--out", "x.gltf"};
        QTest::newRow("blend shapes in pc2") << QStringList{"--format", "pc2", "--blend-shapes", "--out", "x.pc2"};
        QTest::newRow("blend shapes subdivided")
            << QStringList{"--format", "usda", "--blend-shapes", "--subdivision", "1", "--out", "x.usda"};
    }

    void badOptions()
    {
        QFETCH(QStringList, extra);
        const Run r = runCelform(QStringList{"export", m_project} + extra);
        QCOMPARE(r.exitCode, 2);
    }

    void unwritableOutput()
    {
        const QString out = QStringLiteral("/nonexistent-dir/shot.pc2");
        const Run r = runCelform({"export", m_project, "--format", "pc2", "--out", out});
        QCOMPARE(r.exitCode, 3);
        QVERIFY2(r.err.contains(out), qPrintable(r.err));
        QVERIFY(!r.err.contains('\n') || r.err.trimmed().count('\n') == 0);
    }

    // Issue 27: every writer on a full disk (each file ends at 1 KB here, and every output is
    // larger) and into /dev/full: exit 3, one line naming the file and the system's reason, neither
    // a short file nor a temporary file left, and what was at the name (for an edit, the previous
    // version of the project) as it was. Before, most of them exited 0 with cut files.
    // In the arguments OUT stands for the output, PROJECT for the test's project, MESH for its mesh.
    void fullDiskOutputs_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("suffix");
        QTest::addColumn<bool>("onDevice"); // also written into /dev/full through a link
        QTest::addColumn<bool>("edits"); // saves the project OUT (a copy of the test's)
        QTest::newRow("gltf") << QStringList{"export", "PROJECT", "--format", "gltf", "--out", "OUT"} << "gltf" << true
                              << false;
        QTest::newRow("glb") << QStringList{"export", "PROJECT", "--format", "glb", "--out", "OUT"} << "glb" << true
                             << false;
        QTest::newRow("pc2") << QStringList{"export", "PROJECT", "--format", "pc2", "--out", "OUT"} << "pc2" << true
                             << false;
        QTest::newRow("obj-seq") << QStringList{"export", "PROJECT", "--format", "obj-seq", "--frames", "0-2", "--out",
            "OUT"} << "obj" << false
                                 << false;
        QTest::newRow("eval obj") << QStringList{"eval", "PROJECT", "--frame", "3", "--out", "OUT"} << "obj" << true
                                  << false;
        QTest::newRow("eval ply") << QStringList{"eval", "PROJECT", "--frame", "3", "--out", "OUT"} << "ply" << true
                                  << false;
        QTest::newRow("curvature") << QStringList{"curvature", "PROJECT", "--out", "OUT"} << "ply" << true << false;
        QTest::newRow("analysis exr") << QStringList{"analyze", "PROJECT", "--size", "64x48", "--out", "OUT"} << "exr"
                                      << true << false;
        QTest::newRow("new") << QStringList{"new", "MESH", "--out", "OUT"} << "celform" << true << false;
        QTest::newRow("set") << QStringList{"set", "OUT", "--sharpness", "0.5"} << "celform" << false << true;
        QTest::newRow("key add") << QStringList{"key", "add", "OUT", "--name", "up", "--from-base", "--view", "0,1,0"}
                                 << "celform" << false << true;
    }

    void fullDiskOutputs()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, suffix);
        QFETCH(bool, onDevice);
        QFETCH(bool, edits);
        const QString dir = m_dir.filePath(QStringLiteral("full_%1").arg(QString::fromLatin1(QTest::currentDataTag())));
        QVERIFY(QDir().mkpath(dir));
        const QString out = QDir(dir).filePath(QStringLiteral("out.") + suffix);
        // An edit saves the project it opens: a copy of the test's; else something to keep at the name.
        if (edits)
            QVERIFY(QFile::copy(m_project, out));
        else {
            QFile previous(out);
            QVERIFY(previous.open(QIODevice::WriteOnly) && previous.write("the previous file") > 0);
        }
        const QByteArray before = fileBytes(out);
        auto with = [&](const QString& output) {
            QStringList a = args;
            a.replaceInStrings(QStringLiteral("PROJECT"), m_project);
            a.replaceInStrings(QStringLiteral("MESH"), m_dir.filePath(QStringLiteral("sphere.obj")));
            a.replaceInStrings(QStringLiteral("OUT"), output);
            return a;
        };
        const Run r = runCelformOnFullDisk(with(out), 1024);
        QCOMPARE(r.exitCode, 3);
        const QString last = r.err.trimmed().section(QLatin1Char('\n'), -1);
        QVERIFY2(last.startsWith(QStringLiteral("celform: ")) && last.contains(dir)
                && last.contains(QStringLiteral("File too large")),
            qPrintable(r.err));
        QCOMPARE(QDir(dir).entryList(QDir::Files | QDir::Hidden), QStringList{QFileInfo(out).fileName()});
        QCOMPARE(fileBytes(out), before);
        if (!onDevice)
            return;
        const QString link = QDir(dir).filePath(QStringLiteral("device.") + suffix);
        QVERIFY(QFile::link(QStringLiteral("/dev/full"), link));
        const Run device = runCelform(with(link));
        QCOMPARE(device.exitCode, 3);
        QVERIFY2(device.err.contains(QStringLiteral("No space left on device")), qPrintable(device.err));
        QVERIFY(!QFileInfo(QStringLiteral("/dev/full")).isFile());
    }

    void animatedCharacterFromStartToFinish()
    {
        // The story on the bundled animated character (a skinned glTF): import it, key two
        // views at several frames, set a turntable, render the range in one process and on two
        // "nodes", export glTF (validated) and PC2 (equal to eval at every frame).
        const QString glb = QStringLiteral(CELFORM_SOURCE_DIR "/resources/samples/elephant-trunk.glb");
        const QString p = m_dir.filePath(QStringLiteral("story.celform"));
        auto run = [](const QStringList& args) {
            const Run r = runCelform(args);
            if (r.exitCode != 0)
                qWarning() << args << r.err;
            return r;
        };
        QCOMPARE(run({"new", glb, "--out", p}).exitCode, 0);
        const QJsonObject info = QJsonDocument::fromJson(run({"info", p, "--json"}).out.toUtf8()).object();
        QCOMPARE(info.value("fps").toDouble(), 24.0);
        QCOMPARE(info.value("frame_range").toArray(), (QJsonArray{0, 47}));
        QCOMPARE(info.value("base_animation").toObject().value("joints").toInt(), 2);
        QCOMPARE(info.value("base_animation").toObject().value("frame_count").toInt(), 48);
        QCOMPARE(run({"key", "add", p, "--name", "side", "--from-base", "--view", "0,0,1"}).exitCode, 0);
        QCOMPARE(run({"key", "add", p, "--name", "far side", "--from-base", "--view", "0,0,-1"}).exitCode, 0);
        for (const QStringList& stroke :
            {QStringList{"side", "0", "--drag", "0.15,-0.1"}, QStringList{"side", "24", "--drag", "-0.1,0.05"},
                QStringList{"far side", "12", "--push", "0.1"}, QStringList{"far side", "36", "--drag", "0.05,-0.15"}})
            QCOMPARE(run(QStringList{"brush", p, "--key", stroke[0], "--vertex", "691", "--radius", "0.4", "--frame",
                             stroke[1], stroke[2], stroke[3]})
                         .exitCode,
                0);
        QCOMPARE(run({"camera", p, "--turntable", "48"}).exitCode, 0);

        // One process, then two nodes taking alternate frames of the stride, into one folder each.
        QDir(m_dir.path()).mkpath(QStringLiteral("one"));
        QDir(m_dir.path()).mkpath(QStringLiteral("two"));
        const QStringList size{"--size", "64x48"};
        QCOMPARE(run(QStringList{"render", p, "--frames", "0-47:6", "--out", m_dir.filePath("one/f_####.png")} + size)
                     .exitCode,
            0);
        QCOMPARE(run(QStringList{"render", p, "--frames", "0-47:12", "--out", m_dir.filePath("two/f_####.png")} + size)
                     .exitCode,
            0);
        QCOMPARE(run(QStringList{"render", p, "--frames", "6-47:12", "--out", m_dir.filePath("two/f_####.png")} + size)
                     .exitCode,
            0);
        QByteArray first, middle;
        for (int f = 0; f < 48; f += 6) {
            QFile a(m_dir.filePath(QStringLiteral("one/f_%1.png").arg(f, 4, 10, QLatin1Char('0'))));
            QFile b(m_dir.filePath(QStringLiteral("two/f_%1.png").arg(f, 4, 10, QLatin1Char('0'))));
            QVERIFY(a.open(QIODevice::ReadOnly) && b.open(QIODevice::ReadOnly));
            const QByteArray bytes = a.readAll();
            QVERIFY2(bytes == b.readAll(), qPrintable(QStringLiteral("frame %1 differs between the runs").arg(f)));
            if (f == 0)
                first = bytes;
            if (f == 24)
                middle = bytes;
        }
        QVERIFY2(first != middle, "the turntable should show the model from another side at frame 24");

        const QString gltf = m_dir.filePath(QStringLiteral("story.glb"));
        QCOMPARE(run({"export", p, "--format", "glb", "--out", gltf}).exitCode, 0);
        validate(gltf);

        const QString cache = m_dir.filePath(QStringLiteral("story.pc2"));
        QCOMPARE(run({"export", p, "--format", "pc2", "--out", cache}).exitCode, 0);
        const Pc2 pc2 = readPc2(cache);
        QCOMPARE(pc2.samples, 48);
        const int n = pc2.points;
        QCOMPARE(n, 2775);
        for (int f = 0; f < 48; ++f) {
            const QString obj = m_dir.filePath(QStringLiteral("story_%1.obj").arg(f));
            QCOMPARE(run({"eval", p, "--frame", QString::number(f), "--out", obj}).exitCode, 0);
            const algo::TriMesh evaluated = model::importMesh(obj, model::ImportIsolation::ThisProcess).mesh;
            QCOMPARE(int(evaluated.vertexCount()), n);
            double worst = 0.0;
            for (int v = 0; v < n; ++v)
                for (int c = 0; c < 3; ++c)
                    worst = std::max(worst,
                        double(std::abs(
                            pc2.positions[(std::size_t(f) * std::size_t(n) + std::size_t(v)) * 3 + std::size_t(c)]
                            - evaluated.vertices(v, c))));
            QVERIFY2(worst <= 1e-6, qPrintable(QStringLiteral("frame %1 differs by %2").arg(f).arg(worst)));
        }
    }

    void missingProject()
    {
        const Run r = runCelform(
            {"export", m_dir.filePath("none.celform"), "--format", "pc2", "--out", m_dir.filePath("none.pc2")});
        QCOMPARE(r.exitCode, 3);
        QVERIFY(r.err.contains(QStringLiteral("none.celform")));
    }

private:
    /// Runs the Khronos glTF Validator on a file: no errors allowed, warnings printed.
    void validate(const QString& file)
    {
        const QString node = QStandardPaths::findExecutable(QStringLiteral("node"));
        if (node.isEmpty())
            QSKIP("node (Node.js) is not installed: the glTF Validator cannot run (scripts/setup.sh installs it)");
        const QString prefix = validatorPrefix();
        if (!QFileInfo::exists(prefix + QStringLiteral("/node_modules/gltf-validator/package.json")))
            QSKIP(qPrintable(
                QStringLiteral("the gltf-validator package is not in %1 (run scripts/setup.sh)").arg(prefix)));
        QProcess p;
        p.start(node, {QStringLiteral(CELFORM_SOURCE_DIR "/tests/tools/validate_gltf.mjs"), file, prefix});
        QVERIFY(p.waitForFinished(120000));
        const QString report
            = QString::fromUtf8(p.readAllStandardOutput()) + QString::fromUtf8(p.readAllStandardError());
        qInfo().noquote() << "glTF Validator on" << QFileInfo(file).fileName() << ":" << report.trimmed();
        QVERIFY2(p.exitStatus() == QProcess::NormalExit && p.exitCode() == 0, qPrintable(report));
    }

    /// Reads a USD file with TinyUSDZ (tests/tools/read_usd.mjs): it must load without errors;
    /// the reader's report in report.
    void readUsd(const QString& file, QString* report = nullptr)
    {
        const QString node = QStandardPaths::findExecutable(QStringLiteral("node"));
        if (node.isEmpty())
            QSKIP("node (Node.js) is not installed: TinyUSDZ cannot run (scripts/setup.sh installs it)");
        const QString prefix = validatorPrefix();
        if (!QFileInfo::exists(prefix + QStringLiteral("/node_modules/tinyusdz/package.json")))
            QSKIP(qPrintable(QStringLiteral("the tinyusdz package is not in %1 (run scripts/setup.sh)").arg(prefix)));
        QProcess p;
        p.start(node, {QStringLiteral(CELFORM_SOURCE_DIR "/tests/tools/read_usd.mjs"), file, prefix});
        QVERIFY(p.waitForFinished(120000));
        const QString text = QString::fromUtf8(p.readAllStandardOutput()) + QString::fromUtf8(p.readAllStandardError());
        qInfo().noquote() << "TinyUSDZ on" << QFileInfo(file).fileName() << ":" << text.trimmed();
        QVERIFY2(p.exitStatus() == QProcess::NormalExit && p.exitCode() == 0 && text.startsWith("errors 0 meshes 1"),
            qPrintable(text));
        if (report)
            *report = text;
    }

    QTemporaryDir m_dir;
    QString m_project;
    int m_vertices = 0;
};

QTEST_GUILESS_MAIN(TestExport)
#include "test_export.moc"
