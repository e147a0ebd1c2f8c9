// The .celform file: bit-identical round trip, atomic save with backup, refusal of newer,
// corrupt and truncated files with the open document left as it was.
#include "test_support.h"

#include "celform/model/document/document.h"
#include "celform/model/data/io_error.h"
#include "celform/model/io/mesh_io.h"
#include "celform/model/io/project_file.h"

#include <QBuffer>
#include <QCryptographicHash>
#include <QDir>
#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <QThread>
#include <QtEndian>

#include <csignal>
#include <cstring>
#include <functional>
#include <limits>
#include <new>

#include <sys/ptrace.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace celform;
using namespace celform::model;

namespace {

QByteArray pngBytes(int w, int h, QColor color)
{
    QImage image(w, h, QImage::Format_RGBA8888);
    image.fill(color);
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    image.save(&buffer, "PNG");
    return bytes;
}

/// A project using every part of the format: UVs, materials, face sets, drawings, keys with
/// offsets at two frames, non-default settings.
ProjectData richProject()
{
    auto mesh = std::make_shared<algo::TriMesh>();
    mesh->vertices.resize(5, 3);
    mesh->vertices << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5f, 0.5f, 1.f / 3.f;
    mesh->faces.resize(4, 3);
    mesh->faces << 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4;
    mesh->uvs.resize(5, 2);
    mesh->uvs << 0, 0, 1, 0, 1, 1, 0, 1, 0.5f, 0.5f;
    mesh->uvFaces = mesh->faces;
    mesh->materials = {{"skin", {0.9f, 0.7f, 0.6f}}, {"hair", {0.1f, 0.1f, 0.2f}}};
    mesh->faceMaterials = {0, 0, 1, 1};

    ProjectData data;
    data.baseMesh = mesh;
    data.baseMeshName = QStringLiteral("pyramid.obj");
    data.faceSets = {{"forehead", {0, 1}}};
    Drawing d;
    d.id = 1;
    d.name = QStringLiteral("side view");
    d.imageFormat = QStringLiteral("png");
    d.imageData = pngBytes(16, 8, Qt::blue);
    d.camera.eye = Eigen::Vector3d(0.1, 0.2, 7.123456789012345);
    d.camera.projection = Projection::Orthographic;
    d.camera.orthoHeight = 3.3;
    d.aligned = true;
    d.opacity = 0.37;
    d.frame = 12;
    data.drawings.push_back(d);

    KeyViewpoint k;
    k.id = 2;
    k.name = QStringLiteral("キー 1");
    k.direction = Eigen::Vector3d(1, 2, 3).normalized();
    k.camera.eye = k.direction * 5;
    k.drawingIds = {1};
    k.offsetsByFrame[0] = SparseOffsets{{0, 4}, {Eigen::Vector3f(0.1f, 0.2f, 0.3f), Eigen::Vector3f(-1e-7f, 0, 1e6f)}};
    k.offsetsByFrame[24] = SparseOffsets{{2}, {Eigen::Vector3f(0, 0, 1)}};
    k.enabled = false;
    data.keys.push_back(k);

    data.blend.sharpness = 1.75;
    data.blend.unspecified = UnspecifiedMode::Cosine;
    data.blend.time = TimeInterpolation::PeriodicSpline;
    data.look.style = ShadingStyle::Comic;
    data.look.light = {LightType::Point, Eigen::Vector3d(1.5, -2, 3)};
    data.look.showLines = false;
    data.look.materialStyles[1] = ShadingStyle::Gooch;
    Camera shot;
    shot.eye = Eigen::Vector3d(3, 1.5, 4.25);
    shot.target = Eigen::Vector3d(0.5, 0.5, 0.125);
    shot.fovYDegrees = 27.5;
    data.look.renderCamera = shot;
    data.look.toon.thresholds = {0.1f, 0.6f};
    data.look.toon.intensities = {0.2f, 0.5f, 0.9f};
    data.look.toonEvaluation = algo::ToonEvaluation::PerFace;
    data.look.gooch = algo::goochPreset("purple");
    data.look.gooch.warm = algo::Color(0.9f, 0.5f, 0.2f);
    data.look.hatch.spacing = 0.0123f;
    data.look.hatch.angleDegrees = -30.f;
    data.look.lines.creaseAngleDegrees = 33.f;
    data.look.lines.ridges = true;
    data.look.lines.ridgeThreshold = 0.45f;
    data.look.lines.borders = false;
    data.look.lineStyle.jitter = 1.25f;
    data.look.lineStyle.seed = 77;
    data.look.lines.creaseLowAngleDegrees = 21.f;
    data.look.lineStyle.joinGap = 3.5f;
    data.look.lineStyle.smoothing = 3;
    data.look.lineStyle.minLength = 0.02f;
    data.look.lineStyle.taper = 7.f;
    data.look.lineStyle.reduction = 0.25f;
    data.look.stereo.output = algo::StereoOutput::Dubois;
    data.look.stereo.interocular = 0.07;
    data.look.stereo.toeIn = true;
    data.look.stereo.dubois.left(1, 2) = 0.5f;
    // Highlights: a hidden cutter and a layer on the forehead with two keys and every operation.
    HighlightTrack cutter;
    cutter.name = QStringLiteral("cutter");
    cutter.visible = false;
    cutter.keys = {{0.0, {}}};
    cutter.keys[0].layer.shape.epsilon = 0.01f;
    HighlightTrack shine;
    shine.name = QStringLiteral("shine ✦");
    shine.patch = QStringLiteral("forehead");
    shine.guide = Eigen::Vector3f(0.f, 0.3f, -1.f);
    shine.smoothing = 12;
    shine.combineWith = {{algo::HighlightBoolean::Subtraction, QStringLiteral("cutter")},
        {algo::HighlightBoolean::Union, QStringLiteral("cutter")}};
    algo::HighlightLayer first;
    first.color = algo::Color(1.f, 0.9f, 0.7f);
    first.shape.epsilon = 0.07f;
    first.offSpecularCut = 0.1f;
    first.shape.operations = {algo::HighlightOperation::translation(0.2f, -0.1f),
        algo::HighlightOperation::rotation(30.f), algo::HighlightOperation::directionalScaling(0.5f),
        algo::HighlightOperation::split(0.4f, 0.f), algo::HighlightOperation::squaring(0.2f, 2.f)};
    algo::HighlightLayer second = first;
    second.shape.epsilon = 0.03f;
    second.shape.operations[0] = algo::HighlightOperation::translation(-0.3f, 0.25f);
    shine.keys = {{0.0, first}, {30.0, second}};
    data.look.highlights = {cutter, shine};
    data.shadingOffsets = {0.f, 0.1f, -0.2f, 0.3f, 0.f};
    data.nextId = 3;
    return data;
}

QByteArray readAll(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

void writeAll(const QString& path, const QByteArray& bytes)
{
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
    QCOMPARE(f.write(bytes), bytes.size());
}

/// zlib's CRC-32 (reflected polynomial 0xEDB88320), bit by bit.
quint32 crc32(const QByteArray& bytes)
{
    quint32 crc = 0xffffffffu;
    for (const char c : bytes) {
        crc ^= quint32(quint8(c));
        for (int k = 0; k < 8; ++k)
            crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

/// Rewrites a project file's JSON manifest in place, with a valid trailer (docs/file-format.md):
/// what a file written by another version, or edited by hand, would hold.
void editManifest(const QString& path, const std::function<void(QJsonObject&)>& edit)
{
    QByteArray bytes = readAll(path);
    QVERIFY(bytes.size() > 48);
    const char* trailer = bytes.constData() + bytes.size() - 32;
    const auto offset = qsizetype(qFromLittleEndian<quint64>(trailer));
    const auto size = qsizetype(qFromLittleEndian<quint64>(trailer + 8));
    QJsonObject manifest = QJsonDocument::fromJson(bytes.mid(offset, size)).object();
    QVERIFY(!manifest.isEmpty());
    edit(manifest);
    const QByteArray json = QJsonDocument(manifest).toJson(QJsonDocument::Indented);
    QByteArray end(32, '\0');
    qToLittleEndian<quint64>(quint64(offset), end.data());
    qToLittleEndian<quint64>(quint64(json.size()), end.data() + 8);
    qToLittleEndian<quint32>(crc32(json), end.data() + 16);
    std::memcpy(end.data() + 24, trailer + 24, 8);
    writeAll(path, bytes.left(offset) + json + end);
}

/// Sets (or with an undefined value removes) an entry of the last highlight track in the manifest.
void setLastTrackEntry(QJsonObject& manifest, const QString& name, const QJsonValue& value)
{
    QJsonObject look = manifest.value("look").toObject();
    QJsonArray tracks = look.value("highlights").toArray();
    QJsonObject track = tracks.last().toObject();
    if (value.isUndefined())
        track.remove(name);
    else
        track.insert(name, value);
    tracks.replace(tracks.size() - 1, track);
    look.insert("highlights", tracks);
    manifest.insert("look", look);
}

/// How a load run in a child process ended.
struct ChildOutcome {
    enum Kind { IoErrorThrown, OtherException, Returned, Crashed, TimedOut } kind = Crashed;
    QString message; ///< the exception's text
    int signal = 0; ///< for Crashed
    qint64 milliseconds = 0;

    [[nodiscard]] QString describe() const
    {
        const char* names[] = {"IoError", "another exception", "no exception", "crash", "time-out"};
        return QStringLiteral("%1 after %2 ms (signal %3): %4")
            .arg(names[kind])
            .arg(milliseconds)
            .arg(signal)
            .arg(message);
    }
};

/// Runs body in a forked child whose address space may grow by at most budget bytes, killed after
/// timeoutMs: a regression that crashes, hangs or allocates gigabytes fails its test instead of
/// taking the test run (or the machine) down with it.
ChildOutcome runInChild(const std::function<void()>& body, qint64 budget = 512ll << 20, int timeoutMs = 10000)
{
    int fds[2];
    if (::pipe(fds) != 0)
        qFatal("pipe failed");
    std::fflush(stdout);
    std::fflush(stderr);
    QElapsedTimer timer;
    timer.start();
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::close(fds[0]);
        for (int sig : {SIGSEGV, SIGBUS, SIGABRT, SIGFPE, SIGILL})
            std::signal(sig, SIG_DFL); // die by the signal, without QtTest's crash report
        QFile statm(QStringLiteral("/proc/self/statm"));
        const qint64 pages = statm.open(QIODevice::ReadOnly) ? statm.readAll().split(' ').value(0).toLongLong() : 0;
        const auto limit = rlim_t(pages * ::sysconf(_SC_PAGESIZE) + budget);
        const rlimit rl{limit, limit};
        ::setrlimit(RLIMIT_AS, &rl);
        ChildOutcome::Kind kind = ChildOutcome::Returned;
        QByteArray message;
        try {
            body();
        } catch (const IoError& e) {
            kind = ChildOutcome::IoErrorThrown;
            message = e.message().toUtf8();
        } catch (const std::bad_alloc&) {
            kind = ChildOutcome::OtherException;
            message = "std::bad_alloc";
        } catch (const std::exception& e) {
            kind = ChildOutcome::OtherException;
            message = e.what();
        }
        const QByteArray out = QByteArray::number(int(kind)) + ' ' + message;
        [[maybe_unused]] const auto written = ::write(fds[1], out.constData(), std::size_t(out.size()));
        ::_exit(0);
    }
    ::close(fds[1]);
    ChildOutcome outcome;
    int status = 0;
    bool finished = false;
    while (!finished && timer.elapsed() < timeoutMs) {
        finished = ::waitpid(pid, &status, WNOHANG) == pid;
        if (!finished)
            QThread::msleep(5);
    }
    outcome.milliseconds = timer.elapsed();
    if (!finished) {
        ::kill(pid, SIGKILL);
        ::waitpid(pid, &status, 0);
        outcome.kind = ChildOutcome::TimedOut;
    } else if (WIFSIGNALED(status)) {
        outcome.kind = ChildOutcome::Crashed;
        outcome.signal = WTERMSIG(status);
    }
    QByteArray out;
    char buffer[4096];
    for (ssize_t n; (n = ::read(fds[0], buffer, sizeof buffer)) > 0;)
        out.append(buffer, n);
    ::close(fds[0]);
    if (finished && WIFEXITED(status) && !out.isEmpty()) {
        outcome.kind = ChildOutcome::Kind(out.left(out.indexOf(' ')).toInt());
        outcome.message = QString::fromUtf8(out.mid(out.indexOf(' ') + 1));
    }
    return outcome;
}

} // namespace

class TestProjectFile : public QObject {
    Q_OBJECT

private slots:
    void roundTripIsExact()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("rich.celform"));
        const ProjectData original = richProject();
        saveProject(original, path);
        const ProjectData loaded = loadProject(path);
        QVERIFY(loaded == original);
        QCOMPARE(loaded.drawings.front().image.size(), QSize(16, 8));
        // Saving what was loaded gives the same bytes: nothing drifts through a round trip.
        const QString again = dir.filePath(QStringLiteral("again.celform"));
        saveProject(loaded, again);
        QCOMPARE(readAll(again), readAll(path));
    }

