// glTF 2.0 / GLB as an animated base: the scene's triangles merged into one rest mesh, skins as
// linear blend skinning, morph targets as dense deltas, the first animation sampled at whole
// frames. tinygltf parses (animation_io_gltf_load.cpp); every index and count it hands over is
// checked here before use.
#include "celform/model/io/animation_io_gltf.h"

#include "celform/model/io/mesh_io_common.h"

#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

namespace celform::model::animio {

namespace {

using gltf::Source;

/// Where a joint's matrix comes from at each sample: node's global transform (identity for -1)
/// times inverseBind. Skin joints carry their inverse bind matrix; a mesh node moved by the
/// animation but not skinned is one joint whose inverse bind undoes its rest transform (baked
/// into the rest positions); unmoving meshes in a skinned file share one identity joint.
struct JointSource {
    int node = -1;
    Eigen::Matrix4d inverseBind = Eigen::Matrix4d::Identity();
};

/// One mesh instanced by a scene node, and where its vertices and targets went.
struct Instance {
    int node = -1;
    int mesh = -1;
    int targets = 0;
    int firstTarget = 0;
    std::vector<float> defaultWeights;
    /// Vertices of each triangle primitive: (primitive index, first vertex, count).
    std::vector<std::array<std::int64_t, 3>> ranges;
};

/// Everything merged from the instances, in the order the vertices are appended.
struct Merged {
    std::vector<float> positions;
    std::vector<float> uvs;
    bool anyUvs = false;
    std::vector<std::int32_t> indices;
    std::vector<std::int32_t> faceMaterials;
    std::vector<std::array<std::uint16_t, 4>> joints;
    std::vector<Eigen::Vector4f> weights;
    std::int64_t vertexCount() const { return std::int64_t(positions.size() / 3); }
};

QString primitiveName(int mesh, std::size_t primitive)
{
    return AnimationIo::tr("mesh %1, primitive %2").arg(mesh).arg(primitive);
}

/// The nodes the scene draws, parents before children (the vertex order of the merged mesh).
std::vector<int> sceneOrder(const Source& src, const gltf::Hierarchy& nodes)
{
    const auto& model = src.model;
    std::vector<int> roots;
    if (model.scenes.empty()) {
        for (std::size_t i = 0; i < nodes.parent.size(); ++i)
            if (nodes.parent[i] < 0)
                roots.push_back(int(i));
    } else {
        const int scene
            = model.defaultScene >= 0 && std::size_t(model.defaultScene) < model.scenes.size() ? model.defaultScene : 0;
        roots = model.scenes[std::size_t(scene)].nodes;
    }
    std::vector<int> order;
    std::vector<char> seen(nodes.parent.size(), 0);
    std::vector<int> stack;
    for (int root : roots) {
        if (root < 0 || std::size_t(root) >= nodes.parent.size())
            throw IoError(src.path, AnimationIo::tr("the scene names node %1, which does not exist").arg(root));
        stack.push_back(root);
        while (!stack.empty()) {
            const int node = stack.back();
            stack.pop_back();
            if (seen[std::size_t(node)])
                throw IoError(src.path, AnimationIo::tr("the scene reaches node %1 twice").arg(node));
            seen[std::size_t(node)] = 1;
            order.push_back(node);
            const auto& children = model.nodes[std::size_t(node)].children;
            stack.insert(stack.end(), children.rbegin(), children.rend());
        }
    }
    return order;
}

/// The morph target count of a mesh; all its primitives must have the same.
int morphTargetCount(const Source& src, int mesh)
{
    const tinygltf::Mesh& m = src.model.meshes[std::size_t(mesh)];
    const std::size_t count = m.primitives.empty() ? 0 : m.primitives.front().targets.size();
    for (std::size_t p = 0; p < m.primitives.size(); ++p)
        if (m.primitives[p].targets.size() != count)
            throw IoError(src.path,
                AnimationIo::tr("%1 has %2 morph targets, the mesh's first primitive %3")
                    .arg(primitiveName(mesh, p))
                    .arg(m.primitives[p].targets.size())
                    .arg(count));
    if (count > 65536)
        throw IoError(src.path, AnimationIo::tr("mesh %1 has %2 morph targets").arg(mesh).arg(count));
    return int(count);
}

/// The triangles of a primitive's vertex list (glTF 2.0, section 3.7.2.1 for strips and fans).
void appendTriangles(int mode, const std::vector<std::uint32_t>& list, std::int64_t base, Merged& out)
{
    const std::size_t n = list.size();
    const auto push = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        out.indices.insert(out.indices.end(), {std::int32_t(base + a), std::int32_t(base + b), std::int32_t(base + c)});
    };
    if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        for (std::size_t i = 0; i + 2 < n; ++i) // every other triangle turned to keep the winding
            i % 2 == 0 ? push(list[i], list[i + 1], list[i + 2]) : push(list[i], list[i + 2], list[i + 1]);
    } else if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
        for (std::size_t i = 0; i + 2 < n; ++i)
            push(list[i + 1], list[i + 2], list[0]);
    } else {
        for (std::size_t i = 0; i + 2 < n; i += 3)
            push(list[i], list[i + 1], list[i + 2]);
    }
}

