// glTF 2.0 export (export.h, docs/export.md): the base model as one mesh whose morph targets are
// the enabled keys' offsets at the playhead (and an animated base's own morph targets), its
// weights animated frame by frame with the shares the blend gives through the shot's camera, and
// that camera on a node whose translation and rotation follow the camera path. Built as a
// tinygltf model and written by tinygltf, in text (buffer embedded) or binary form.
#include "celform/model/export/export.h"

#include "celform/model/data/io_error.h"

#include <tiny_gltf.h>

#include <QCoreApplication>
#include <QFileInfo>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <sstream>
#include <unordered_map>

namespace celform::model::exporting {

namespace {

QString text(const char* s)
{
    return QCoreApplication::translate("celform::model::Export", s);
}

/// The model under construction with one buffer, and helpers adding accessors to it.
class GltfBuilder {
public:
    GltfBuilder() { m_model.buffers.emplace_back(); }

    /// Appends count elements of floats (components per element by type) as a new buffer view and
    /// accessor; with bounds, the accessor's min and max (POSITION and animation inputs need them).
    int addFloats(const float* values, std::size_t count, int type, int components, int target, bool bounds)
    {
        std::vector<double> lo(std::size_t(components), std::numeric_limits<double>::infinity());
        std::vector<double> hi(std::size_t(components), -std::numeric_limits<double>::infinity());
        if (bounds)
            for (std::size_t i = 0; i < count; ++i)
                for (int c = 0; c < components; ++c) {
                    const double v = values[i * std::size_t(components) + std::size_t(c)];
                    lo[std::size_t(c)] = std::min(lo[std::size_t(c)], v);
                    hi[std::size_t(c)] = std::max(hi[std::size_t(c)], v);
                }
        const int view = addView(values, count * std::size_t(components) * sizeof(float), target);
        tinygltf::Accessor a;
        a.bufferView = view;
        a.byteOffset = 0;
        a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
        a.count = count;
        a.type = type;
        if (bounds && count > 0) {
            a.minValues = lo;
            a.maxValues = hi;
        }
        m_model.accessors.push_back(std::move(a));
        return int(m_model.accessors.size()) - 1;
    }