    void highlightsAreValidatedOnLoad()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("bad_highlight.celform"));
        ProjectData data = richProject();
        data.look.highlights.back().patch = QStringLiteral("no such set");
        saveProject(data, path);
        QVERIFY_THROWS_EXCEPTION(IoError, loadProject(path));
        data = richProject();
        data.look.highlights.back().combineWith = {{algo::HighlightBoolean::Union, QStringLiteral("ghost")}};
        saveProject(data, path);
        QVERIFY_THROWS_EXCEPTION(IoError, loadProject(path));
    }

    void ridgeSettingsAreStoredAndOptional()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("ridges.celform"));
        saveProject(richProject(), path);
        QVERIFY(loadProject(path).look.lines.ridges);
        QCOMPARE(loadProject(path).look.lines.ridgeThreshold, 0.45f);
        // Files from before apparent ridges open with ridges off and the default threshold.
        editManifest(path, [](QJsonObject& m) {
            QJsonObject look = m.value(QStringLiteral("look")).toObject();
            QJsonObject kinds = look.value(QStringLiteral("line_kinds")).toObject();
            kinds.remove(QStringLiteral("ridges"));
            kinds.remove(QStringLiteral("ridge_threshold"));
            look.insert(QStringLiteral("line_kinds"), kinds);
            m.insert(QStringLiteral("look"), look);
        });
        const ProjectData old = loadProject(path);
        QVERIFY(!old.look.lines.ridges);
        QCOMPARE(old.look.lines.ridgeThreshold, algo::LineSettings().ridgeThreshold);
        QCOMPARE(old.look.lines.creaseAngleDegrees, 33.f);
        // A negative threshold is damage.
        editManifest(path, [](QJsonObject& m) {
            QJsonObject look = m.value(QStringLiteral("look")).toObject();
            QJsonObject kinds = look.value(QStringLiteral("line_kinds")).toObject();
            kinds.insert(QStringLiteral("ridge_threshold"), -1);
            look.insert(QStringLiteral("line_kinds"), kinds);
            m.insert(QStringLiteral("look"), look);
        });
        QVERIFY_THROWS_EXCEPTION(IoError, loadProject(path));
    }

    void strokeCleanUpIsStoredAndOptional()
    {
        // Issue 25: crease hysteresis and the stroke clean-up round-trip; older files get the
        // hand-drawn defaults; values out of range are damage.
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("strokes.celform"));
        saveProject(richProject(), path);
        const ProjectData saved = loadProject(path);
        QCOMPARE(saved.look.lines.creaseLowAngleDegrees, 21.f);
        QCOMPARE(saved.look.lineStyle.joinGap, 3.5f);
        QCOMPARE(saved.look.lineStyle.smoothing, 3);
        QCOMPARE(saved.look.lineStyle.minLength, 0.02f);
        QCOMPARE(saved.look.lineStyle.taper, 7.f);
        QCOMPARE(saved.look.lineStyle.reduction, 0.25f);
        auto editLines = [&](const char* object, const std::function<void(QJsonObject&)>& change) {
            editManifest(path, [&](QJsonObject& m) {
                QJsonObject look = m.value(QStringLiteral("look")).toObject();
                QJsonObject o = look.value(QLatin1String(object)).toObject();
                change(o);
                look.insert(QLatin1String(object), o);
                m.insert(QStringLiteral("look"), look);
            });
        };
        editLines("line_kinds", [](QJsonObject& k) { k.remove(QStringLiteral("crease_low_angle_degrees")); });
        editLines("line_style", [](QJsonObject& l) {
            for (const char* key : {"join_gap", "smoothing", "min_length", "taper", "reduction"})
                l.remove(QLatin1String(key));
        });
        const ProjectData old = loadProject(path);
        QCOMPARE(old.look.lines.creaseLowAngleDegrees, algo::LineSettings().creaseLowAngleDegrees);
        algo::LineStyle expected = algo::LineStyle();
        expected.color = old.look.lineStyle.color;
        expected.outlineWidth = old.look.lineStyle.outlineWidth;
        expected.innerWidth = old.look.lineStyle.innerWidth;
        expected.jitter = old.look.lineStyle.jitter;
        expected.widthVariation = old.look.lineStyle.widthVariation;
        expected.overshoot = old.look.lineStyle.overshoot;
        expected.seed = old.look.lineStyle.seed;
        QVERIFY(old.look.lineStyle == expected);
        for (const auto& [key, bad] : std::vector<std::pair<const char*, double>>{
                 {"join_gap", -1}, {"smoothing", 1.5}, {"smoothing", 9}, {"min_length", 2}, {"reduction", 1.5}}) {
            saveProject(richProject(), path);
            const QString k = QLatin1String(key);
            const double v = bad;
            editLines("line_style", [&](QJsonObject& l) { l.insert(k, v); });
            QVERIFY_THROWS_EXCEPTION(IoError, loadProject(path));
        }
    }

    void subdivisionIsStoredAndOptional()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("smooth.celform"));
        ProjectData data = richProject();
        data.look.subdivision = {2, 1};
        saveProject(data, path);
        QCOMPARE(loadProject(path).look.subdivision, (SubdivisionLook{2, 1}));
        QCOMPARE(loadProject(path).look.subdivision.viewport(), 1);
        // Files from before subdivision show the control mesh.
        editManifest(path, [](QJsonObject& m) {
            QJsonObject look = m.value(QStringLiteral("look")).toObject();
            look.remove(QStringLiteral("subdivision"));
            m.insert(QStringLiteral("look"), look);
        });
        QCOMPARE(loadProject(path).look.subdivision, SubdivisionLook{});
        QCOMPARE(SubdivisionLook{}.level, 0);
        // Levels out of range, or not whole, are damage.
        for (const auto& levels : {std::pair{4.0, -1.0}, std::pair{-1.0, -1.0}, std::pair{1.5, -1.0},
                 std::pair{2.0, -2.0}, std::pair{2.0, 4.0}}) {
            const double render = levels.first, viewport = levels.second; // C++17 lambdas take no bindings
            editManifest(path, [&](QJsonObject& m) {
                QJsonObject look = m.value(QStringLiteral("look")).toObject();
                look.insert(QStringLiteral("subdivision"),
                    QJsonObject{
                        {QStringLiteral("render_level"), render}, {QStringLiteral("viewport_level"), viewport}});
                m.insert(QStringLiteral("look"), look);
            });
            QVERIFY_THROWS_EXCEPTION(IoError, loadProject(path));
        }
    }

    void oneHotSequenceOfFormat3OpensAsVertexFrames()
    {
        // Issue 27, item 6: formats 2 and 3 stored a vertex sequence as one morph target per later
        // file with one-hot weights. Such a file opens as vertex frames giving the same positions
        // at every frame, and is saved back linearly; a real blend of targets stays as it is.
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("old-sequence.celform"));
        ProjectData data = richProject();
        const algo::Positions& rest = data.baseMesh->vertices;
        auto old = std::make_shared<algo::BaseAnimation>();
        old->firstFrame = 2;
        old->frameCount = 4; // samples: rest, target 0, target 0 (a missing file), target 1
        old->morphTargets = {algo::Positions::Constant(5, 3, 0.25f), algo::Positions::Constant(5, 3, -0.5f)};
        old->morphTargets[1](3, 1) = 0.125f;
        old->morphWeights = {0, 0, 1, 0, 1, 0, 0, 1};
        data.baseAnimation = old;
        saveProject(data, path);
        editManifest(path, [](QJsonObject& m) { m.insert(QStringLiteral("format_version"), 3); });
        const ProjectData read = loadProject(path);
        QVERIFY(read.baseAnimation);
        const algo::BaseAnimation& a = *read.baseAnimation;
        QVERIFY(a.morphTargets.empty() && a.morphWeights.empty());
        QCOMPARE(a.storedFrameCount(5), Eigen::Index(3));
        QCOMPARE(a.vertexFrameOfSample, (std::vector<std::int32_t>{0, 1, 1, 2}));
        algo::Positions before, after;
        for (int frame = 0; frame <= 7; ++frame) {
            old->evaluate(rest, frame, before);
            a.evaluate(read.baseMesh->vertices, frame, after);
            QVERIFY2(before == after, qPrintable(QStringLiteral("frame %1").arg(frame)));
        }
        saveProject(read, path);
        QVERIFY(*loadProject(path).baseAnimation == a);

        // Weights of 0.5: a blend, kept as morph targets.
        old->morphWeights = {0, 0, 0.5f, 0, 1, 0, 0, 1};
        saveProject(data, path);
        editManifest(path, [](QJsonObject& m) { m.insert(QStringLiteral("format_version"), 3); });
        QVERIFY(*loadProject(path).baseAnimation == *old);
    }

    void ridgeSettingsRoundTrip()
    {
        // Issue 26, fix 7: raw ridges and the depth-driven threshold are saved; older files (no
        // keys) join the ridges and use one threshold.
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("ridges.celform"));
        ProjectData data = richProject();
        data.look.lines.ridges = true;
        data.look.lines.ridgeSnakes = false;
        data.look.lines.ridgeDepthStrength = 2.5f;
        saveProject(data, path);
        QVERIFY(loadProject(path).look.lines == data.look.lines);
        editManifest(path, [](QJsonObject& m) {
            QJsonObject look = m.value(QStringLiteral("look")).toObject();
            QJsonObject kinds = look.value(QStringLiteral("line_kinds")).toObject();
            kinds.remove(QStringLiteral("ridge_snakes"));
            kinds.remove(QStringLiteral("ridge_depth_strength"));
            look.insert(QStringLiteral("line_kinds"), kinds);
            m.insert(QStringLiteral("look"), look);
        });
        const ProjectData old = loadProject(path);
        QVERIFY(old.look.lines.ridgeSnakes);
        QCOMPARE(old.look.lines.ridgeDepthStrength, 0.f);
    }

    void lightTrackIsStoredAndOptional()
    {
        // issue 26: the light track is saved (format 3) and files without it (formats 1 and 2)
        // open with the single light serving every frame.
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("track.celform"));
        ProjectData data = richProject();
        data.look.lightTrack.setKey(0, Light{LightType::Directional, {0.0, 0.0, 1.0}});
        data.look.lightTrack.setKey(10, Light{LightType::Directional, {1.0, 0.0, 0.0}});
        data.look.lightTrack.setKey(20, Light{LightType::Point, {1.0, 2.0, 3.0}});
        saveProject(data, path);
        const ProjectData read = loadProject(path);
        QCOMPARE(read.look.lightTrack, data.look.lightTrack);
        QCOMPARE(read.look.light, data.look.light);
        editManifest(path, [](QJsonObject& m) {
            QCOMPARE(m.value(QStringLiteral("format_version")).toInt(), kProjectFormatVersion);
            QJsonObject look = m.value(QStringLiteral("look")).toObject();
            look.remove(QStringLiteral("light_keys"));
            m.insert(QStringLiteral("look"), look);
            m.insert(QStringLiteral("format_version"), 2);
        });
        QVERIFY(loadProject(path).look.lightTrack.empty());
        QCOMPARE(loadProject(path).look.lightAt(7), data.look.light);
        // Keys out of order, or a directional light without a direction, are damage.
        for (const QJsonArray& keys :
            {QJsonArray{
                 QJsonObject{{"frame", 5}, {"light", QJsonObject{{"type", "point"}, {"vector", QJsonArray{0, 0, 1}}}}},
                 QJsonObject{{"frame", 5}, {"light", QJsonObject{{"type", "point"}, {"vector", QJsonArray{0, 1, 1}}}}}},
                QJsonArray{QJsonObject{
                    {"frame", 1}, {"light", QJsonObject{{"type", "directional"}, {"vector", QJsonArray{0, 0, 0}}}}}}}) {
            editManifest(path, [&](QJsonObject& m) {
                QJsonObject look = m.value(QStringLiteral("look")).toObject();
                look.insert(QStringLiteral("light_keys"), keys);
                m.insert(QStringLiteral("look"), look);
            });
            QVERIFY_THROWS_EXCEPTION(IoError, loadProject(path));
        }
    }

    void subdivisionEditIsOneUndoStep()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("edit.celform"));
        saveProject(richProject(), path);
        Document doc;
        doc.open(path);
        doc.look().setSubdivision({2, -1});
        QCOMPARE(doc.data().look.subdivision.level, 2);
        QCOMPARE(doc.undoStack()->count(), 1);
        QVERIFY_THROWS_EXCEPTION(EditRefused, doc.look().setSubdivision({4, -1}));
        QVERIFY_THROWS_EXCEPTION(EditRefused, doc.look().setSubdivision({1, -3}));
        QCOMPARE(doc.undoStack()->count(), 1);
        doc.undoStack()->undo();
        QCOMPARE(doc.data().look.subdivision, SubdivisionLook{});
    }

    void normalSmoothingIsStoredAndChecked()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("smooth.celform"));
        const ProjectData original = richProject();
        QCOMPARE(highlightTrackJson(original.look.highlights.back()).value("normal_smoothing").toInt(-1), 12);
        saveProject(original, path);
        QCOMPARE(loadProject(path).look.highlights.back().smoothing, 12);
        QCOMPARE(loadProject(path).look.highlights.front().smoothing, 0);

        // The validation the editor and the command line share.
        std::vector<HighlightTrack> tracks = original.look.highlights;
        const std::vector<QString> sets = original.faceSetNames();
        QVERIFY(highlightTracksProblem(tracks, sets).isEmpty());
        tracks.back().smoothing = kMaxHighlightSmoothing;
        QVERIFY(highlightTracksProblem(tracks, sets).isEmpty());
        for (const int bad : {-1, kMaxHighlightSmoothing + 1}) {
            tracks.back().smoothing = bad;
            QVERIFY2(highlightTracksProblem(tracks, sets).contains(QStringLiteral("smoothing")),
                qPrintable(highlightTracksProblem(tracks, sets)));
        }

        // Files from before the entry read as no smoothing.
        editManifest(path,
            [](QJsonObject& m) { setLastTrackEntry(m, QStringLiteral("normal_smoothing"), QJsonValue::Undefined); });
        QCOMPARE(loadProject(path).look.highlights.back().smoothing, 0);
        editManifest(path, [](QJsonObject& m) { setLastTrackEntry(m, QStringLiteral("normal_smoothing"), 1000); });
        QCOMPARE(loadProject(path).look.highlights.back().smoothing, 1000);

        // Out of range, fractional or not a number: damaged.
        for (const QJsonValue& bad : {QJsonValue(-1), QJsonValue(1001), QJsonValue(2.5), QJsonValue("3")}) {
            editManifest(path, [&](QJsonObject& m) { setLastTrackEntry(m, QStringLiteral("normal_smoothing"), bad); });
            try {
                loadProject(path);
                QFAIL("a bad normal smoothing was accepted");
            } catch (const IoError& e) {
                QVERIFY2(e.message().contains(QStringLiteral("damaged")), qPrintable(e.message()));
            }
        }
        // A track saved with a bad value is refused on load too.
        ProjectData data = richProject();
        data.look.highlights.back().smoothing = -3;
        saveProject(data, path);
        QVERIFY_THROWS_EXCEPTION(IoError, loadProject(path));
    }

    void emptyProjectRoundTrip()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("empty.celform"));
        saveProject(ProjectData{}, path);
        QVERIFY(loadProject(path) == ProjectData{});
    }

    // A key frame that moves no vertex (a key just added, or one whose offsets were all undone) is
    // stored as empty blocks; reading them copied zero bytes into a null vector (undefined
    // behaviour that the sanitize preset's UBSan stopped at, in every command opening such a file).
    void emptyKeyFrameRoundTrip()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("empty_key.celform"));
        ProjectData data = richProject();
        data.keys.front().offsetsByFrame[48] = SparseOffsets{};
        data.faceSets.push_back({"nothing yet", {}});
        saveProject(data, path);
        const ProjectData loaded = loadProject(path);
        QVERIFY(loaded == data);
        QVERIFY(loaded.keys.front().offsetsByFrame.at(48).indices.empty());
    }

    void realMeshRoundTrip()
    {
        CELFORM_REQUIRE_SHARED(meshPath, QStringLiteral("meshes/cgal_elephant.off"));
        QTemporaryDir dir;
        ProjectData data;
        data.baseMesh = std::make_shared<algo::TriMesh>(importMesh(meshPath).mesh);
        data.baseMeshName = QStringLiteral("cgal_elephant.off");
        const QString path = dir.filePath(QStringLiteral("elephant.celform"));
        saveProject(data, path);
        const ProjectData loaded = loadProject(path);
        QVERIFY(loaded == data);
        QCOMPARE(loaded.baseMesh->vertexCount(), Eigen::Index(2775));
        QCOMPARE(loaded.baseMesh->faceCount(), Eigen::Index(5558));
    }

    void mirrorPlaneIsSavedAndDetectedForOldFiles()
    {
        CELFORM_REQUIRE_SHARED(meshPath, QStringLiteral("meshes/cgal_elephant.off"));
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("elephant.celform"));
        ProjectData data = newProject(std::make_shared<algo::TriMesh>(importMesh(meshPath).mesh), "elephant");
        QCOMPARE(data.mirrorPlane, MirrorPlane::Z); // detected: the elephant faces +x
        data.mirrorPlane = MirrorPlane::Y;
        saveProject(data, path);
        QCOMPARE(loadProject(path).mirrorPlane, MirrorPlane::Y);
        // A file from before the plane was saved gets the plane detected on its model.
        editManifest(path, [](QJsonObject& m) { m.remove("mirror_plane"); });
        QCOMPARE(loadProject(path).mirrorPlane, MirrorPlane::Z);
        editManifest(path, [](QJsonObject& m) { m.insert("mirror_plane", "w"); });
        try {
            (void)loadProject(path);
            QFAIL("a bad mirror plane was read");
        } catch (const IoError& e) {
            QVERIFY2(e.message().contains("mirror plane"), qPrintable(e.message()));
        }
    }

    void saveKeepsBackupOfPreviousVersion()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("p.celform"));
        ProjectData first = richProject();
        saveProject(first, path);
        const QByteArray firstBytes = readAll(path);
        ProjectData second = first;
        second.blend.sharpness = 4.0;
        saveProject(second, path);
        QCOMPARE(readAll(path + QStringLiteral(".bak")), firstBytes);
        QCOMPARE(loadProject(path).blend.sharpness, 4.0);
        QCOMPARE(loadProject(path + QStringLiteral(".bak")).blend.sharpness, 1.75);
    }

    // A save killed at any instant leaves the project opening and a whole backup. The
    // save runs in a child stopped at every system call (ptrace), where a kill would leave the
    // files exactly as they are; the old save removed .bak before linking the new one.
    void backupSurvivesAKillAtEveryStep()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("p.celform"));
        const QString backup = path + QStringLiteral(".bak");
        ProjectData data = richProject();
        const double first = 1.25, second = 2.5, third = 5.0; // the versions' sharpness
        data.blend.sharpness = first;
        saveProject(data, path);
        data.blend.sharpness = second;
        saveProject(data, path);
        QCOMPARE(loadProject(backup, DrawingImages::Skip).blend.sharpness, first);
        // A staged backup left by an interrupted save is replaced, not trusted.
        writeAll(path + QStringLiteral(".bak.new"), "left over");
        data.blend.sharpness = third;

        std::fflush(stdout);
        std::fflush(stderr);
        const pid_t pid = ::fork();
        if (pid == 0) {
            ::ptrace(PTRACE_TRACEME, 0, nullptr, nullptr);
            ::raise(SIGSTOP);
            try {
                saveProject(data, path);
            } catch (...) {
                ::_exit(1);
            }
            ::_exit(0);
        }
        int status = 0;
        ::waitpid(pid, &status, 0);
        if (!WIFSTOPPED(status)
            || ::ptrace(PTRACE_SETOPTIONS, pid, nullptr, PTRACE_O_TRACESYSGOOD | PTRACE_O_EXITKILL) != 0) {
            ::kill(pid, SIGKILL);
            ::waitpid(pid, &status, 0);
            QSKIP("ptrace is not allowed here");
        }
        auto sharpnessOf = [](const QString& file) {
            try {
                return loadProject(file, DrawingImages::Skip).blend.sharpness;
            } catch (const IoError&) {
                return -1.0;
            }
        };
        int stops = 0;
        QString broken;
        int signal = 0;
        while (broken.isEmpty()) {
            if (::ptrace(PTRACE_SYSCALL, pid, nullptr, reinterpret_cast<void*>(qintptr(signal))) != 0)
                break;
            ::waitpid(pid, &status, 0);
            if (WIFEXITED(status) || WIFSIGNALED(status))
                break;
            signal = 0;
            if (WSTOPSIG(status) != (SIGTRAP | 0x80)) {
                signal = WSTOPSIG(status); // not a system call: pass the signal on
                continue;
            }
            ++stops;
            const double current = sharpnessOf(path), previous = sharpnessOf(backup);
            if ((current != second && current != third) || (previous != first && previous != second))
                broken = QStringLiteral("at system call stop %1 the project reads %2 and its backup %3 (-1: none)")
                             .arg(stops)
                             .arg(current)
                             .arg(previous);
        }
        if (!broken.isEmpty()) {
            ::kill(pid, SIGKILL);
            ::waitpid(pid, &status, 0);
            QFAIL(qPrintable(broken));
        }
        QVERIFY2(WIFEXITED(status) && WEXITSTATUS(status) == 0, "the traced save failed");
        QVERIFY(stops > 10);
        QCOMPARE(sharpnessOf(path), third);
        QCOMPARE(sharpnessOf(backup), second);
        QVERIFY(!QFileInfo::exists(path + QStringLiteral(".bak.new")));
    }

    // The header's flags word is 0 in every version so far; a file that sets it is refused.
    void refusesUnknownHeaderFlags()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("flags.celform"));
        saveProject(richProject(), path);
        QByteArray bytes = readAll(path);
        qToLittleEndian<quint32>(quint32(4), bytes.data() + 12);
        writeAll(path, bytes);
        try {
            loadProject(path);
            QFAIL("a file with header flags was read");
        } catch (const IoError& e) {
            QVERIFY2(e.problem().contains(QStringLiteral("unknown flags")), qPrintable(e.message()));
        }
    }

    // Saving through a symbolic link replaces and backs up the file it names; the link stays a link
    // and the backup holds the previous version (a backup made of the link itself showed the new one).
    void saveThroughALinkBacksUpTheTarget()
    {
        QTemporaryDir dir;
        const QString real = dir.filePath(QStringLiteral("real.celform"));
        const QString link = dir.filePath(QStringLiteral("link.celform"));
        ProjectData first = richProject();
        saveProject(first, real);
        const QByteArray firstBytes = readAll(real);
        QVERIFY(QFile::link(real, link));
        ProjectData second = first;
        second.blend.sharpness = 4.0;
        saveProject(second, link);
        QVERIFY(QFileInfo(link).isSymLink());
        QCOMPARE(loadProject(real).blend.sharpness, 4.0);
        QCOMPARE(readAll(real + QStringLiteral(".bak")), firstBytes);
        QVERIFY(!QFileInfo::exists(link + QStringLiteral(".bak")));
    }

    // A value that is not finite is never written (the reader would refuse the file): the save
    // is refused naming where it stands, and the file on disk keeps its previous version.
    void refusesToSaveValuesThatAreNotFinite()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("p.celform"));
        saveProject(richProject(), path);
        const QByteArray before = readAll(path);
        ProjectData bad = richProject();
        bad.blend.sharpness = std::numeric_limits<double>::quiet_NaN();
        try {
            saveProject(bad, path);
            QFAIL("a NaN was saved");
        } catch (const IoError& e) {
            QVERIFY2(e.problem().contains(QStringLiteral("sharpness")), qPrintable(e.message()));
            QVERIFY2(e.problem().contains(QStringLiteral("not a finite number")), qPrintable(e.message()));
        }
        QCOMPARE(readAll(path), before);
        ProjectData badMesh = richProject();
        auto mesh = std::make_shared<algo::TriMesh>(*badMesh.baseMesh);
        mesh->vertices(0, 1) = std::numeric_limits<float>::infinity();
        badMesh.baseMesh = mesh;
        QVERIFY_THROWS_EXCEPTION(IoError, saveProject(badMesh, path));
        QCOMPARE(readAll(path), before);
    }

    void failedSaveLeavesFileIntact()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("p.celform"));
        saveProject(richProject(), path);
        const QByteArray before = readAll(path);
        // A save into a folder that does not exist fails cleanly and touches nothing.
        QVERIFY_THROWS_EXCEPTION(
            IoError, saveProject(richProject(), dir.filePath(QStringLiteral("no/such/dir/p.celform"))));
        QCOMPARE(readAll(path), before);
    }

    void refusesBadFiles_data()
    {
        QTest::addColumn<QString>("kind");
        QTest::addColumn<QString>("expected");
        QTest::newRow("missing") << "missing"
                                 << "does not exist";
        QTest::newRow("empty") << "empty"
                               << "is empty";
        QTest::newRow("not a project") << "text"
                                       << "not a Celform project";
        QTest::newRow("newer version") << "newer"
                                       << "newer version of Celform";
        QTest::newRow("truncated") << "truncated"
                                   << "truncated";
        QTest::newRow("truncated to header") << "header"
                                             << "truncated";
        QTest::newRow("flipped byte in mesh") << "flip-chunk"
                                              << "checksum";
        QTest::newRow("flipped byte in manifest") << "flip-manifest"
                                                  << "checksum";
    }

    void refusesBadFiles()
    {
        QFETCH(QString, kind);
        QFETCH(QString, expected);
        QTemporaryDir dir;
        const QString good = dir.filePath(QStringLiteral("good.celform"));
        saveProject(richProject(), good);
        QByteArray bytes = readAll(good);
        const QString bad = dir.filePath(QStringLiteral("bad.celform"));
        if (kind == "empty")
            writeAll(bad, {});
        else if (kind == "text")
            writeAll(bad, "this is a text file, not a project\n");
        else if (kind == "newer") {
            qToLittleEndian<quint32>(quint32(kProjectFormatVersion + 1), bytes.data() + 8);
            writeAll(bad, bytes);
        } else if (kind == "truncated")
            writeAll(bad, bytes.left(bytes.size() / 2));
        else if (kind == "header")
            writeAll(bad, bytes.left(12));
        else if (kind == "flip-chunk") {
            bytes[20] = char(bytes[20] ^ 0x5a); // inside the first chunk (mesh vertices)
            writeAll(bad, bytes);
        } else if (kind == "flip-manifest") {
            const int pos = int(bytes.indexOf("\"format_version\""));
            QVERIFY(pos > 0);
            bytes[pos + 3] = char(bytes[pos + 3] ^ 0x01);
            writeAll(bad, bytes);
        }
        try {
            loadProject(bad);
            QFAIL("a bad file was accepted");
        } catch (const IoError& e) {
            QVERIFY2(e.message().contains(expected), qPrintable(e.message()));
            QVERIFY2(e.message().contains(QStringLiteral("bad.celform")), qPrintable(e.message()));
        }
    }

    // Handcrafted files that crashed, or allocated gigabytes before their refusal, each
    // named after what it triggers (tests/data/fuzz-regressions/README.md). Every one is refused at
    // once, in one line naming the file, within a small memory budget.
    void refusesFuzzRegressions_data()
    {
        QTest::addColumn<QString>("path");
        QTest::addColumn<QString>("expected");
        const QDir dir(celform::test::testDataPath(QStringLiteral("fuzz-regressions/project")));
        const QStringList files = dir.entryList({QStringLiteral("*.celform")}, QDir::Files, QDir::Name);
        QVERIFY(!files.isEmpty());
        for (const QString& name : files) {
            const QString expected = name.startsWith(QLatin1String("drawing-")) ? QStringLiteral("too large")
                : name.startsWith(QLatin1String("trailer-"))                    ? QStringLiteral("table of contents")
                                                                                : QStringLiteral("damaged");
            QTest::newRow(qPrintable(name)) << dir.filePath(name) << expected;
        }
    }

    void refusesFuzzRegressions()
    {
        QFETCH(QString, path);
        QFETCH(QString, expected);
        const ChildOutcome outcome = runInChild([&] { loadProject(path); });
        QVERIFY2(outcome.kind == ChildOutcome::IoErrorThrown, qPrintable(outcome.describe()));
        QVERIFY2(outcome.message.startsWith(path), qPrintable(outcome.message));
        QVERIFY2(outcome.message.contains(expected), qPrintable(outcome.message));
        QVERIFY2(!outcome.message.contains(QLatin1Char('\n')), qPrintable(outcome.message));
        QVERIFY2(outcome.milliseconds < 5000, qPrintable(outcome.describe()));
    }

    // The trailer's and the chunk table's bounds are checked by subtraction, against the data's end.
    void refusesOffsetsOutsideTheFile_data()
    {
        QTest::addColumn<QString>("entry");
        QTest::addColumn<double>("value");
        QTest::addColumn<QString>("expected");
        QTest::newRow("offset 2^64") << "offset" << 18446744073709551616.0 << "out of range";
        QTest::newRow("offset 2^53") << "offset" << 9007199254740992.0 << "outside the file";
        QTest::newRow("offset fractional") << "offset" << 16.5 << "out of range";
        QTest::newRow("offset negative") << "offset" << -8.0 << "out of range";
        QTest::newRow("offset in the header") << "offset" << 8.0 << "outside the file";
        QTest::newRow("offset at the manifest") << "offset" << -1.0 << "outside the file"; // -1: the manifest's
        QTest::newRow("size 2^53") << "size" << 9007199254740992.0 << "outside the file";
        QTest::newRow("size past the manifest") << "size" << -1.0 << "outside the file"; // -1: to the manifest + 1
        QTest::newRow("crc 2^32") << "crc32" << 4294967296.0 << "out of range";
    }

    void refusesOffsetsOutsideTheFile()
    {
        QFETCH(QString, entry);
        QFETCH(double, value);
        QFETCH(QString, expected);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("offsets.celform"));
        saveProject(richProject(), path);
        editManifest(path, [&](QJsonObject& m) {
            QJsonObject chunks = m.value("chunks").toObject();
            QJsonObject faces = chunks.value("mesh/faces").toObject();
            const QByteArray bytes = readAll(path);
            const auto manifestOffset = double(qFromLittleEndian<quint64>(bytes.constData() + bytes.size() - 32));
            if (value != -1.0)
                faces.insert(entry, value);
            else if (entry == QLatin1String("offset"))
                faces.insert(entry, manifestOffset);
            else
                faces.insert(entry, manifestOffset - faces.value("offset").toDouble() + 1);
            chunks.insert("mesh/faces", faces);
            m.insert("chunks", chunks);
        });
        const ChildOutcome outcome = runInChild([&] { loadProject(path); });
        QVERIFY2(outcome.kind == ChildOutcome::IoErrorThrown, qPrintable(outcome.describe()));
        QVERIFY2(outcome.message.contains(expected), qPrintable(outcome.message));
        QVERIFY2(outcome.message.contains(QStringLiteral("offsets.celform")), qPrintable(outcome.message));
    }

    // Numbers that become ids, frames or counts are checked before the cast, and a block serves
    // one entry only (a block named by many entries multiplied what was allocated).
    void refusesBadNumbersAndSharedBlocks_data()
    {
        QTest::addColumn<QString>("edit");
        QTest::addColumn<QString>("expected");
        QTest::newRow("face set block used twice") << "shared-block"
                                                   << "used twice";
        QTest::newRow("face set longer than the faces") << "face-set-count"
                                                        << "more faces than the model";
        QTest::newRow("key moves more vertices than there are") << "key-count"
                                                                << "more vertices than the model";
        QTest::newRow("key frame 1e300") << "key-frame"
                                         << "not a frame number";
        QTest::newRow("drawing frame 2.5") << "drawing-frame"
                                           << "not a frame number";
        QTest::newRow("drawing id -1") << "drawing-id"
                                       << "out of range";
        QTest::newRow("linked drawing id 1e300") << "linked-id"
                                                 << "out of range";
        QTest::newRow("next_id 2^64") << "next-id"
                                      << "out of range";
        // What `celform set` and the format refuse is refused when read, too.
        QTest::newRow("sharpness 0") << "sharpness-0"
                                     << "sharpness";
        QTest::newRow("sharpness 1e308") << "sharpness-huge"
                                         << "sharpness";
        QTest::newRow("sharpness -1e308") << "sharpness-negative"
                                          << "sharpness";
        QTest::newRow("drawing opacity 1.5") << "opacity"
                                             << "opacity outside 0 to 1";
        QTest::newRow("key linked to a missing drawing") << "missing-drawing"
                                                         << "does not hold";
        QTest::newRow("a key with a drawing's id") << "duplicate-id"
                                                   << "of another object";
        QTest::newRow("format_version \"two\"") << "version-text"
                                                << "not a version number";
        QTest::newRow("key direction zero") << "zero-direction"
                                            << "view direction of zero length";
        QTest::newRow("outline closing radius 1e9") << "outline-closing"
                                                    << "closing radius";
        QTest::newRow("outline threshold 2") << "outline-threshold"
                                             << "outline threshold";
    }

    void refusesBadNumbersAndSharedBlocks()
    {
        QFETCH(QString, edit);
        QFETCH(QString, expected);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("numbers.celform"));
        saveProject(richProject(), path);
        editManifest(path, [&](QJsonObject& m) {
            QJsonObject mesh = m.value("base_mesh").toObject();
            QJsonArray sets = mesh.value("face_sets").toArray();
            QJsonArray drawings = m.value("drawings").toArray();
            QJsonObject drawing = drawings.first().toObject();
            QJsonArray keys = m.value("keys").toArray();
            QJsonObject key = keys.first().toObject();
            QJsonArray frames = key.value("frames").toArray();
            QJsonObject frame = frames.first().toObject();
            if (edit == QLatin1String("shared-block")) {
                QJsonObject twin = sets.first().toObject();
                twin.insert("name", QStringLiteral("twin"));
                sets.append(twin);
            } else if (edit == QLatin1String("face-set-count")) {
                QJsonObject set = sets.first().toObject();
                set.insert("count", 5); // the mesh has 4 faces
                sets.replace(0, set);
            } else if (edit == QLatin1String("key-count")) {
                frame.insert("count", 6); // the mesh has 5 vertices
            } else if (edit == QLatin1String("key-frame")) {
                frame.insert("frame", 1e300);
            } else if (edit == QLatin1String("drawing-frame")) {
                drawing.insert("frame", 2.5);
            } else if (edit == QLatin1String("drawing-id")) {
                drawing.insert("id", -1);
            } else if (edit == QLatin1String("linked-id")) {
                key.insert("drawings", QJsonArray{1e300});
            } else if (edit == QLatin1String("next-id")) {
                m.insert("next_id", 18446744073709551616.0);
            } else if (edit.startsWith(QLatin1String("sharpness"))) {
                QJsonObject blend = m.value("blend").toObject();
                blend.insert("sharpness",
                    edit.endsWith(QLatin1String("-0"))         ? 0.0
                        : edit.endsWith(QLatin1String("huge")) ? 1e308
                                                               : -1e308);
                m.insert("blend", blend);
            } else if (edit == QLatin1String("opacity")) {
                drawing.insert("opacity", 1.5);
            } else if (edit == QLatin1String("missing-drawing")) {
                key.insert("drawings", QJsonArray{double(m.value("next_id").toDouble() - 1)});
            } else if (edit == QLatin1String("duplicate-id")) {
                key.insert("id", drawing.value("id"));
                key.insert("drawings", QJsonArray{});
            } else if (edit == QLatin1String("version-text")) {
                m.insert("format_version", QStringLiteral("two"));
            } else if (edit == QLatin1String("zero-direction")) {
                key.insert("direction", QJsonArray{0.0, 0.0, 0.0});
            } else if (edit.startsWith(QLatin1String("outline-"))) {
                QJsonObject outline = drawing.value("outline").toObject();
                if (edit.endsWith(QLatin1String("closing")))
                    outline.insert("closing_radius", 1e9);
                else
                    outline.insert("threshold", 2.0);
                drawing.insert("outline", outline);
            }
            mesh.insert("face_sets", sets);
            m.insert("base_mesh", mesh);
            drawings.replace(0, drawing);
            m.insert("drawings", drawings);
            frames.replace(0, frame);
            key.insert("frames", frames);
            keys.replace(0, key);
            m.insert("keys", keys);
        });
        const ChildOutcome outcome = runInChild([&] { loadProject(path); });
        QVERIFY2(outcome.kind == ChildOutcome::IoErrorThrown, qPrintable(outcome.describe()));
        QVERIFY2(outcome.message.contains(expected), qPrintable(outcome.message));
        QVERIFY2(outcome.message.contains(QStringLiteral("numbers.celform")), qPrintable(outcome.message));
    }

    // A named pipe given as a project blocked in open() for ever, waiting for a writer;
    // anything but a regular file is refused before it is opened.
    void refusesPipesAndFolders_data()
    {
        QTest::addColumn<QString>("kind");
        QTest::newRow("named pipe") << "fifo";
        QTest::newRow("folder") << "folder";
        QTest::newRow("device") << "device";
    }

    void refusesPipesAndFolders()
    {
        QFETCH(QString, kind);
        QTemporaryDir dir;
        QString path = dir.filePath(QStringLiteral("special.celform"));
        if (kind == QLatin1String("fifo"))
            QCOMPARE(::mkfifo(QFile::encodeName(path).constData(), 0600), 0);
        else if (kind == QLatin1String("folder"))
            QVERIFY(QDir(dir.path()).mkdir(QStringLiteral("special.celform")));
        else
            path = QStringLiteral("/dev/zero");
        const ChildOutcome outcome = runInChild([&] { loadProject(path); }, 512ll << 20, 5000);
        QVERIFY2(outcome.kind == ChildOutcome::IoErrorThrown, qPrintable(outcome.describe()));
        QVERIFY2(outcome.message.startsWith(path + QStringLiteral(": ")), qPrintable(outcome.message));
        QVERIFY2(outcome.message.contains(QStringLiteral("not a regular file")), qPrintable(outcome.message));
    }

    void failedOpenLeavesDocumentUntouched()
    {
        QTemporaryDir dir;
        const QString good = dir.filePath(QStringLiteral("good.celform"));
        saveProject(richProject(), good);
        Document doc;
        doc.open(good);
        doc.look().setSharpness(3.0);
        const ProjectData before = doc.data();
        const int undoCount = doc.undoStack()->count();

        QByteArray bytes = readAll(good);
        const QString truncated = dir.filePath(QStringLiteral("truncated.celform"));
        writeAll(truncated, bytes.left(bytes.size() - 10));
        QVERIFY_THROWS_EXCEPTION(IoError, doc.open(truncated));
        QVERIFY(doc.data() == before);
        QCOMPARE(doc.undoStack()->count(), undoCount);
        QCOMPARE(doc.filePath(), QFileInfo(good).absoluteFilePath());
        QVERIFY(doc.isModified());
    }

    void documentSaveMarksClean()
    {
        QTemporaryDir dir;
        Document doc;
        doc.reset(richProject());
        doc.keys().renameKey(2, QStringLiteral("renamed"));
        QVERIFY(doc.isModified());
        const QString path = dir.filePath(QStringLiteral("saved.celform"));
        doc.saveAs(path);
        QVERIFY(!doc.isModified());
        QCOMPARE(doc.filePath(), QFileInfo(path).absoluteFilePath());
        Document other;
        other.open(path);
        QVERIFY(other.data() == doc.data());
    }

    // Key layers of shading offsets: kept through a save, refused with the file's
    // name when a count or a value is wrong.
    void keyShadingOffsetsRoundTripAndRefusals_data()
    {
        QTest::addColumn<QString>("damage");
        QTest::newRow("intact") << QString();
        QTest::newRow("count") << QStringLiteral("count");
        QTest::newRow("not finite") << QStringLiteral("nan");
    }
    void keyShadingOffsetsRoundTripAndRefusals()
    {
        QFETCH(QString, damage);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("layers.celform"));
        ProjectData data = richProject();
        const std::size_t n = std::size_t(data.baseMesh->vertexCount());
        data.keys.front().shadingOffsetsByFrame[0] = std::vector<float>(n, 0.25f);
        data.keys.front().shadingOffsetsByFrame[7] = std::vector<float>(n, -0.5f);
        if (damage == QLatin1String("nan")) {
            // The writer refuses it; a file damaged afterwards (its checksum made to match) is
            // refused by the reader.
            ProjectData bad = data;
            bad.keys.front().shadingOffsetsByFrame[7][1] = std::numeric_limits<float>::quiet_NaN();
            QVERIFY_THROWS_EXCEPTION(IoError, saveProject(bad, path));
            QVERIFY(!QFileInfo::exists(path));
        }
        saveProject(data, path);
        if (damage == QLatin1String("nan")) {
            const QString name = QStringLiteral("keys/%1/shading_offsets/7").arg(data.keys.front().id);
            qsizetype offset = 0, size = 0;
            editManifest(path, [&](QJsonObject& m) {
                const QJsonObject chunk = m.value("chunks").toObject().value(name).toObject();
                offset = qsizetype(chunk.value("offset").toDouble());
                size = qsizetype(chunk.value("size").toDouble());
            });
            QVERIFY(size > qsizetype(2 * sizeof(float)));
            QByteArray bytes = readAll(path);
            const float nan = std::numeric_limits<float>::quiet_NaN();
            std::memcpy(bytes.data() + offset + qsizetype(sizeof(float)), &nan, sizeof(float));
            writeAll(path, bytes);
            editManifest(path, [&](QJsonObject& m) {
                QJsonObject chunks = m.value("chunks").toObject();
                QJsonObject chunk = chunks.value(name).toObject();
                chunk.insert("crc32", double(crc32(bytes.mid(offset, size))));
                chunks.insert(name, chunk);
                m.insert("chunks", chunks);
            });
        }
        if (damage == QLatin1String("count")) {
            editManifest(path, [&](QJsonObject& m) {
                QJsonArray keys = m.value("keys").toArray();
                QJsonObject key = keys.first().toObject();
                QJsonArray layers = key.value("shading_offsets").toArray();
                QJsonObject layer = layers.first().toObject();
                layer.insert("count", double(n - 1));
                layers.replace(0, layer);
                key.insert("shading_offsets", layers);
                keys.replace(0, key);
                m.insert("keys", keys);
            });
        }
        if (damage.isEmpty()) {
            QVERIFY(loadProject(path) == data);
            return;
        }
        const ChildOutcome outcome = runInChild([&] { loadProject(path); });
        QVERIFY2(outcome.kind == ChildOutcome::IoErrorThrown, qPrintable(outcome.describe()));
        QVERIFY2(outcome.message.contains(QStringLiteral("shading offset")), qPrintable(outcome.message));
        QVERIFY2(outcome.message.contains(QStringLiteral("layers.celform")), qPrintable(outcome.message));
    }
};

QTEST_GUILESS_MAIN(TestProjectFile)
#include "test_project_file.moc"