/// Up to eight influences (JOINTS_0/1, WEIGHTS_0/1) reduced to the four heaviest, summing to 1.
void appendSkinWeights(const Source& src, const tinygltf::Primitive& prim, const QString& where,
    std::size_t vertexCount, int jointBase, int skinJoints, Merged& out)
{
    std::vector<std::uint32_t> joints[2];
    std::vector<float> weights[2];
    for (int set = 0; set < 2; ++set) {
        const auto j = prim.attributes.find("JOINTS_" + std::to_string(set));
        const auto w = prim.attributes.find("WEIGHTS_" + std::to_string(set));
        if (j == prim.attributes.end() && w == prim.attributes.end())
            continue;
        if (j == prim.attributes.end() || w == prim.attributes.end())
            throw IoError(src.path, AnimationIo::tr("%1 has only one of JOINTS_%2 and WEIGHTS_%2").arg(where).arg(set));
        joints[set] = gltf::readIntegers(src, j->second, TINYGLTF_TYPE_VEC4, where);
        weights[set] = gltf::readFloats(src, w->second, TINYGLTF_TYPE_VEC4, where);
        if (joints[set].size() != vertexCount * 4 || weights[set].size() != vertexCount * 4)
            throw IoError(src.path,
                AnimationIo::tr("%1: JOINTS_%2 and WEIGHTS_%2 give %3 and %4 vertices, POSITION %5")
                    .arg(where)
                    .arg(set)
                    .arg(joints[set].size() / 4)
                    .arg(weights[set].size() / 4)
                    .arg(vertexCount));
    }
    if (joints[0].empty())
        throw IoError(src.path, AnimationIo::tr("%1 is skinned but has no JOINTS_0 and WEIGHTS_0").arg(where));
    for (std::size_t v = 0; v < vertexCount; ++v) {
        std::array<std::pair<float, std::uint32_t>, 8> influences{};
        int used = 0;
        for (int set = 0; set < 2; ++set) {
            if (joints[set].empty())
                continue;
            for (std::size_t i = 0; i < 4; ++i) {
                const float w = weights[set][4 * v + i];
                const std::uint32_t j = joints[set][4 * v + i];
                if (!std::isfinite(w) || w < 0.0f)
                    throw IoError(src.path,
                        AnimationIo::tr("%1: vertex %2 has a joint weight that is negative or not a number")
                            .arg(where)
                            .arg(v));
                if (w == 0.0f)
                    continue;
                if (j >= std::uint32_t(skinJoints))
                    throw IoError(src.path,
                        AnimationIo::tr("%1: vertex %2 names joint %3, but the skin has %4 joints")
                            .arg(where)
                            .arg(v)
                            .arg(j)
                            .arg(skinJoints));
                const auto same = std::find_if(
                    influences.begin(), influences.begin() + used, [&](const auto& inf) { return inf.second == j; });
                if (same != influences.begin() + used)
                    same->first += w;
                else
                    influences[std::size_t(used++)] = {w, j};
            }
        }
        for (int i = 1; i < used; ++i) // heaviest first (at most eight: insertion)
            for (int k = i; k > 0 && influences[std::size_t(k)].first > influences[std::size_t(k - 1)].first; --k)
                std::swap(influences[std::size_t(k)], influences[std::size_t(k - 1)]);
        std::array<std::uint16_t, 4> ji{};
        Eigen::Vector4f wi = Eigen::Vector4f::Zero();
        float sum = 0.0f;
        for (int i = 0; i < std::min(used, 4); ++i) {
            ji[std::size_t(i)] = std::uint16_t(jointBase + int(influences[std::size_t(i)].second));
            wi[i] = influences[std::size_t(i)].first;
            sum += wi[i];
        }
        if (sum > 0.0f) {
            wi /= sum;
        } else { // no influence at all: held by the skin's first joint, as other importers do
            ji = {std::uint16_t(jointBase), 0, 0, 0};
            wi = Eigen::Vector4f(1, 0, 0, 0);
        }
        out.joints.push_back(ji);
        out.weights.push_back(wi);
    }
}

