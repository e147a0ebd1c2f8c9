// Reading .celform files (layout in docs/file-format.md): the trailer locates the manifest, every
// chunk is checked against the file (sizes by subtraction, CRC-32) before anything is allocated,
// and the manifest is read into a ProjectData. Writing is project_file.cpp.
#include "celform/model/io/project_file.h"
#include "celform/model/io/project_file_format.h"

#include "celform/algorithms/mesh_analysis.h"
#include "celform/algorithms/stroke_refine.h"
#include "celform/model/io/image_io.h"
#include "celform/model/data/io_error.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtEndian>

#include <zlib.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <new>
#include <set>

#include <unistd.h>

namespace celform::model {
namespace {

using namespace project_format;

// --- reading ----------------------------------------------------------------------------------

/// Reads the manifest's values, throwing IoError with the file name on anything malformed.
class Reader {
public:
    /// dataEnd: where the data blocks end (the manifest's offset); no block may reach past it.
    Reader(QString path, const char* bytes, qint64 dataEnd, QJsonObject chunks)
        : m_path(std::move(path))
        , m_bytes(bytes)
        , m_dataEnd(dataEnd)
        , m_chunks(std::move(chunks))
    { }

    [[noreturn]] void fail(const QString& problem) const { throw IoError(m_path, problem); }
    [[noreturn]] void corrupt(const QString& what) const { fail(ProjectFile::tr("is damaged: %1").arg(what)); }

    QJsonValue member(const QJsonObject& o, const char* name, QJsonValue::Type type) const
    {
        const QJsonValue v = o.value(QLatin1String(name));
        if (v.type() != type)
            corrupt(ProjectFile::tr("the entry “%1” is missing or has the wrong type").arg(QLatin1String(name)));
        return v;
    }
    double number(const QJsonObject& o, const char* name) const
    {
        const double d = member(o, name, QJsonValue::Double).toDouble();
        if (!std::isfinite(d))
            corrupt(ProjectFile::tr("the entry “%1” is not a finite number").arg(QLatin1String(name)));
        return d;
    }
    qint64 count(const QJsonObject& o, const char* name) const
    {
        const double d = number(o, name);
        if (d < 0 || d > double(std::numeric_limits<std::int32_t>::max()) || d != std::floor(d))
            corrupt(ProjectFile::tr("the count “%1” is out of range").arg(QLatin1String(name)));
        return qint64(d);
    }
    /// A whole number in [0, max] that locates or sizes bytes of the file. JSON numbers are doubles,
    /// so anything above 2^53 (or fractional, or negative) is refused before it becomes an integer.
    qint64 position(const QJsonObject& o, const char* name, qint64 max) const
    {
        const double d = number(o, name);
        if (d < 0 || d > double(max) || d != std::floor(d))
            corrupt(ProjectFile::tr("the entry “%1” is out of range").arg(QLatin1String(name)));
        return qint64(d);
    }
    /// An object id: a whole number that a double holds exactly (a cast of -1 or 1e300 to an
    /// unsigned id is undefined).
    ObjectId objectId(const QJsonObject& o, const char* name) const
    {
        return ObjectId(position(o, name, qint64(1) << 53));
    }
    /// A frame number of a key or drawing: whole, within +-kMaxFrame as the playhead's.
    int frame(const QJsonObject& o, const char* name) const
    {
        const double d = number(o, name);
        if (d != std::floor(d) || std::abs(d) > double(kMaxFrame))
            corrupt(ProjectFile::tr("the entry “%1” is not a frame number").arg(QLatin1String(name)));
        return int(d);
    }
    QString string(const QJsonObject& o, const char* name) const
    {
        return member(o, name, QJsonValue::String).toString();
    }
    bool boolean(const QJsonObject& o, const char* name) const { return member(o, name, QJsonValue::Bool).toBool(); }
    QJsonObject object(const QJsonObject& o, const char* name) const
    {
        return member(o, name, QJsonValue::Object).toObject();
    }
    QJsonArray array(const QJsonObject& o, const char* name) const
    {
        return member(o, name, QJsonValue::Array).toArray();
    }
    Vec3 vector3(const QJsonObject& o, const char* name) const
    {
        const QJsonArray a = array(o, name);
        if (a.size() != 3 || !a[0].isDouble() || !a[1].isDouble() || !a[2].isDouble())
            corrupt(ProjectFile::tr("the entry “%1” is not a 3D vector").arg(QLatin1String(name)));
        Eigen::Vector3d v(a[0].toDouble(), a[1].toDouble(), a[2].toDouble());
        if (!v.allFinite())
            corrupt(ProjectFile::tr("the entry “%1” is not finite").arg(QLatin1String(name)));
        return v;
    }
    template <typename E> E enumValue(const QJsonObject& o, const char* name) const
    {
        const QString s = string(o, name);
        for (const auto& [v, n] : EnumNames<E>::list)
            if (s == QLatin1String(n))
                return v;
        corrupt(ProjectFile::tr("the entry “%1” has the unknown value “%2”").arg(QLatin1String(name), s));
    }
    Camera camera(const QJsonObject& o) const
    {
        Camera c;
        c.eye = vector3(o, "eye");
        c.target = vector3(o, "target");
        c.up = vector3(o, "up");
        c.projection = enumValue<Projection>(o, "projection");
        c.fovYDegrees = number(o, "fov_y_degrees");
        c.orthoHeight = number(o, "ortho_height");
        return c;
    }

