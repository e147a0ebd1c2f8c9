// Writing .celform files (layout in docs/file-format.md): a header, raw binary chunks straight from
// memory, a JSON manifest describing them, and a trailer that locates the manifest; the previous
// version is kept as .bak. Reading is project_file_read.cpp.
#include "celform/model/io/project_file.h"
#include "celform/model/io/project_file_format.h"

#include "celform/algorithms/mesh_analysis.h"
#include "celform/model/io/image_io.h"
#include "celform/model/io/output_file.h"
#include "celform/model/data/io_error.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtEndian>

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <new>
#include <set>
#include <type_traits>

#include <unistd.h>

namespace celform::model {
namespace {

using namespace project_format;

// --- writing ----------------------------------------------------------------------------------

QJsonArray vec3(const Eigen::Vector3d& v)
{
    return {v.x(), v.y(), v.z()};
}
QJsonArray vec3f(const Eigen::Vector3f& v)
{
    return {double(v.x()), double(v.y()), double(v.z())};
}

/// Collects chunks (pointers into the data, no copies) and their manifest entries.
class ChunkWriter {
public:
    QString add(const QString& name, const void* data, qint64 size)
    {
        m_chunks.push_back({name, static_cast<const char*>(data), size});
        return name;
    }
    template <typename Matrix> QString addMatrix(const QString& name, const Matrix& m)
    {
        noteNonFinite(name, m.data(), std::size_t(m.size()));
        return add(name, m.data(), qint64(m.size()) * qint64(sizeof(typename Matrix::Scalar)));
    }
    template <typename T> QString addVector(const QString& name, const std::vector<T>& v)
    {
        noteNonFinite(name, v.data(), v.size());
        return add(name, v.data(), qint64(v.size() * sizeof(T)));
    }
    /// The first data block holding a value that is not a finite number, empty when none does.
    [[nodiscard]] const QString& nonFiniteChunk() const { return m_nonFinite; }

    void write(OutputFile& file, QJsonObject manifest)
    {
        QByteArray header(kHeaderSize, '\0');
        std::memcpy(header.data(), kMagic, 8);
        qToLittleEndian<quint32>(quint32(kProjectFormatVersion), header.data() + 8);
        put(file, header.constData(), header.size());

        QJsonObject table;
        static const char zeros[8] = {};
        for (const Chunk& c : m_chunks) {
            const qint64 pad = (8 - m_pos % 8) % 8;
            put(file, zeros, pad);
            table.insert(c.name,
                QJsonObject{
                    {"offset", double(m_pos)}, {"size", double(c.size)}, {"crc32", double(crc32Of(c.data, c.size))}});
            put(file, c.data, c.size);
        }
        manifest.insert("chunks", table);
        const QByteArray json = QJsonDocument(manifest).toJson(QJsonDocument::Indented);
        const qint64 manifestOffset = m_pos;
        put(file, json.constData(), json.size());

        char trailer[kTrailerSize] = {};
        qToLittleEndian<quint64>(quint64(manifestOffset), trailer);
        qToLittleEndian<quint64>(quint64(json.size()), trailer + 8);
        qToLittleEndian<quint32>(crc32Of(json.constData(), json.size()), trailer + 16);
        std::memcpy(trailer + 24, kEndMagic, 8);
        put(file, trailer, kTrailerSize);
    }

private:
    template <typename T> void noteNonFinite(const QString& name, const T* data, std::size_t count)
    {
        if constexpr (std::is_floating_point_v<T>) {
            if (m_nonFinite.isEmpty() && !std::all_of(data, data + count, [](T x) { return std::isfinite(x); }))
                m_nonFinite = name;
        }
    }

    void put(OutputFile& file, const char* data, qint64 size)
    {
        file.write(data, size); // throws IoError naming the file and the system's reason
        m_pos += size;
    }