/// The joints of skin `skin`, added to sources on its first use; returns the first one's index.
int addSkin(const Source& src, int skin, std::vector<int>& skinBase, std::vector<JointSource>& sources)
{
    if (skinBase[std::size_t(skin)] >= 0)
        return skinBase[std::size_t(skin)];
    const tinygltf::Skin& s = src.model.skins[std::size_t(skin)];
    if (s.joints.empty())
        throw IoError(src.path, AnimationIo::tr("skin %1 has no joints").arg(skin));
    std::vector<float> inverseBind;
    if (s.inverseBindMatrices >= 0) {
        inverseBind
            = gltf::readFloats(src, s.inverseBindMatrices, TINYGLTF_TYPE_MAT4, AnimationIo::tr("skin %1").arg(skin));
        if (inverseBind.size() < s.joints.size() * 16)
            throw IoError(src.path,
                AnimationIo::tr("skin %1 has %2 inverse bind matrices for %3 joints")
                    .arg(skin)
                    .arg(inverseBind.size() / 16)
                    .arg(s.joints.size()));
    }
    skinBase[std::size_t(skin)] = int(sources.size());
    for (std::size_t j = 0; j < s.joints.size(); ++j) {
        const int node = s.joints[j];
        if (node < 0 || std::size_t(node) >= src.model.nodes.size())
            throw IoError(src.path, AnimationIo::tr("skin %1 names node %2, which does not exist").arg(skin).arg(node));
        JointSource js;
        js.node = node;
        if (!inverseBind.empty())
            js.inverseBind = Eigen::Map<const Eigen::Matrix4f>(inverseBind.data() + 16 * j).cast<double>();
        if (!js.inverseBind.allFinite())
            throw IoError(
                src.path, AnimationIo::tr("skin %1: joint %2's inverse bind matrix is not finite").arg(skin).arg(j));
        sources.push_back(js);
    }
    return skinBase[std::size_t(skin)];
}

} // namespace