    int addIndices(const std::vector<std::uint32_t>& indices)
    {
        const int view
            = addView(indices.data(), indices.size() * sizeof(std::uint32_t), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
        tinygltf::Accessor a;
        a.bufferView = view;
        a.byteOffset = 0;
        a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
        a.count = indices.size();
        a.type = TINYGLTF_TYPE_SCALAR;
        m_model.accessors.push_back(std::move(a));
        return int(m_model.accessors.size()) - 1;
    }

    tinygltf::Model& model() { return m_model; }

private:
    int addView(const void* bytes, std::size_t size, int target)
    {
        std::vector<unsigned char>& data = m_model.buffers[0].data;
        data.resize((data.size() + 3) / 4 * 4, 0); // every view starts 4-byte aligned
        tinygltf::BufferView v;
        v.buffer = 0;
        v.byteOffset = data.size();
        v.byteLength = size;
        v.target = target;
        const std::size_t at = data.size();
        data.resize(at + size);
        if (size > 0)
            std::memcpy(data.data() + at, bytes, size);
        m_model.bufferViews.push_back(std::move(v));
        return int(m_model.bufferViews.size()) - 1;
    }

    tinygltf::Model m_model;
};

/// glTF vertices: one per distinct (position, texture coordinate) corner, as glTF has a single
/// index per corner; origin[i] is glTF vertex i's base model vertex.
struct VertexSplit {
    std::vector<std::uint32_t> origin;
    std::vector<std::uint32_t> uvOf; ///< the texture coordinate of each glTF vertex (with UVs)
    std::vector<std::uint32_t> corners; ///< per face corner, the glTF vertex (#F * 3)
};

VertexSplit splitVertices(const algo::TriMesh& mesh)
{
    VertexSplit split;
    const auto faces = std::size_t(mesh.faceCount());
    split.corners.resize(faces * 3);
    if (!mesh.hasUvs()) {
        split.origin.resize(std::size_t(mesh.vertexCount()));
        for (std::size_t v = 0; v < split.origin.size(); ++v)
            split.origin[v] = std::uint32_t(v);
        std::memcpy(split.corners.data(), mesh.faces.data(), faces * 3 * sizeof(std::uint32_t));
        return split;
    }
    std::unordered_map<std::uint64_t, std::uint32_t> seen;
    seen.reserve(std::size_t(mesh.vertexCount()) * 2);
    for (std::size_t f = 0; f < faces; ++f)
        for (int k = 0; k < 3; ++k) {
            const auto v = std::uint32_t(mesh.faces(Eigen::Index(f), k));
            const auto t = std::uint32_t(mesh.uvFaces(Eigen::Index(f), k));
            const auto [it, added] = seen.emplace((std::uint64_t(v) << 32) | t, std::uint32_t(split.origin.size()));
            if (added) {
                split.origin.push_back(v);
                split.uvOf.push_back(t);
            }
            split.corners[f * 3 + std::size_t(k)] = it->second;
        }
    return split;
}

/// Rows of a #V by 3 float array gathered into glTF vertex order.
std::vector<float> gather(const algo::Positions& rows, const VertexSplit& split)
{
    std::vector<float> out(split.origin.size() * 3);
    for (std::size_t i = 0; i < split.origin.size(); ++i)
        for (int c = 0; c < 3; ++c)
            out[i * 3 + std::size_t(c)] = rows(Eigen::Index(split.origin[i]), c);
    return out;
}

/// A camera's orientation as glTF wants it: the camera looks down its -Z with +Y up.
Eigen::Quaternionf cameraRotation(const Camera& camera)
{
    Eigen::Matrix3d axes;
    axes.col(0) = camera.right();
    axes.col(1) = camera.trueUp();
    axes.col(2) = -camera.forward();
    Eigen::Quaternionf q(Eigen::Quaterniond(axes).cast<float>());
    q.normalize();
    return q;
}

} // namespace

void writeGltf(const ProjectData& data, const QString& source, const ExportJob& job, algo::Progress* progress,
    ExportResult& result)
{
    const algo::TriMesh& mesh = *data.baseMesh;
    const bool animated = data.animated();
    if (animated && data.baseAnimation->skinned())
        result.warnings << text("the base model is skinned: glTF export carries none of its skinning (use a PC2 "
                                "point cache or an OBJ sequence for the animated shape)");

    GltfBuilder builder;
    tinygltf::Model& model = builder.model();
    model.asset.version = "2.0";
    model.asset.generator = "Celform";

    // --- the base mesh ---
    const VertexSplit split = splitVertices(mesh);
    const std::size_t vertexCount = split.origin.size();
    tinygltf::Primitive shared;
    shared.mode = TINYGLTF_MODE_TRIANGLES;
    {
        const std::vector<float> positions = gather(mesh.vertices, split);
        shared.attributes["POSITION"] = builder.addFloats(
            positions.data(), vertexCount, TINYGLTF_TYPE_VEC3, 3, TINYGLTF_TARGET_ARRAY_BUFFER, true);
        std::vector<float> normals = gather(mesh.normals(), split);
        for (std::size_t i = 0; i < vertexCount; ++i) {
            Eigen::Map<Eigen::Vector3f> n(normals.data() + i * 3);
            n = n.norm() > 1e-12f ? Eigen::Vector3f(n.normalized()) : Eigen::Vector3f::UnitZ();
        }
        shared.attributes["NORMAL"] = builder.addFloats(
            normals.data(), vertexCount, TINYGLTF_TYPE_VEC3, 3, TINYGLTF_TARGET_ARRAY_BUFFER, false);
        if (mesh.hasUvs()) {
            // glTF's texture origin is the image's top left, OBJ's its bottom left.
            std::vector<float> uvs(vertexCount * 2);
            for (std::size_t i = 0; i < vertexCount; ++i) {
                uvs[i * 2] = mesh.uvs(Eigen::Index(split.uvOf[i]), 0);
                uvs[i * 2 + 1] = 1.0f - mesh.uvs(Eigen::Index(split.uvOf[i]), 1);
            }
            shared.attributes["TEXCOORD_0"] = builder.addFloats(
                uvs.data(), vertexCount, TINYGLTF_TYPE_VEC2, 2, TINYGLTF_TARGET_ARRAY_BUFFER, false);
        }
    }

    // --- morph targets: the enabled keys at the playhead, then the animated base's own ---
    std::vector<std::string> targetNames;
    std::map<ObjectId, std::size_t> targetOfKey;
    {
        algo::Positions dense(mesh.vertexCount(), 3);
        for (const KeyViewpoint& key : data.keys) {
            if (!key.enabled)
                continue;
            dense.setZero();
            const ProjectData::FrameOffsets offsets = ProjectData::offsetsAt(key, data.currentFrame, data.blend.time);
            const SparseOffsets& sparse = *offsets.get();
            for (std::size_t i = 0; i < sparse.indices.size(); ++i)
                dense.row(Eigen::Index(sparse.indices[i])) = sparse.deltas[i].transpose();
            const std::vector<float> deltas = gather(dense, split);
            targetOfKey[key.id] = targetNames.size();
            targetNames.push_back(key.name.toStdString());
            shared.targets.push_back({{"POSITION",
                builder.addFloats(
                    deltas.data(), vertexCount, TINYGLTF_TYPE_VEC3, 3, TINYGLTF_TARGET_ARRAY_BUFFER, true)}});
        }
        if (animated)
            for (std::size_t t = 0; t < data.baseAnimation->morphTargets.size(); ++t) {
                const std::vector<float> deltas = gather(data.baseAnimation->morphTargets[t], split);
                targetNames.push_back("base:" + std::to_string(t));
                shared.targets.push_back({{"POSITION",
                    builder.addFloats(
                        deltas.data(), vertexCount, TINYGLTF_TYPE_VEC3, 3, TINYGLTF_TARGET_ARRAY_BUFFER, true)}});
            }
        // A vertex sequence's stored frames: glTF has no vertex caches, so each is a morph target
        // (its displacement from the rest positions) weighted 1 at the samples that show it.
        if (animated && data.baseAnimation->hasVertexFrames()) {
            const algo::BaseAnimation& anim = *data.baseAnimation;
            const Eigen::Index n = mesh.vertexCount();
            for (Eigen::Index k = 0; k < anim.storedFrameCount(n); ++k) {
                dense = anim.vertexFrames.middleRows(k * n, n) - mesh.vertices;
                const std::vector<float> deltas = gather(dense, split);
                targetNames.push_back("base:frame:" + std::to_string(k));
                shared.targets.push_back({{"POSITION",
                    builder.addFloats(
                        deltas.data(), vertexCount, TINYGLTF_TYPE_VEC3, 3, TINYGLTF_TARGET_ARRAY_BUFFER, true)}});
            }
        }
    }
    const std::size_t keyTargets = targetOfKey.size();
    const std::size_t targetCount = targetNames.size();

    // One primitive per material used, sharing the vertex attributes and targets.
    const int materialCount = std::max<int>(1, int(mesh.materials.size()));
    auto indicesOf = std::vector<std::vector<std::uint32_t>>(std::size_t(materialCount));
    for (Eigen::Index f = 0; f < mesh.faceCount(); ++f) {
        int m = mesh.faceMaterials.empty() ? 0 : mesh.faceMaterials[std::size_t(f)];
        m = std::clamp(m, 0, materialCount - 1);
        for (int k = 0; k < 3; ++k)
            indicesOf[std::size_t(m)].push_back(split.corners[std::size_t(f) * 3 + std::size_t(k)]);
    }
    const std::string meshName
        = data.baseMeshName.isEmpty() ? "base" : QFileInfo(data.baseMeshName).completeBaseName().toStdString();
    tinygltf::Mesh gltfMesh;
    gltfMesh.name = meshName;
    for (int m = 0; m < materialCount; ++m) {
        if (indicesOf[std::size_t(m)].empty())
            continue;
        tinygltf::Material material;
        const algo::Material given = mesh.materials.empty() ? algo::Material{} : mesh.materials[std::size_t(m)];
        material.name = given.name.empty() ? "material" + std::to_string(m) : given.name;
        material.pbrMetallicRoughness.baseColorFactor
            = {given.baseColor.x(), given.baseColor.y(), given.baseColor.z(), 1.0};
        material.pbrMetallicRoughness.metallicFactor = 0.0;
        material.pbrMetallicRoughness.roughnessFactor = 1.0;
        model.materials.push_back(std::move(material));
        tinygltf::Primitive primitive = shared;
        primitive.indices = builder.addIndices(indicesOf[std::size_t(m)]);
        primitive.material = int(model.materials.size()) - 1;
        gltfMesh.primitives.push_back(std::move(primitive));
    }
    if (targetCount > 0) {
        tinygltf::Value::Array names;
        for (const std::string& n : targetNames)
            names.emplace_back(n);
        tinygltf::Value::Object extras;
        extras["targetNames"] = tinygltf::Value(std::move(names));
        gltfMesh.extras = tinygltf::Value(std::move(extras));
    }

    // --- every frame: the camera and the weights ---
    const auto frames = std::size_t(job.frameCount());
    std::vector<float> times, translations, rotations, weights;
    times.reserve(frames);
    translations.reserve(frames * 3);
    rotations.reserve(frames * 4);
    weights.reserve(frames * targetCount);
    Camera firstCamera;
    double farthest = 0.0;
    Eigen::Quaternionf previous = Eigen::Quaternionf::Identity();
    FrameWalk walk(data, source, job, progress);
    while (walk.next()) {
        const Camera& camera = walk.camera();
        if (walk.done() == 1)
            firstCamera = camera;
        times.push_back(float(double(walk.frame() - job.firstFrame) / data.time.fps));
        for (int c = 0; c < 3; ++c)
            translations.push_back(float(camera.eye[c]));
        // Successive frames on the same side of the quaternion sphere, so LINEAR (slerp) takes
        // the short way.
        Eigen::Quaternionf q = cameraRotation(camera);
        if (walk.done() > 1 && q.dot(previous) < 0.0f)
            q.coeffs() = -q.coeffs();
        previous = q;
        for (float c : {q.x(), q.y(), q.z(), q.w()})
            rotations.push_back(c);
        farthest = std::max(farthest, (camera.eye - camera.target).norm());
        const std::size_t row = weights.size();
        weights.resize(row + targetCount, 0.0f);
        for (const KeyShare& share : walk.evaluator().blend().shares)
            if (const auto it = targetOfKey.find(share.key); it != targetOfKey.end())
                weights[row + it->second] = float(share.weight);
        if (animated) {
            const algo::BaseAnimation& anim = *data.baseAnimation;
            const std::size_t morphs = anim.morphTargets.size();
            const std::size_t sample = std::size_t(anim.sampleOf(walk.frame()));
            for (std::size_t t = 0; t < morphs; ++t)
                weights[row + keyTargets + t] = anim.morphWeights[sample * morphs + t];
            if (anim.hasVertexFrames())
                weights[row + keyTargets + morphs + std::size_t(anim.vertexFrameOfSample[sample])] = 1.0f;
        }
        ++result.frames;
    }
    if (walk.cancelled()) {
        result.cancelled = true;
        return;
    }
    if (targetCount > 0)
        gltfMesh.weights.assign(weights.begin(), weights.begin() + std::ptrdiff_t(targetCount));
    model.meshes.push_back(std::move(gltfMesh));

    // The camera: its lens from the first frame (glTF cannot animate a lens without extensions).
    const double size = algo::boundingBox(mesh.vertices).diagonal().norm();
    tinygltf::Camera lens;
    lens.name = "camera";
    const double zfar = std::max(1e-3, (farthest + size) * 10.0);
    if (firstCamera.projection == Projection::Perspective) {
        lens.type = "perspective";
        lens.perspective.yfov = firstCamera.fovYDegrees * M_PI / 180.0;
        lens.perspective.aspectRatio = job.aspect;
        lens.perspective.znear = std::max(1e-6, zfar * 1e-5);
        lens.perspective.zfar = zfar;
    } else {
        lens.type = "orthographic";
        lens.orthographic.ymag = firstCamera.orthoHeight / 2.0;
        lens.orthographic.xmag = lens.orthographic.ymag * job.aspect;
        lens.orthographic.znear = 0.0;
        lens.orthographic.zfar = zfar;
    }
    model.cameras.push_back(std::move(lens));

    tinygltf::Node meshNode;
    meshNode.name = meshName;
    meshNode.mesh = 0;
    tinygltf::Node cameraNode;
    cameraNode.name = "camera";
    cameraNode.camera = 0;
    cameraNode.translation = {translations[0], translations[1], translations[2]};
    cameraNode.rotation = {rotations[0], rotations[1], rotations[2], rotations[3]};
    model.nodes = {meshNode, cameraNode};
    tinygltf::Scene scene;
    scene.name = "celform";
    scene.nodes = {0, 1};
    model.scenes.push_back(std::move(scene));
    model.defaultScene = 0;

    // --- the animation: camera path and weights, one key per frame ---
    const bool cameraMoves = !data.look.cameraPath.empty() && frames > 1;
    if (cameraMoves || (targetCount > 0 && frames > 1)) {
        tinygltf::Animation animation;
        animation.name = "celform";
        const int input = builder.addFloats(times.data(), frames, TINYGLTF_TYPE_SCALAR, 1, 0, true);
        auto channel = [&](int output, int node, const char* path) {
            tinygltf::AnimationSampler sampler;
            sampler.input = input;
            sampler.output = output;
            sampler.interpolation = "LINEAR";
            animation.samplers.push_back(std::move(sampler));
            tinygltf::AnimationChannel c;
            c.sampler = int(animation.samplers.size()) - 1;
            c.target_node = node;
            c.target_path = path;
            animation.channels.push_back(std::move(c));
        };
        if (cameraMoves) {
            channel(builder.addFloats(translations.data(), frames, TINYGLTF_TYPE_VEC3, 3, 0, false), 1, "translation");
            channel(builder.addFloats(rotations.data(), frames, TINYGLTF_TYPE_VEC4, 4, 0, false), 1, "rotation");
        }
        if (targetCount > 0)
            channel(builder.addFloats(weights.data(), frames * targetCount, TINYGLTF_TYPE_SCALAR, 1, 0, false), 0,
                "weights");
        model.animations.push_back(std::move(animation));
    }
    model.buffers[0].data.resize((model.buffers[0].data.size() + 3) / 4 * 4, 0);

    // --- write ---
    const bool binary = job.format == ExportFormat::Glb;
    std::ostringstream stream(std::ios::binary);
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&model, stream, !binary, binary))
        throw IoError(job.output, text("the glTF writer failed"));
    const std::string bytes = stream.str();
    OutputFile file(job.output); // whole or not at all; every write checked (issue 27)
    file.write(bytes.data(), qint64(bytes.size()));
    finishFile(file, algo::cancelRequested(progress), result);
}

} // namespace celform::model::exporting