    struct Chunk {
        QString name;
        const char* data;
        qint64 size;
    };
    std::vector<Chunk> m_chunks;
    qint64 m_pos = 0;
    QString m_nonFinite;
};

/// Where in a manifest the first number that is not finite stands ("keys[2].camera.eye[0]"), empty
/// when every number is finite. QJsonDocument would write such a number as null, which the reader
/// refuses: a project holding one must not be saved at all.
QString firstNonFinite(const QJsonValue& value, const QString& where)
{
    if (value.isDouble())
        return std::isfinite(value.toDouble()) ? QString() : where;
    if (value.isArray()) {
        const QJsonArray array = value.toArray();
        for (qsizetype i = 0; i < array.size(); ++i) {
            const QString found = firstNonFinite(array.at(i), QStringLiteral("%1[%2]").arg(where).arg(i));
            if (!found.isEmpty())
                return found;
        }
    } else if (value.isObject()) {
        const QJsonObject object = value.toObject();
        for (auto it = object.begin(); it != object.end(); ++it) {
            const QString found
                = firstNonFinite(it.value(), where.isEmpty() ? it.key() : QStringLiteral("%1.%2").arg(where, it.key()));
            if (!found.isEmpty())
                return found;
        }
    }
    return {};
}

QJsonArray floats(const std::vector<float>& values)
{
    QJsonArray a;
    for (float v : values)
        a.append(double(v));
    return a;
}

QJsonArray matrix3(const Eigen::Matrix3f& m)
{
    QJsonArray rows;
    for (int r = 0; r < 3; ++r)
        rows.append(vec3f(m.row(r).transpose()));
    return rows;
}

QJsonArray highlightsJson(const std::vector<HighlightTrack>& tracks)
{
    QJsonArray out;
    for (const HighlightTrack& t : tracks)
        out.append(highlightTrackJson(t));
    return out;
}

QJsonObject lookJson(const Look& look)
{
    QJsonObject materialStyles;
    for (const auto& [material, style] : look.materialStyles)
        materialStyles.insert(QString::number(material), enumName(style));
    const auto& g = look.gooch;
    const auto& l = look.lineStyle;
    const auto& st = look.stereo;
    QJsonObject out{{"style", enumName(look.style)}, {"material_styles", materialStyles},
        {"light", lightJson(look.light)}, {"background", vec3f(look.backgroundColor)},
        {"toon",
            QJsonObject{{"thresholds", floats(look.toon.thresholds)}, {"intensities", floats(look.toon.intensities)},
                {"evaluation", enumName(look.toonEvaluation)}}},
        {"gooch",
            QJsonObject{{"preset", QString::fromStdString(g.preset)}, {"ka", double(g.ka)}, {"k1", double(g.k1)},
                {"k2", double(g.k2)}, {"k3", double(g.k3)}, {"k4", double(g.k4)}, {"warm", vec3f(g.warm)},
                {"cool", vec3f(g.cool)}}},
        {"hatch",
            QJsonObject{{"spacing", double(look.hatch.spacing)}, {"angle_degrees", double(look.hatch.angleDegrees)},
                {"width", double(look.hatch.width)}}},
        {"lines", look.showLines},
        {"line_kinds",
            QJsonObject{{"silhouettes", look.lines.silhouettes}, {"creases", look.lines.creases},
                {"borders", look.lines.borders}, {"material_boundaries", look.lines.materialBoundaries},
                {"crease_angle_degrees", double(look.lines.creaseAngleDegrees)},
                {"crease_low_angle_degrees", double(look.lines.creaseLowAngleDegrees)}, {"ridges", look.lines.ridges},
                {"ridge_threshold", double(look.lines.ridgeThreshold)}, {"ridge_snakes", look.lines.ridgeSnakes},
                {"ridge_depth_strength", double(look.lines.ridgeDepthStrength)}}},
        {"line_style",
            QJsonObject{{"color", vec3f(l.color)}, {"outline_width", double(l.outlineWidth)},
                {"inner_width", double(l.innerWidth)}, {"jitter", double(l.jitter)},
                {"width_variation", double(l.widthVariation)}, {"overshoot", double(l.overshoot)},
                {"seed", double(l.seed)}, {"join_gap", double(l.joinGap)}, {"smoothing", l.smoothing},
                {"min_length", double(l.minLength)}, {"taper", double(l.taper)}, {"reduction", double(l.reduction)}}},
        {"stereo",
            QJsonObject{{"output", enumName(st.output)}, {"interocular", st.interocular},
                {"convergence", st.convergence}, {"toe_in", st.toeIn}, {"swap_eyes", st.swapEyes},
                {"dubois_left", matrix3(st.dubois.left)}, {"dubois_right", matrix3(st.dubois.right)}}},
        {"subdivision",
            QJsonObject{{"render_level", look.subdivision.level}, {"viewport_level", look.subdivision.viewportLevel}}},
        {"highlights", highlightsJson(look.highlights)}};
    if (look.renderCamera)
        out.insert("render_camera", cameraJson(*look.renderCamera));
    if (!look.cameraPath.empty())
        out.insert("camera_path", cameraPathJson(look.cameraPath));
    if (!look.lightTrack.empty())
        out.insert("light_keys", lightTrackJson(look.lightTrack));
    return out;
}

/// The animated base (algo::BaseAnimation) as manifest entries and data blocks.
QJsonObject baseAnimationJson(const algo::BaseAnimation& a, Eigen::Index vertexCount, ChunkWriter& chunks)
{
    QJsonArray targets;
    for (std::size_t t = 0; t < a.morphTargets.size(); ++t)
        targets.append(chunks.addMatrix(QStringLiteral("animation/morph_targets/%1").arg(t), a.morphTargets[t]));
    QJsonObject out{{"first_frame", a.firstFrame}, {"frame_count", a.frameCount}, {"morph_targets", targets},
        {"morph_weights", chunks.addVector("animation/morph_weights", a.morphWeights)}, {"joint_count", a.jointCount}};
    if (a.hasVertexFrames()) {
        // Format 4: a vertex sequence's frames in one block, and the frame each sample shows.
        out.insert("vertex_frame_count", double(a.storedFrameCount(vertexCount)));
        out.insert("vertex_frames", chunks.addMatrix("animation/vertex_frames", a.vertexFrames));
        out.insert(
            "vertex_frame_of_sample", chunks.addVector("animation/vertex_frame_of_sample", a.vertexFrameOfSample));
    }
    if (a.skinned()) {
        out.insert("joints", chunks.addVector("animation/joints", a.joints));
        out.insert("joint_weights", chunks.addVector("animation/joint_weights", a.jointWeights));
        out.insert("skin_matrices",
            chunks.add("animation/skin_matrices", a.skinMatrices.data(),
                qint64(a.skinMatrices.size() * sizeof(algo::SkinMatrix))));
    }
    return out;
}

QJsonObject buildManifest(const ProjectData& data, ChunkWriter& chunks)
{
    QJsonObject root;
    root.insert("format_version", kProjectFormatVersion);
    root.insert("generator", QStringLiteral("Celform %1").arg(QStringLiteral(CELFORM_VERSION)));

    if (const auto& mesh = data.baseMesh) {
        QJsonObject m{{"name", data.baseMeshName}, {"vertex_count", double(mesh->vertexCount())},
            {"face_count", double(mesh->faceCount())}, {"vertices", chunks.addMatrix("mesh/vertices", mesh->vertices)},
            {"faces", chunks.addMatrix("mesh/faces", mesh->faces)}};
        if (mesh->uvs.rows() > 0) {
            m.insert("uv_count", double(mesh->uvs.rows()));
            m.insert("uvs", chunks.addMatrix("mesh/uvs", mesh->uvs));
            m.insert("uv_faces", chunks.addMatrix("mesh/uv_faces", mesh->uvFaces));
        }
        if (!mesh->faceMaterials.empty())
            m.insert("face_materials", chunks.addVector("mesh/face_materials", mesh->faceMaterials));
        QJsonArray materials;
        for (const auto& mat : mesh->materials)
            materials.append(
                QJsonObject{{"name", QString::fromStdString(mat.name)}, {"base_color", vec3f(mat.baseColor)}});
        m.insert("materials", materials);
        QJsonArray sets;
        for (std::size_t i = 0; i < data.faceSets.size(); ++i) {
            const auto& set = data.faceSets[i];
            sets.append(QJsonObject{{"name", QString::fromStdString(set.name)}, {"count", double(set.faces.size())},
                {"faces", chunks.addVector(QStringLiteral("mesh/face_sets/%1").arg(i), set.faces)}});
        }
        m.insert("face_sets", sets);
        // Format 4, optional: the depth analysis's per-face say (issue 26).
        if (!data.faceImportance.empty())
            m.insert("face_importance", chunks.addVector("mesh/face_importance", data.faceImportance));
        if (!data.segmentOverrides.empty())
            m.insert("segment_overrides", chunks.addVector("mesh/segment_overrides", data.segmentOverrides));
        root.insert("base_mesh", m);
        if (data.animated())
            root.insert("base_animation", baseAnimationJson(*data.baseAnimation, mesh->vertexCount(), chunks));
    }

    QJsonArray drawings;
    for (const auto& d : data.drawings) {
        drawings.append(QJsonObject{{"id", double(d.id)}, {"name", d.name}, {"format", d.imageFormat},
            {"image",
                chunks.add(QStringLiteral("drawings/%1/image").arg(d.id), d.imageData.constData(), d.imageData.size())},
            {"camera", cameraJson(d.camera)}, {"aligned", d.aligned}, {"opacity", d.opacity}, {"frame", d.frame},
            {"outline",
                QJsonObject{{"threshold", d.outline.threshold}, {"closing_radius", d.outline.closingRadius},
                    {"inner_lines", d.outline.innerLines}, {"min_component_pixels", d.outline.minComponentPixels}}}});
    }
    root.insert("drawings", drawings);

    QJsonArray keys;
    for (const auto& k : data.keys) {
        QJsonArray frames;
        for (const auto& [frame, offsets] : k.offsetsByFrame) {
            const QString prefix = QStringLiteral("keys/%1/frames/%2/").arg(k.id).arg(frame);
            frames.append(QJsonObject{{"frame", frame}, {"count", double(offsets.indices.size())},
                {"indices", chunks.addVector(prefix + "indices", offsets.indices)},
                {"offsets",
                    chunks.add(prefix + "offsets", offsets.deltas.data(),
                        qint64(offsets.deltas.size() * sizeof(Eigen::Vector3f)))}});
        }
        QJsonArray linked;
        for (ObjectId id : k.drawingIds)
            linked.append(double(id));
        QJsonObject key{{"id", double(k.id)}, {"name", k.name}, {"direction", vec3(k.direction)},
            {"camera", cameraJson(k.camera)}, {"drawings", linked}, {"enabled", k.enabled}, {"frames", frames}};
        // The key's layer of shading offsets (paper 3, eq. 4.3), dense per vertex per keyed frame.
        if (!k.shadingOffsetsByFrame.empty()) {
            QJsonArray shading;
            for (const auto& [frame, values] : k.shadingOffsetsByFrame)
                shading.append(QJsonObject{{"frame", frame}, {"count", double(values.size())},
                    {"values",
                        chunks.addVector(QStringLiteral("keys/%1/shading_offsets/%2").arg(k.id).arg(frame), values)}});
            key.insert("shading_offsets", shading);
        }
        keys.append(key);
    }
    root.insert("keys", keys);

    root.insert("blend",
        QJsonObject{{"sharpness", data.blend.sharpness}, {"unspecified", enumName(data.blend.unspecified)},
            {"time", enumName(data.blend.time)}});
    root.insert("look", lookJson(data.look));
    root.insert("mirror_plane", mirrorPlaneName(data.mirrorPlane));
    if (!data.shadingOffsets.empty()) {
        root.insert("shading_offsets",
            QJsonObject{{"count", double(data.shadingOffsets.size())},
                {"values", chunks.addVector("mesh/shading_offsets", data.shadingOffsets)}});
    }
    root.insert("next_id", double(data.nextId));
    root.insert("current_frame", data.currentFrame);
    root.insert("scene",
        QJsonObject{
            {"fps", data.time.fps}, {"first_frame", data.time.firstFrame}, {"last_frame", data.time.lastFrame}});
    return root;
}

/// Makes PATH.bak the current PATH, before the new version replaces it. The new backup is made
/// beside the old one and renamed over it, so a kill at any instant leaves a whole backup (the old
/// one or the new); removing the old .bak first left none for a moment (15 of 60 aimed kills).
void keepPreviousVersion(const QString& path)
{
    // path is the file itself (saveProject resolves links): link(2) does not follow a symbolic
    // link, so a backup of the link would be a second name of the link, showing the new version.
    const QByteArray current = QFile::encodeName(path);
    const QByteArray backup = current + ".bak";
    const QByteArray staged = current + ".bak.new";
    ::unlink(staged.constData()); // left by an interrupted save; .bak is still whole
    // A hard link keeps the previous version at no cost; fall back to a copy.
    if (::link(current.constData(), staged.constData()) != 0 && !QFile::copy(path, QFile::decodeName(staged)))
        return; // no backup can be made here (as before): the save itself goes on
    // rename(2) replaces .bak atomically. When both already name the same file (a save killed
    // after this step and before its commit) it does nothing, so the staged name is removed after.
    ::rename(staged.constData(), backup.constData());
    ::unlink(staged.constData());
}

} // namespace

QJsonArray vec3Json(const Eigen::Vector3d& v)
{
    return vec3(v);
}

QJsonObject cameraJson(const Camera& c)
{
    return {{"eye", vec3(c.eye)}, {"target", vec3(c.target)}, {"up", vec3(c.up)},
        {"projection", enumName(c.projection)}, {"fov_y_degrees", c.fovYDegrees}, {"ortho_height", c.orthoHeight}};
}

QJsonArray cameraPathJson(const CameraPath& path)
{
    QJsonArray keys;
    for (const CameraKey& k : path.keys)
        keys.append(QJsonObject{{"frame", k.frame}, {"camera", cameraJson(k.camera)}});
    return keys;
}

QJsonObject lightJson(const Light& light)
{
    return {{"type", enumName(light.type)}, {"vector", vec3(light.vector)}};
}

QJsonArray lightTrackJson(const LightTrack& track)
{
    QJsonArray keys;
    for (const LightKey& k : track.keys)
        keys.append(QJsonObject{{"frame", k.frame}, {"light", lightJson(k.light)}});
    return keys;
}

QJsonObject highlightTrackJson(const HighlightTrack& t)
{
    QJsonArray combine;
    for (const auto& [mode, other] : t.combineWith)
        combine.append(
            QJsonObject{{"mode", mode == algo::HighlightBoolean::Union ? "union" : "subtract"}, {"layer", other}});
    QJsonArray keys;
    for (const algo::HighlightKey& k : t.keys) {
        QJsonArray operations;
        for (const algo::HighlightOperation& op : k.layer.shape.operations) {
            QJsonArray values{double(op.a)};
            if (highlightOperationArity(op.type) == 2)
                values.append(double(op.b));
            operations.append(QJsonObject{{"type", highlightOperationName(op.type)}, {"values", values}});
        }
        keys.append(
            QJsonObject{{"frame", k.frame}, {"color", vec3f(k.layer.color)}, {"epsilon", double(k.layer.shape.epsilon)},
                {"off_specular_cut", double(k.layer.offSpecularCut)}, {"operations", operations}});
    }
    return {{"id", double(t.id)}, {"name", t.name}, {"patch", t.patch}, {"guide", vec3f(t.guide)},
        {"visible", t.visible}, {"normal_smoothing", t.smoothing}, {"combine", combine}, {"keys", keys}};
}

void saveProject(const ProjectData& data, const QString& given, bool keepBackup)
{
    // Through a symbolic link, the file it names is saved and backed up (FILE.bak beside the
    // target), as Blender and Krita do; the link stays a link. A dangling link saves to its target.
    const QFileInfo info(given);
    const QString path = !info.isSymLink() ? given : info.exists() ? info.canonicalFilePath() : info.symLinkTarget();
    ChunkWriter chunks;
    const QJsonObject manifest = buildManifest(data, chunks);
    // Nothing the reader would refuse is written: the file on disk stays as it was.
    QString bad = firstNonFinite(manifest, {});
    if (bad.isEmpty())
        bad = chunks.nonFiniteChunk();
    if (!bad.isEmpty())
        throw IoError(given, ProjectFile::tr("was not saved: %1 holds a value that is not a finite number").arg(bad));
    // Every write, the sync and the rename are checked: on a full disk the save fails naming the
    // file and the reason, and the previous version stays as it was (issue 27).
    OutputFile file(path);
    chunks.write(file, manifest);

    if (keepBackup && QFileInfo(path).isFile())
        keepPreviousVersion(path);
    file.commit();
}

} // namespace celform::model