    /// The verified bytes of a chunk named by o[name]; expectedSize < 0 accepts any size.
    std::pair<const char*, qint64> chunk(const QJsonObject& o, const char* name, qint64 expectedSize) const
    {
        const QString chunkName = string(o, name);
        const QJsonValue entry = m_chunks.value(chunkName);
        if (!entry.isObject())
            corrupt(ProjectFile::tr("the data block “%1” is missing").arg(chunkName));
        // Each block describes one thing. A block named many times over would multiply what the
        // reader allocates (a thousand face sets on one large block) beyond the file's own size.
        if (!m_used.insert(chunkName).second)
            corrupt(ProjectFile::tr("the data block “%1” is used twice").arg(chunkName));
        const QJsonObject e = entry.toObject();
        constexpr qint64 kMaxExact = qint64(1) << 53; // every integer up to here is exact as a double
        const qint64 offset = position(e, "offset", kMaxExact);
        const qint64 size = position(e, "size", kMaxExact);
        const auto crc = quint32(position(e, "crc32", std::numeric_limits<quint32>::max()));
        // By subtraction: offset + size could pass a limit by wrapping around (as the trailer's did).
        if (offset < kHeaderSize || offset > m_dataEnd || size > m_dataEnd - offset)
            corrupt(ProjectFile::tr("the data block “%1” lies outside the file").arg(chunkName));
        if (expectedSize >= 0 && size != expectedSize)
            corrupt(ProjectFile::tr("the data block “%1” has %2 bytes instead of %3")
                        .arg(chunkName)
                        .arg(size)
                        .arg(expectedSize));
        const char* p = m_bytes + offset;
        if (crc32Of(p, size) != crc)
            corrupt(ProjectFile::tr("the data block “%1” fails its checksum").arg(chunkName));
        return {p, size};
    }
    /// Reads a matrix of rows rows from a chunk. The chunk's size is checked against rows before
    /// anything is allocated: a count from the manifest is only believed once its block holds it, so
    /// a count of 2^31 over a 48-byte block costs nothing.
    template <typename Matrix>
    void readMatrix(const QJsonObject& o, const char* name, Eigen::Index rows, Matrix& m) const
    {
        constexpr qint64 rowBytes = qint64(Matrix::ColsAtCompileTime) * qint64(sizeof(typename Matrix::Scalar));
        const auto [p, size] = chunk(o, name, qint64(rows) * rowBytes);
        m.resize(rows, Matrix::ColsAtCompileTime);
        if (size > 0) // an empty matrix has no data pointer, and memcpy's may not be null even for 0 bytes
            std::memcpy(m.data(), p, std::size_t(size));
    }
    /// The same for a vector of n items.
    template <typename T> void readVector(const QJsonObject& o, const char* name, qint64 n, std::vector<T>& v) const
    {
        const auto [p, size] = chunk(o, name, n * qint64(sizeof(T)));
        v.resize(std::size_t(n));
        if (size > 0) // a key frame that moves no vertex: v.data() is null (see readMatrix)
            std::memcpy(static_cast<void*>(v.data()), p, std::size_t(size));
    }

private:
    QString m_path;
    const char* m_bytes;
    qint64 m_dataEnd;
    QJsonObject m_chunks;
    mutable std::set<QString> m_used; ///< the chunks read so far
};

std::vector<float> readFloats(const Reader& r, const QJsonObject& o, const char* name)
{
    std::vector<float> values;
    for (const QJsonValue& v : r.array(o, name)) {
        if (!v.isDouble() || !std::isfinite(v.toDouble()))
            r.corrupt(ProjectFile::tr("the entry “%1” holds something that is not a number").arg(QLatin1String(name)));
        values.push_back(float(v.toDouble()));
    }
    return values;
}

/// A number in [lo, hi] (a whole one when whole is set), else the file is damaged.
float rangedNumber(const Reader& r, const QJsonObject& o, const char* name, double lo, double hi, bool whole = false)
{
    const double d = r.number(o, name);
    if (d < lo || d > hi || (whole && d != std::floor(d)))
        r.corrupt(ProjectFile::tr("the entry “%1” is out of range").arg(QLatin1String(name)));
    return float(d);
}

Eigen::Matrix3f readMatrix3(const Reader& r, const QJsonObject& o, const char* name)
{
    const QJsonArray rows = r.array(o, name);
    if (rows.size() != 3)
        r.corrupt(ProjectFile::tr("the entry “%1” is not a 3 by 3 matrix").arg(QLatin1String(name)));
    Eigen::Matrix3f m;
    for (int i = 0; i < 3; ++i) {
        const QJsonObject wrapper{{"row", rows[i]}};
        m.row(i) = r.vector3(wrapper, "row").cast<float>().transpose();
    }
    return m;
}

/// Highlight tracks; their references (face sets, other tracks) are checked by the caller.
std::vector<HighlightTrack> readHighlights(const Reader& r, const QJsonArray& array)
{
    std::vector<HighlightTrack> tracks;
    for (const QJsonValue& tv : array) {
        if (!tv.isObject())
            r.corrupt(ProjectFile::tr("a highlight layer is not an object"));
        const QJsonObject o = tv.toObject();
        HighlightTrack t;
        // Optional: files from before highlight ids have none (Document::reset gives them).
        if (o.contains(QLatin1String("id")))
            t.id = ObjectId(r.count(o, "id"));
        t.name = r.string(o, "name");
        t.patch = r.string(o, "patch");
        t.guide = r.vector3(o, "guide").cast<float>();
        t.visible = r.boolean(o, "visible");
        // Optional: files from before normal smoothing have none.
        if (o.contains(QLatin1String("normal_smoothing"))) {
            const qint64 rounds = r.count(o, "normal_smoothing");
            if (rounds > kMaxHighlightSmoothing)
                r.corrupt(ProjectFile::tr("the count “%1” is out of range").arg(QLatin1String("normal_smoothing")));
            t.smoothing = int(rounds);
        }
        for (const QJsonValue& cv : r.array(o, "combine")) {
            const QJsonObject c = cv.toObject();
            const QString mode = r.string(c, "mode");
            if (mode != QLatin1String("union") && mode != QLatin1String("subtract"))
                r.corrupt(ProjectFile::tr("the entry “mode” has the unknown value “%1”").arg(mode));
            t.combineWith.emplace_back(
                mode == QLatin1String("union") ? algo::HighlightBoolean::Union : algo::HighlightBoolean::Subtraction,
                r.string(c, "layer"));
        }
        for (const QJsonValue& kv : r.array(o, "keys")) {
            const QJsonObject k = kv.toObject();
            algo::HighlightKey key;
            key.frame = r.number(k, "frame");
            key.layer.color = r.vector3(k, "color").cast<float>();
            key.layer.shape.epsilon = float(r.number(k, "epsilon"));
            key.layer.offSpecularCut = float(r.number(k, "off_specular_cut"));
            for (const QJsonValue& ov : r.array(k, "operations")) {
                const QJsonObject op = ov.toObject();
                const QString typeName = r.string(op, "type");
                const auto type = highlightOperationType(typeName);
                if (!type)
                    r.corrupt(ProjectFile::tr("the highlight operation “%1” is unknown").arg(typeName));
                const std::vector<float> values = readFloats(r, op, "values");
                if (int(values.size()) != highlightOperationArity(*type))
                    r.corrupt(ProjectFile::tr("the highlight operation “%1” has %2 values instead of %3")
                                  .arg(typeName)
                                  .arg(values.size())
                                  .arg(highlightOperationArity(*type)));
                key.layer.shape.operations.push_back({*type, values[0], values.size() > 1 ? values[1] : 0.f});
            }
            t.keys.push_back(std::move(key));
        }
        tracks.push_back(std::move(t));
    }
    return tracks;
}

/// The look; every part but the style, light, background and lines switch is optional, so
/// projects from before the cartoon look still open with its defaults.
Look readLook(const Reader& r, const QJsonObject& look)
{
    Look out;
    out.style = r.enumValue<ShadingStyle>(look, "style");
    const QJsonObject light = r.object(look, "light");
    out.light.type = r.enumValue<LightType>(light, "type");
    out.light.vector = r.vector3(light, "vector");
    out.backgroundColor = r.vector3(look, "background").cast<float>();
    out.showLines = r.boolean(look, "lines");
    if (look.contains("material_styles")) {
        const QJsonObject styles = r.object(look, "material_styles");
        for (auto it = styles.begin(); it != styles.end(); ++it) {
            bool ok = false;
            const int material = it.key().toInt(&ok);
            if (!ok)
                r.corrupt(ProjectFile::tr("a material style names no material"));
            out.materialStyles[material] = r.enumValue<ShadingStyle>(QJsonObject{{"style", it.value()}}, "style");
        }
    }
    if (look.contains("toon")) {
        const QJsonObject t = r.object(look, "toon");
        out.toon.thresholds = readFloats(r, t, "thresholds");
        out.toon.intensities = readFloats(r, t, "intensities");
        out.toonEvaluation = r.enumValue<algo::ToonEvaluation>(t, "evaluation");
        if (!out.toon.isValid())
            r.corrupt(ProjectFile::tr("the toon tones are not valid"));
    }
    if (look.contains("gooch")) {
        const QJsonObject g = r.object(look, "gooch");
        out.gooch.preset = r.string(g, "preset").toStdString();
        out.gooch.ka = float(r.number(g, "ka"));
        out.gooch.k1 = float(r.number(g, "k1"));
        out.gooch.k2 = float(r.number(g, "k2"));
        out.gooch.k3 = float(r.number(g, "k3"));
        out.gooch.k4 = float(r.number(g, "k4"));
        out.gooch.warm = r.vector3(g, "warm").cast<float>();
        out.gooch.cool = r.vector3(g, "cool").cast<float>();
    }
    if (look.contains("hatch")) {
        const QJsonObject h = r.object(look, "hatch");
        out.hatch.spacing = float(r.number(h, "spacing"));
        out.hatch.angleDegrees = float(r.number(h, "angle_degrees"));
        out.hatch.width = float(r.number(h, "width"));
    }
    if (look.contains("line_kinds")) {
        const QJsonObject k = r.object(look, "line_kinds");
        out.lines.silhouettes = r.boolean(k, "silhouettes");
        out.lines.creases = r.boolean(k, "creases");
        out.lines.borders = r.boolean(k, "borders");
        out.lines.materialBoundaries = r.boolean(k, "material_boundaries");
        out.lines.creaseAngleDegrees = float(r.number(k, "crease_angle_degrees"));
        // Crease hysteresis came with issue 25: older files get the default low angle.
        if (k.contains(QLatin1String("crease_low_angle_degrees")))
            out.lines.creaseLowAngleDegrees = rangedNumber(r, k, "crease_low_angle_degrees", 0.0, 180.0);
        // Apparent ridges came later: files without them load with ridges off.
        if (k.contains(QLatin1String("ridges")))
            out.lines.ridges = r.boolean(k, "ridges");
        if (k.contains(QLatin1String("ridge_threshold"))) {
            out.lines.ridgeThreshold = float(r.number(k, "ridge_threshold"));
            if (!(out.lines.ridgeThreshold >= 0.f))
                r.corrupt(ProjectFile::tr("the ridge threshold is negative"));
        }
        // Raw or joined ridges came with format 4: older files join them (the snakes).
        if (k.contains(QLatin1String("ridge_snakes")))
            out.lines.ridgeSnakes = r.boolean(k, "ridge_snakes");
        if (k.contains(QLatin1String("ridge_depth_strength")))
            out.lines.ridgeDepthStrength = float(rangedNumber(r, k, "ridge_depth_strength", 0.0, 100.0));
    }
    if (look.contains("line_style")) {
        const QJsonObject l = r.object(look, "line_style");
        out.lineStyle.color = r.vector3(l, "color").cast<float>();
        out.lineStyle.outlineWidth = float(r.number(l, "outline_width"));
        out.lineStyle.innerWidth = float(r.number(l, "inner_width"));
        out.lineStyle.jitter = float(r.number(l, "jitter"));
        out.lineStyle.widthVariation = float(r.number(l, "width_variation"));
        out.lineStyle.overshoot = float(r.number(l, "overshoot"));
        // Any 32-bit seed: the writer stores the whole range, so count()'s int32 limit is too tight.
        const double seed = r.number(l, "seed");
        if (seed < 0 || seed > double(std::numeric_limits<std::uint32_t>::max()) || seed != std::floor(seed))
            r.corrupt(ProjectFile::tr("the count “%1” is out of range").arg(QLatin1String("seed")));
        out.lineStyle.seed = std::uint32_t(seed);
        // The stroke clean-up came with issue 25: older files get its hand-drawn defaults.
        if (l.contains(QLatin1String("join_gap")))
            out.lineStyle.joinGap = rangedNumber(r, l, "join_gap", 0.0, 100.0);
        if (l.contains(QLatin1String("smoothing")))
            out.lineStyle.smoothing = int(rangedNumber(r, l, "smoothing", 0.0, double(algo::kMaxSmoothing), true));
        if (l.contains(QLatin1String("min_length")))
            out.lineStyle.minLength = rangedNumber(r, l, "min_length", 0.0, 1.0);
        if (l.contains(QLatin1String("taper")))
            out.lineStyle.taper = rangedNumber(r, l, "taper", 0.0, 1000.0);
        if (l.contains(QLatin1String("reduction")))
            out.lineStyle.reduction = rangedNumber(r, l, "reduction", 0.0, 1.0);
    }
    if (look.contains("stereo")) {
        const QJsonObject st = r.object(look, "stereo");
        out.stereo.output = r.enumValue<algo::StereoOutput>(st, "output");
        out.stereo.interocular = r.number(st, "interocular");
        out.stereo.convergence = r.number(st, "convergence");
        out.stereo.toeIn = r.boolean(st, "toe_in");
        out.stereo.swapEyes = r.boolean(st, "swap_eyes");
        out.stereo.dubois.left = readMatrix3(r, st, "dubois_left");
        out.stereo.dubois.right = readMatrix3(r, st, "dubois_right");
    }
    // Subdivision came later: files without it show the control mesh.
    if (look.contains("subdivision")) {
        const QJsonObject s = r.object(look, "subdivision");
        const double render = r.number(s, "render_level"), viewport = r.number(s, "viewport_level");
        out.subdivision.level = int(std::clamp(render, -2.0, 99.0));
        out.subdivision.viewportLevel = int(std::clamp(viewport, -2.0, 99.0));
        if (render != std::floor(render) || viewport != std::floor(viewport)
            || !subdivisionProblem(out.subdivision).isEmpty())
            r.corrupt(ProjectFile::tr("the subdivision levels are out of range"));
    }
    if (look.contains("highlights"))
        out.highlights = readHighlights(r, r.array(look, "highlights"));
    if (look.contains("render_camera")) {
        out.renderCamera = r.camera(r.object(look, "render_camera"));
        if (!out.renderCamera->isValid())
            r.corrupt(ProjectFile::tr("the render camera is not a camera (eye at the target, or up along the view)"));
    }
    if (look.contains("camera_path")) {
        for (const QJsonValue& v : r.array(look, "camera_path")) {
            const QJsonObject k = v.toObject();
            out.cameraPath.keys.push_back({r.frame(k, "frame"), r.camera(r.object(k, "camera"))});
        }
        const QString problem = cameraPathProblem(out.cameraPath);
        if (!problem.isEmpty())
            r.corrupt(ProjectFile::tr("the camera path is invalid: %1").arg(problem));
    }
    // The light track (format 3); absent in older files: the single light serves every frame.
    if (look.contains("light_keys")) {
        for (const QJsonValue& v : r.array(look, "light_keys")) {
            const QJsonObject k = v.toObject();
            const QJsonObject keyed = r.object(k, "light");
            out.lightTrack.keys.push_back(
                {r.frame(k, "frame"), Light{r.enumValue<LightType>(keyed, "type"), r.vector3(keyed, "vector")}});
        }
        const QString problem = lightTrackProblem(out.lightTrack);
        if (!problem.isEmpty())
            r.corrupt(ProjectFile::tr("the light track is invalid: %1").arg(problem));
    }
    return out;
}

/// The animated base (format 2): sizes checked against the base model and the data blocks before
/// anything is allocated, then algo::BaseAnimation::problem() as a last check.
std::shared_ptr<const algo::BaseAnimation> readBaseAnimation(
    const Reader& r, const QJsonObject& o, const algo::TriMesh& mesh)
{
    auto a = std::make_shared<algo::BaseAnimation>();
    a->firstFrame = r.frame(o, "first_frame");
    a->frameCount = int(r.count(o, "frame_count"));
    if (a->frameCount < 1 || qint64(a->firstFrame) + a->frameCount - 1 > kMaxFrame)
        r.corrupt(ProjectFile::tr("the base animation's frames are out of range"));
    const QJsonArray targets = r.array(o, "morph_targets");
    a->morphTargets.resize(std::size_t(targets.size()));
    for (int t = 0; t < targets.size(); ++t) {
        QJsonObject entry{{"block", targets[t]}};
        r.readMatrix(entry, "block", mesh.vertexCount(), a->morphTargets[std::size_t(t)]);
    }
    r.readVector(o, "morph_weights", qint64(targets.size()) * a->frameCount, a->morphWeights);
    if (o.contains(QLatin1String("vertex_frames"))) {
        // Format 4. The samples' frame numbers first: the block's size, checked against the
        // vertex count, then gives the number of stored frames.
        r.readVector(o, "vertex_frame_of_sample", a->frameCount, a->vertexFrameOfSample);
        const qint64 stored = r.count(o, "vertex_frame_count");
        if (stored < 1 || stored > a->frameCount)
            r.corrupt(ProjectFile::tr("the base animation's vertex frames are out of range"));
        r.readMatrix(o, "vertex_frames", Eigen::Index(stored) * mesh.vertexCount(), a->vertexFrames);
    }
    a->jointCount = int(r.count(o, "joint_count"));
    if (a->jointCount > 0) {
        if (a->jointCount > 65536)
            r.corrupt(ProjectFile::tr("the base animation has too many joints"));
        r.readVector(o, "joints", mesh.vertexCount(), a->joints);
        r.readVector(o, "joint_weights", mesh.vertexCount(), a->jointWeights);
        std::vector<algo::SkinMatrix> matrices;
        r.readVector(o, "skin_matrices", qint64(a->jointCount) * a->frameCount, matrices);
        a->skinMatrices.assign(matrices.begin(), matrices.end());
    }
    const std::string problem = a->problem(mesh.vertexCount());
    if (!problem.empty())
        r.corrupt(ProjectFile::tr("the base animation is invalid: %1").arg(QString::fromStdString(problem)));
    return a;
}

/// Files before format 4 held a vertex sequence as one morph target per file after the first,
/// each with a one-hot weight (memory quadratic in the sequence's length, issue 27). Such an
/// animation becomes vertex frames holding the positions it evaluated to (rest + target, in
/// floats, as BaseAnimation::evaluate() added them); any other animation is returned as it is.
std::shared_ptr<const algo::BaseAnimation> vertexFramesFromOneHotMorphs(
    std::shared_ptr<const algo::BaseAnimation> a, const algo::Positions& rest)
{
    const std::size_t targets = a->morphTargets.size();
    if (targets == 0 || a->skinned() || a->hasVertexFrames())
        return a;
    std::vector<std::int32_t> shows(std::size_t(a->frameCount), 0);
    for (std::size_t s = 0; s < shows.size(); ++s)
        for (std::size_t t = 0; t < targets; ++t) {
            const float w = a->morphWeights[s * targets + t];
            if (w == 0.0f)
                continue;
            if (w != 1.0f || shows[s] != 0)
                return a; // a real blend of targets: kept as morphs
            shows[s] = std::int32_t(t + 1);
        }
    auto out = std::make_shared<algo::BaseAnimation>();
    out->firstFrame = a->firstFrame;
    out->frameCount = a->frameCount;
    const Eigen::Index n = rest.rows();
    out->vertexFrames.resize(Eigen::Index(targets + 1) * n, 3);
    out->vertexFrames.topRows(n) = rest;
    for (std::size_t t = 0; t < targets; ++t) {
        auto frame = out->vertexFrames.middleRows(Eigen::Index(t + 1) * n, n);
        frame = rest;
        frame.noalias() += a->morphTargets[t];
    }
    out->vertexFrameOfSample = std::move(shows);
    return out;
}

ProjectData parseManifest(const Reader& r, const QJsonObject& root, const QString& path, DrawingImages images)
{
    ProjectData data;
    if (root.contains("base_mesh")) {
        const QJsonObject m = r.object(root, "base_mesh");
        auto mesh = std::make_shared<algo::TriMesh>();
        data.baseMeshName = r.string(m, "name");
        r.readMatrix(m, "vertices", r.count(m, "vertex_count"), mesh->vertices);
        r.readMatrix(m, "faces", r.count(m, "face_count"), mesh->faces);
        if (m.contains("uvs")) {
            r.readMatrix(m, "uvs", r.count(m, "uv_count"), mesh->uvs);
            r.readMatrix(m, "uv_faces", mesh->faces.rows(), mesh->uvFaces);
            if (mesh->uvFaces.size() > 0
                && (mesh->uvFaces.minCoeff() < 0 || mesh->uvFaces.maxCoeff() >= mesh->uvs.rows()))
                r.corrupt(ProjectFile::tr("a texture coordinate index is out of range"));
        }
        if (m.contains("face_materials"))
            r.readVector(m, "face_materials", mesh->faces.rows(), mesh->faceMaterials);
        for (const QJsonValue& v : r.array(m, "materials")) {
            const QJsonObject o = v.toObject();
            mesh->materials.push_back({r.string(o, "name").toStdString(), r.vector3(o, "base_color").cast<float>()});
        }
        for (const QJsonValue& v : r.array(m, "face_sets")) {
            const QJsonObject o = v.toObject();
            algo::FaceSet set;
            set.name = r.string(o, "name").toStdString();
            if (set.name.empty() || data.faceSet(QString::fromStdString(set.name)))
                r.corrupt(ProjectFile::tr("a face set name is empty or used twice"));
            // Ascending and without repeats, so never more than the faces (checked before the block).
            const qint64 count = r.count(o, "count");
            if (count > mesh->faces.rows())
                r.corrupt(ProjectFile::tr("face set “%1” has more faces than the model")
                              .arg(QString::fromStdString(set.name)));
            r.readVector(o, "faces", count, set.faces);
            for (std::size_t k = 0; k < set.faces.size(); ++k)
                if (set.faces[k] < 0 || set.faces[k] >= mesh->faces.rows()
                    || (k > 0 && set.faces[k] <= set.faces[k - 1]))
                    r.corrupt(ProjectFile::tr("face set “%1” refers to a face out of range or out of order")
                                  .arg(QString::fromStdString(set.name)));
            data.faceSets.push_back(std::move(set));
        }
        // Optional (format 4): focal points and segment overrides, one value per face.
        if (m.contains("face_importance")) {
            r.readVector(m, "face_importance", mesh->faces.rows(), data.faceImportance);
            if (const QString problem = faceImportanceProblem(data.faceImportance, mesh->faces.rows());
                !problem.isEmpty())
                r.corrupt(problem);
        }
        if (m.contains("segment_overrides")) {
            r.readVector(m, "segment_overrides", mesh->faces.rows(), data.segmentOverrides);
            if (const QString problem = segmentOverridesProblem(data.segmentOverrides, mesh->faces.rows());
                !problem.isEmpty())
                r.corrupt(problem);
        }
        for (auto f : mesh->faceMaterials)
            if (f < 0 || (f > 0 && std::size_t(f) >= mesh->materials.size()))
                r.corrupt(ProjectFile::tr("a face material index is out of range"));
        if (auto defect = algo::findFatalDefect(*mesh))
            r.corrupt(ProjectFile::tr("the base model is invalid (%1)").arg(QString::fromStdString(*defect)));
        data.baseMesh = std::move(mesh);
    }
    const qint64 vertexCount = data.baseMesh ? data.baseMesh->vertexCount() : 0;

    for (const QJsonValue& v : r.array(root, "drawings")) {
        const QJsonObject o = v.toObject();
        Drawing d;
        d.id = r.objectId(o, "id");
        d.name = r.string(o, "name");
        d.imageFormat = r.string(o, "format");
        const auto [p, size] = r.chunk(o, "image", -1);
        d.imageData = QByteArray(p, qsizetype(size));
        d.camera = r.camera(r.object(o, "camera"));
        d.aligned = r.boolean(o, "aligned");
        d.opacity = r.number(o, "opacity");
        if (!(d.opacity >= 0.0 && d.opacity <= 1.0))
            r.corrupt(ProjectFile::tr("drawing “%1” has an opacity outside 0 to 1").arg(d.name));
        d.frame = r.frame(o, "frame");
        // Files written before Fit to Drawing have no outline settings: the defaults.
        if (o.contains(QLatin1String("outline"))) {
            const QJsonObject outline = r.object(o, "outline");
            d.outline.threshold = r.number(outline, "threshold");
            d.outline.closingRadius = r.number(outline, "closing_radius");
            d.outline.innerLines = r.boolean(outline, "inner_lines");
            d.outline.minComponentPixels = int(r.count(outline, "min_component_pixels"));
            if (const QString problem = d.outline.problem(); !problem.isEmpty())
                r.corrupt(ProjectFile::tr("drawing “%1”: %2").arg(d.name, problem));
        }
        data.drawings.push_back(std::move(d));
    }

    for (const QJsonValue& v : r.array(root, "keys")) {
        const QJsonObject o = v.toObject();
        KeyViewpoint k;
        k.id = r.objectId(o, "id");
        k.name = r.string(o, "name");
        k.direction = r.vector3(o, "direction");
        // A key's direction is a unit vector (DESIGN.md, "View direction"): a zero one has none.
        if (!(k.direction.norm() > 1e-9))
            r.corrupt(ProjectFile::tr("key “%1” has a view direction of zero length").arg(k.name));
        k.camera = r.camera(r.object(o, "camera"));
        k.enabled = r.boolean(o, "enabled");
        for (const QJsonValue& id : r.array(o, "drawings"))
            k.drawingIds.push_back(r.objectId(QJsonObject{{"drawings", id}}, "drawings"));
        for (const QJsonValue& fv : r.array(o, "frames")) {
            const QJsonObject f = fv.toObject();
            SparseOffsets offsets;
            // Strictly increasing vertex indices: never more than the vertices.
            const qint64 n = r.count(f, "count");
            if (n > vertexCount)
                r.corrupt(ProjectFile::tr("key “%1” moves more vertices than the model has").arg(k.name));
            r.readVector(f, "indices", n, offsets.indices);
            r.readVector(f, "offsets", n, offsets.deltas);
            for (std::size_t i = 0; i < offsets.indices.size(); ++i) {
                if (offsets.indices[i] >= vertexCount || (i > 0 && offsets.indices[i] <= offsets.indices[i - 1]))
                    r.corrupt(ProjectFile::tr("key “%1” has a vertex index out of range or out of order").arg(k.name));
                if (!offsets.deltas[i].allFinite())
                    r.corrupt(ProjectFile::tr("key “%1” has a non-finite offset").arg(k.name));
            }
            k.offsetsByFrame.emplace(r.frame(f, "frame"), std::move(offsets));
        }
        // Optional (absent in files written before key layers of shading offsets).
        if (o.contains("shading_offsets")) {
            for (const QJsonValue& sv : r.array(o, "shading_offsets")) {
                const QJsonObject f = sv.toObject();
                const qint64 n = r.count(f, "count");
                if (n != vertexCount)
                    r.corrupt(
                        ProjectFile::tr("key “%1” has shading offsets that do not match the vertex count").arg(k.name));
                std::vector<float> values;
                r.readVector(f, "values", n, values);
                for (float value : values)
                    if (!std::isfinite(value))
                        r.corrupt(ProjectFile::tr("key “%1” has a shading offset that is not finite").arg(k.name));
                const int frame = r.frame(f, "frame");
                if (!k.shadingOffsetsByFrame.emplace(frame, std::move(values)).second)
                    r.corrupt(ProjectFile::tr("key “%1” has shading offsets twice at frame %2").arg(k.name).arg(frame));
            }
        }
        data.keys.push_back(std::move(k));
    }

    const QJsonObject blend = r.object(root, "blend");
    data.blend.sharpness = r.number(blend, "sharpness");
    if (!(data.blend.sharpness > 0.0 && data.blend.sharpness <= kMaxSharpness))
        r.corrupt(ProjectFile::tr("the blend sharpness is not between 0 and %1").arg(kMaxSharpness));
    data.blend.unspecified = r.enumValue<UnspecifiedMode>(blend, "unspecified");
    data.blend.time = r.enumValue<TimeInterpolation>(blend, "time");

    data.look = readLook(r, r.object(root, "look"));
    // The brushes' mirror plane; files from before it was saved get the plane detected on the model.
    if (root.contains("mirror_plane")) {
        const std::optional<MirrorPlane> plane = mirrorPlaneFromName(r.string(root, "mirror_plane"));
        if (!plane)
            r.corrupt(ProjectFile::tr("the mirror plane is not off, x, y or z"));
        data.mirrorPlane = *plane;
    } else if (data.baseMesh) {
        data.mirrorPlane = detectMirrorPlane(*data.baseMesh);
    }
    const QString highlightProblem = highlightTracksProblem(data.look.highlights, data.faceSetNames());
    if (!highlightProblem.isEmpty())
        r.corrupt(highlightProblem);
    if (root.contains("shading_offsets")) {
        const QJsonObject o = r.object(root, "shading_offsets");
        const qint64 n = r.count(o, "count");
        if (n != vertexCount)
            r.corrupt(ProjectFile::tr("the shading offsets do not match the vertex count"));
        r.readVector(o, "values", n, data.shadingOffsets);
        for (float v : data.shadingOffsets)
            if (!std::isfinite(v))
                r.corrupt(ProjectFile::tr("a shading offset is not finite"));
    }

    data.nextId = r.objectId(root, "next_id");
    // Drawings and keys draw their ids from one counter: each id names one object.
    std::set<ObjectId> objectIds;
    for (const auto& d : data.drawings) {
        if (d.id >= data.nextId)
            r.corrupt(ProjectFile::tr("an object id is not below next_id"));
        if (!objectIds.insert(d.id).second)
            r.corrupt(ProjectFile::tr("drawing “%1” has the id %2 of another object").arg(d.name).arg(d.id));
    }
    for (const auto& k : data.keys) {
        if (k.id >= data.nextId)
            r.corrupt(ProjectFile::tr("an object id is not below next_id"));
        if (!objectIds.insert(k.id).second)
            r.corrupt(ProjectFile::tr("key “%1” has the id %2 of another object").arg(k.name).arg(k.id));
        for (ObjectId drawing : k.drawingIds)
            if (!data.drawing(drawing))
                r.corrupt(ProjectFile::tr("key “%1” is linked to drawing %2, which the project does not hold")
                              .arg(k.name)
                              .arg(drawing));
    }
    std::set<ObjectId> highlightIds;
    for (const auto& h : data.look.highlights) {
        if (h.id == 0)
            continue; // a file from before highlight ids: the document gives them
        if (h.id >= data.nextId)
            r.corrupt(ProjectFile::tr("an object id is not below next_id"));
        if (!highlightIds.insert(h.id).second)
            r.corrupt(ProjectFile::tr("two highlight layers have the same id"));
    }
    // Optional: files from before the playhead have none.
    if (root.contains(QLatin1String("current_frame"))) {
        const double frame = r.number(root, "current_frame");
        if (frame != std::floor(frame) || std::abs(frame) > double(kMaxFrame))
            r.corrupt(ProjectFile::tr("the current frame is not a frame number"));
        data.currentFrame = int(frame);
    }
    // Format 2: the scene's time and the animated base.
    if (root.contains(QLatin1String("scene"))) {
        const QJsonObject scene = r.object(root, "scene");
        data.time.fps = r.number(scene, "fps");
        data.time.firstFrame = r.frame(scene, "first_frame");
        data.time.lastFrame = r.frame(scene, "last_frame");
        const QString problem = sceneTimeProblem(data.time);
        if (!problem.isEmpty())
            r.corrupt(ProjectFile::tr("the scene time is invalid: %1").arg(problem));
    }
    if (root.contains(QLatin1String("base_animation"))) {
        if (!data.baseMesh)
            r.corrupt(ProjectFile::tr("the base animation has no base model"));
        data.baseAnimation = readBaseAnimation(r, r.object(root, "base_animation"), *data.baseMesh);
        if (root.value(QLatin1String("format_version")).toInt() < 4)
            data.baseAnimation = vertexFramesFromOneHotMorphs(std::move(data.baseAnimation), data.baseMesh->vertices);
    }
    // Last, once the rest is known to be sound, and together: the drawings decoded in a child
    // process (PSD, TIFF, ...) share one, which loads OpenImageIO once.
    if (images == DrawingImages::Decode) {
        std::vector<EncodedImage> encoded;
        for (const Drawing& d : data.drawings)
            encoded.push_back({d.imageData, d.imageFormat, QStringLiteral("%1 (%2)").arg(path, d.name)});
        std::vector<QImage> decoded = decodeImages(encoded);
        for (std::size_t i = 0; i < decoded.size(); ++i)
            data.drawings[i].image = std::move(decoded[i]);
    }
    return data;
}

} // namespace

ProjectData loadProject(const QString& path, DrawingImages images)
{
    const QFileInfo info(path);
    if (!info.exists())
        throw IoError(path, ProjectFile::tr("does not exist"));
    // Before open(): opening a named pipe blocks until something writes to it, for ever.
    if (!info.isFile())
        throw IoError(path, ProjectFile::tr("is not a regular file (a folder, pipe or device)"));
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        throw IoError(path, ProjectFile::tr("could not be opened: %1").arg(file.errorString()));
    const qint64 size = file.size();
    if (size == 0)
        throw IoError(path, ProjectFile::tr("is empty"));
    if (size < 8)
        throw IoError(path, ProjectFile::tr("is not a Celform project"));
    const uchar* mapped = file.map(0, size);
    QByteArray fallback;
    if (!mapped) {
        fallback = file.readAll();
        mapped = reinterpret_cast<const uchar*>(fallback.constData());
    }
    const char* bytes = reinterpret_cast<const char*>(mapped);
    if (std::memcmp(bytes, kMagic, 8) != 0)
        throw IoError(path, ProjectFile::tr("is not a Celform project"));
    if (size < kHeaderSize + kTrailerSize)
        throw IoError(path, ProjectFile::tr("is truncated"));
    const auto version = qFromLittleEndian<quint32>(bytes + 8);
    if (version > quint32(kProjectFormatVersion))
        throw IoError(path,
            ProjectFile::tr("was written by a newer version of Celform (file format %1; this version reads up "
                            "to %2). Please update Celform to open it.")
                .arg(version)
                .arg(kProjectFormatVersion));
    if (version == 0)
        throw IoError(path, ProjectFile::tr("is damaged: the format version is 0"));
    // No version so far sets a flag: a file that does was not written by Celform, or is damaged.
    if (const auto flags = qFromLittleEndian<quint32>(bytes + 12); flags != 0)
        throw IoError(path, ProjectFile::tr("is damaged: its header has unknown flags (%1)").arg(flags));

    const char* trailer = bytes + size - kTrailerSize;
    if (std::memcmp(trailer + 24, kEndMagic, 8) != 0)
        throw IoError(path, ProjectFile::tr("is truncated or damaged: its end marker is missing"));
    const auto manifestOffset = qFromLittleEndian<quint64>(trailer);
    const auto manifestSize = qFromLittleEndian<quint64>(trailer + 8);
    // By subtraction: with an offset near 2^64, offset + size wraps around to a small number and
    // passes an addition's check.
    const auto manifestLimit = quint64(size - kTrailerSize);
    if (manifestOffset < quint64(kHeaderSize) || manifestOffset > manifestLimit
        || manifestSize > manifestLimit - manifestOffset)
        throw IoError(path, ProjectFile::tr("is damaged: its table of contents lies outside the file"));
    const char* manifestBytes = bytes + manifestOffset;
    if (crc32Of(manifestBytes, qint64(manifestSize)) != qFromLittleEndian<quint32>(trailer + 16))
        throw IoError(path, ProjectFile::tr("is damaged: its table of contents fails its checksum"));

    QJsonParseError jsonError;
    const QJsonDocument json
        = QJsonDocument::fromJson(QByteArray::fromRawData(manifestBytes, qsizetype(manifestSize)), &jsonError);
    if (json.isNull() || !json.isObject())
        throw IoError(path, ProjectFile::tr("is damaged: %1").arg(jsonError.errorString()));
    const QJsonObject root = json.object();
    const QJsonValue versionValue = root.value("format_version");
    const double manifestVersion = versionValue.toDouble(-1);
    if (!versionValue.isDouble() || manifestVersion < 1 || manifestVersion != std::floor(manifestVersion))
        throw IoError(path, ProjectFile::tr("is damaged: its format_version is not a version number"));
    if (manifestVersion > kProjectFormatVersion)
        throw IoError(path,
            ProjectFile::tr("was written by a newer version of Celform (file format %1; this version reads up "
                            "to %2). Please update Celform to open it.")
                .arg(manifestVersion)
                .arg(kProjectFormatVersion));
    const Reader reader(path, bytes, qint64(manifestOffset), root.value("chunks").toObject());
    try {
        return parseManifest(reader, root, path, images);
    } catch (const std::bad_alloc&) {
        // Every count is checked against the file before it is allocated, so this is a file too
        // large for the memory left, not a damaged one; either way the message names the file.
        throw IoError(path, ProjectFile::tr("cannot be opened: not enough memory"));
    }
}

} // namespace celform::model