AnimatedImport readGltfAnimation(const QString& path, double fps)
{
    const Source src = gltf::load(path);
    const auto& model = src.model;
    const gltf::Hierarchy nodes = gltf::readHierarchy(src);

    // The instances, in the scene's order; their morph target counts, for the weights channels.
    std::vector<Instance> instances;
    std::vector<int> targetsOfNode(model.nodes.size(), 0);
    std::vector<int> instanceOfNode(model.nodes.size(), -1);
    int targetTotal = 0;
    for (int node : sceneOrder(src, nodes)) {
        const tinygltf::Node& n = model.nodes[std::size_t(node)];
        if (n.mesh < 0)
            continue;
        if (std::size_t(n.mesh) >= model.meshes.size())
            throw IoError(path, AnimationIo::tr("node %1 names mesh %2, which does not exist").arg(node).arg(n.mesh));
        if (n.skin >= 0 && std::size_t(n.skin) >= model.skins.size())
            throw IoError(path, AnimationIo::tr("node %1 names skin %2, which does not exist").arg(node).arg(n.skin));
        Instance inst;
        inst.node = node;
        inst.mesh = n.mesh;
        inst.targets = morphTargetCount(src, n.mesh);
        inst.firstTarget = targetTotal;
        targetTotal += inst.targets;
        // Each target takes at least a float per vertex: far fewer than this fit (and an int holds it).
        if (targetTotal > kMaxAnimationFloats / 3)
            throw IoError(path, AnimationIo::tr("the scene has more morph targets than Celform can hold"));
        // Default weights: the node's, else the mesh's, else zero.
        const tinygltf::Mesh& mesh = model.meshes[std::size_t(n.mesh)];
        const std::vector<double>& given = !n.weights.empty() ? n.weights : mesh.weights;
        if (!given.empty() && given.size() != std::size_t(inst.targets))
            throw IoError(path,
                AnimationIo::tr("node %1 gives %2 morph weights for the %3 morph targets of mesh %4")
                    .arg(node)
                    .arg(given.size())
                    .arg(inst.targets)
                    .arg(n.mesh));
        inst.defaultWeights.assign(std::size_t(inst.targets), 0.0f);
        std::transform(given.begin(), given.end(), inst.defaultWeights.begin(), [](double w) { return float(w); });
        targetsOfNode[std::size_t(node)] = inst.targets;
        instanceOfNode[std::size_t(node)] = int(instances.size());
        instances.push_back(std::move(inst));
    }
    if (instances.empty())
        throw IoError(path, AnimationIo::tr("the scene has no mesh"));

    const std::vector<gltf::Track> tracks = gltf::readFirstAnimation(src, nodes, targetsOfNode);
    // A mesh moves when its node or an ancestor is animated (parents come first in nodes.order).
    std::vector<char> moving(model.nodes.size(), 0);
    for (const gltf::Track& t : tracks)
        if (t.path != gltf::TrackPath::Weights)
            moving[std::size_t(t.node)] = 1;
    for (int i : nodes.order)
        if (nodes.parent[std::size_t(i)] >= 0 && moving[std::size_t(nodes.parent[std::size_t(i)])])
            moving[std::size_t(i)] = 1;
    const bool skinning = std::any_of(instances.begin(), instances.end(), [&](const Instance& inst) {
        return model.nodes[std::size_t(inst.node)].skin >= 0 || moving[std::size_t(inst.node)];
    });

    // Geometry: every triangle primitive of every instance, appended in order.
    Merged merged;
    std::vector<JointSource> sources;
    std::vector<int> skinBase(model.skins.size(), -1);
    int fixedJoint = -1;
    int defaultMaterial = -1;
    std::vector<algo::Material> materials;
    for (const tinygltf::Material& m : model.materials) {
        algo::Material material;
        material.name = m.name;
        const auto& c = m.pbrMetallicRoughness.baseColorFactor;
        if (c.size() >= 3 && std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[2]))
            material.baseColor = Eigen::Vector3d(c[0], c[1], c[2]).cwiseMax(0.0).cwiseMin(1.0).cast<float>();
        materials.push_back(std::move(material));
    }
    for (Instance& inst : instances) {
        const tinygltf::Node& node = model.nodes[std::size_t(inst.node)];
        const tinygltf::Mesh& mesh = model.meshes[std::size_t(inst.mesh)];
        const bool skinned = node.skin >= 0;
        int jointBase = 0;
        int skinJoints = 0;
        if (skinned) {
            jointBase = addSkin(src, node.skin, skinBase, sources);
            skinJoints = int(model.skins[std::size_t(node.skin)].joints.size());
        } else if (moving[std::size_t(inst.node)]) {
            const Eigen::Matrix4d& rest = nodes.restGlobal[std::size_t(inst.node)];
            if (std::abs(rest.topLeftCorner<3, 3>().determinant()) < 1e-12)
                throw IoError(path, AnimationIo::tr("node %1 is animated but has a zero scale at rest").arg(inst.node));
            jointBase = int(sources.size());
            sources.push_back({inst.node, rest.inverse()});
        } else if (skinning) {
            if (fixedJoint < 0) {
                fixedJoint = int(sources.size());
                sources.push_back({});
            }
            jointBase = fixedJoint;
        }
        if (sources.size() > 65535)
            throw IoError(path, AnimationIo::tr("the file has more than 65,535 joints"));
        // Skinned meshes rest in their bind pose (glTF ignores the skinned node's transform);
        // the others have their node's rest transform applied.
        const Eigen::Matrix4d transform
            = skinned ? Eigen::Matrix4d::Identity() : nodes.restGlobal[std::size_t(inst.node)];
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
            const tinygltf::Primitive& prim = mesh.primitives[p];
            const QString where = primitiveName(inst.mesh, p);
            const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
            if (mode >= TINYGLTF_MODE_POINTS && mode <= TINYGLTF_MODE_LINE_STRIP)
                continue; // points and lines have no surface
            if (mode > TINYGLTF_MODE_TRIANGLE_FAN)
                throw IoError(path, AnimationIo::tr("%1 has the unknown mode %2").arg(where).arg(mode));
            const auto position = prim.attributes.find("POSITION");
            if (position == prim.attributes.end())
                throw IoError(path, AnimationIo::tr("%1 has no POSITION").arg(where));
            const std::vector<float> points = gltf::readFloats(src, position->second, TINYGLTF_TYPE_VEC3, where);
            const std::size_t count = points.size() / 3;
            const std::int64_t base = merged.vertexCount();
            if (base + std::int64_t(count) > meshio::kMaxMeshVertices)
                throw IoError(path,
                    AnimationIo::tr("the scene has more than the %1 vertices Celform can load")
                        .arg(meshio::kMaxMeshVertices));
            std::vector<std::uint32_t> list;
            if (prim.indices >= 0) {
                list = gltf::readIntegers(src, prim.indices, TINYGLTF_TYPE_SCALAR, where);
                for (std::size_t i = 0; i < list.size(); ++i)
                    if (list[i] >= count)
                        throw IoError(path,
                            AnimationIo::tr("%1: index %2 is %3, but the primitive has %4 vertices")
                                .arg(where)
                                .arg(i)
                                .arg(list[i])
                                .arg(count));
            } else {
                list.resize(count);
                for (std::size_t i = 0; i < count; ++i)
                    list[i] = std::uint32_t(i);
            }
            for (std::size_t v = 0; v < count; ++v) {
                const Eigen::Vector4d p4(points[3 * v], points[3 * v + 1], points[3 * v + 2], 1.0);
                if (!p4.allFinite())
                    throw IoError(path,
                        AnimationIo::tr("%1: vertex %2 has a coordinate that is not a finite number")
                            .arg(where)
                            .arg(v));
                const Eigen::Vector4d q = transform * p4;
                const Eigen::Vector3f f = q.head<3>().cast<float>();
                if (!f.allFinite()) // a huge scale takes a finite coordinate beyond float's range
                    throw IoError(path,
                        AnimationIo::tr("%1: vertex %2 is beyond the range of a float once its node's transform is "
                                        "applied")
                            .arg(where)
                            .arg(v));
                merged.positions.insert(merged.positions.end(), {f[0], f[1], f[2]});
            }
            // Checked before appending: a list of a billion indices into one vertex is short to store.
            const std::size_t added
                = mode == TINYGLTF_MODE_TRIANGLES ? list.size() / 3 : std::max<std::size_t>(list.size(), 2) - 2;
            if (std::int64_t(merged.indices.size() / 3 + added) > meshio::kMaxMeshTriangles)
                throw IoError(path,
                    AnimationIo::tr("the scene has more than the %1 triangles Celform can load")
                        .arg(meshio::kMaxMeshTriangles));
            appendTriangles(mode, list, base, merged);
            if (!materials.empty()) {
                int material = prim.material;
                if (material >= int(materials.size()))
                    throw IoError(
                        path, AnimationIo::tr("%1 names material %2, which does not exist").arg(where).arg(material));
                if (material < 0) {
                    if (defaultMaterial < 0) {
                        defaultMaterial = int(materials.size());
                        materials.push_back(algo::Material{"default", Eigen::Vector3f(1, 1, 1)});
                    }
                    material = defaultMaterial;
                }
                merged.faceMaterials.resize(merged.indices.size() / 3, material);
            }
            // Texture coordinates: glTF's v runs down the image, OBJ's (and Celform's) up.
            const auto uv = prim.attributes.find("TEXCOORD_0");
            merged.uvs.resize(std::size_t(base) * 2, 0.0f);
            if (uv != prim.attributes.end()) {
                const std::vector<float> coords = gltf::readFloats(src, uv->second, TINYGLTF_TYPE_VEC2, where);
                if (coords.size() != count * 2)
                    throw IoError(path,
                        AnimationIo::tr("%1 has %2 texture coordinates for %3 vertices")
                            .arg(where)
                            .arg(coords.size() / 2)
                            .arg(count));
                for (std::size_t v = 0; v < count; ++v)
                    merged.uvs.insert(merged.uvs.end(), {coords[2 * v], 1.0f - coords[2 * v + 1]});
                merged.anyUvs = true;
            }
            if (skinned)
                appendSkinWeights(src, prim, where, count, jointBase, skinJoints, merged);
            else if (skinning)
                for (std::size_t v = 0; v < count; ++v) {
                    merged.joints.push_back({std::uint16_t(jointBase), 0, 0, 0});
                    merged.weights.push_back(Eigen::Vector4f(1, 0, 0, 0));
                }
            inst.ranges.push_back({std::int64_t(p), base, std::int64_t(count)});
        }
    }
    if (merged.indices.empty())
        throw IoError(path, AnimationIo::tr("the file has no triangle primitive"));

    auto mesh = std::make_shared<algo::TriMesh>();
    const auto vertexCount = static_cast<Eigen::Index>(merged.vertexCount());
    mesh->vertices = Eigen::Map<const algo::Positions>(merged.positions.data(), vertexCount, 3);
    mesh->faces = Eigen::Map<const algo::Faces>(merged.indices.data(), Eigen::Index(merged.indices.size() / 3), 3);
    if (merged.anyUvs) {
        merged.uvs.resize(std::size_t(vertexCount) * 2, 0.0f);
        mesh->uvs = Eigen::Map<const algo::TexCoords>(merged.uvs.data(), vertexCount, 2);
        mesh->uvFaces = mesh->faces;
    }
    if (!materials.empty()) {
        mesh->materials = std::move(materials);
        mesh->faceMaterials = std::move(merged.faceMaterials);
    }

    // Frames: t = F / fps for F = 0 .. ceil(end * fps); a rounding error of the key times (1.0000001
    // seconds at 24 fps) does not add a frame.
    double end = 0.0;
    for (const gltf::Track& t : tracks)
        end = std::max(end, double(t.times.back()));
    if (end * fps > double(kMaxFrames - 1))
        throw IoError(path,
            AnimationIo::tr(
                "the animation lasts %1 seconds, more than the %2 frames Celform can load at %3 frames per second")
                .arg(end)
                .arg(kMaxFrames)
                .arg(fps));
    const int frames = int(std::ceil(end * fps - 1e-4)) + 1;
    const auto jointCount = std::int64_t(skinning ? sources.size() : 0);
    const std::int64_t floats = std::int64_t(targetTotal) * (vertexCount * 3 + frames) + frames * jointCount * 12;
    if (floats > kMaxAnimationFloats)
        throw IoError(path,
            AnimationIo::tr("%1 morph targets and %2 joints over %3 frames are more than Celform can hold")
                .arg(targetTotal)
                .arg(jointCount)
                .arg(frames));

    AnimatedImport out;
    out.fps = fps;
    algo::BaseAnimation& anim = out.animation;
    anim.firstFrame = 0;
    anim.frameCount = frames;

    // Morph targets: dense deltas over the whole merged mesh, zero outside their instance. A
    // target of an unskinned mesh is turned by its node's rest transform, as its positions were.
    anim.morphTargets.assign(std::size_t(targetTotal), algo::Positions::Zero(vertexCount, 3));
    for (const Instance& inst : instances) {
        const bool skinned = model.nodes[std::size_t(inst.node)].skin >= 0;
        const Eigen::Matrix3d linear = skinned
            ? Eigen::Matrix3d::Identity()
            : Eigen::Matrix3d(nodes.restGlobal[std::size_t(inst.node)].topLeftCorner<3, 3>());
        const tinygltf::Mesh& source = model.meshes[std::size_t(inst.mesh)];
        for (const auto& [p, first, count] : inst.ranges) {
            const tinygltf::Primitive& prim = source.primitives[std::size_t(p)];
            for (int k = 0; k < inst.targets; ++k) {
                const auto target = prim.targets[std::size_t(k)].find("POSITION");
                if (target == prim.targets[std::size_t(k)].end())
                    continue;
                const QString where
                    = AnimationIo::tr("morph target %1 of %2").arg(k).arg(primitiveName(inst.mesh, std::size_t(p)));
                const std::vector<float> delta = gltf::readFloats(src, target->second, TINYGLTF_TYPE_VEC3, where);
                if (std::int64_t(delta.size()) != count * 3)
                    throw IoError(path,
                        AnimationIo::tr("%1 has %2 positions, the primitive %3")
                            .arg(where)
                            .arg(delta.size() / 3)
                            .arg(count));
                algo::Positions& dst = anim.morphTargets[std::size_t(inst.firstTarget + k)];
                for (std::int64_t v = 0; v < count; ++v) {
                    const Eigen::Vector3d d(
                        delta[std::size_t(3 * v)], delta[std::size_t(3 * v + 1)], delta[std::size_t(3 * v + 2)]);
                    if (!d.allFinite())
                        throw IoError(path,
                            AnimationIo::tr("%1: vertex %2 has a coordinate that is not a finite number")
                                .arg(where)
                                .arg(v));
                    const Eigen::Vector3f moved = (linear * d).cast<float>();
                    if (!moved.allFinite())
                        throw IoError(path,
                            AnimationIo::tr("%1: vertex %2 is beyond the range of a float once its node's transform is "
                                            "applied")
                                .arg(where)
                                .arg(v));
                    dst.row(Eigen::Index(first + v)) = moved.transpose();
                }
            }
        }
    }

    // Samples: morph weights (defaults, then the weights channels) and skin matrices.
    anim.morphWeights.resize(std::size_t(frames) * std::size_t(targetTotal));
    if (skinning) {
        anim.jointCount = int(jointCount);
        anim.joints = std::move(merged.joints);
        anim.jointWeights = std::move(merged.weights);
        anim.skinMatrices.resize(std::size_t(frames) * std::size_t(jointCount));
    }
    std::vector<Eigen::Matrix4d> globals;
    std::vector<double> values;
    for (int f = 0; f < frames; ++f) {
        const double t = f / fps;
        float* weights = anim.morphWeights.data() + std::size_t(f) * std::size_t(targetTotal);
        for (const Instance& inst : instances)
            std::copy(inst.defaultWeights.begin(), inst.defaultWeights.end(), weights + inst.firstTarget);
        for (const gltf::Track& track : tracks) {
            if (track.path != gltf::TrackPath::Weights || instanceOfNode[std::size_t(track.node)] < 0)
                continue;
            const Instance& inst = instances[std::size_t(instanceOfNode[std::size_t(track.node)])];
            values.resize(std::size_t(track.width));
            gltf::sampleTrack(track, t, values.data());
            std::transform(values.begin(), values.end(), weights + inst.firstTarget, [](double w) { return float(w); });
        }
        if (!skinning)
            continue;
        gltf::globalTransforms(nodes, tracks, t, globals);
        for (std::size_t j = 0; j < sources.size(); ++j) {
            const JointSource& js = sources[j];
            const Eigen::Matrix4d m
                = js.node < 0 ? js.inverseBind : Eigen::Matrix4d(globals[std::size_t(js.node)] * js.inverseBind);
            anim.skinMatrices[std::size_t(f) * sources.size() + j] = m.topRows<3>().cast<float>();
        }
    }
    out.mesh = std::move(mesh);
    return out;
}

} // namespace celform::model::animio
