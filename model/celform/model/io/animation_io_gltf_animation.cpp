// The moving half of a glTF file: the node tree, the first animation's channels, and their
// interpolation (glTF 2.0, section 3.11 "Animations" and appendix C "Interpolation").
#include "celform/model/io/animation_io_gltf.h"

#include <algorithm>
#include <cmath>

namespace celform::model::animio::gltf {

namespace {

Eigen::Matrix4d composeTrs(const Eigen::Vector3d& t, const Eigen::Quaterniond& r, const Eigen::Vector3d& s)
{
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m.topLeftCorner<3, 3>() = r.toRotationMatrix() * s.asDiagonal();
    m.topRightCorner<3, 1>() = t;
    return m;
}

bool allFinite(const std::vector<double>& values)
{
    return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

/// glTF quaternions are stored x, y, z, w.
Eigen::Quaterniond quaternion(const double* xyzw)
{
    return Eigen::Quaterniond(xyzw[3], xyzw[0], xyzw[1], xyzw[2]);
}

/// A key's quaternion, unit length (a zero one, which has no direction, is taken as no rotation).
Eigen::Quaterniond keyQuaternion(const float* xyzw)
{
    Eigen::Quaterniond q(xyzw[3], xyzw[0], xyzw[1], xyzw[2]);
    const double norm = q.norm();
    return norm > 1e-12 ? Eigen::Quaterniond(q.coeffs() / norm) : Eigen::Quaterniond::Identity();
}

/// A sampled x, y, z, w to unit length; a zero one (a spline may pass through it) is no rotation.
void normaliseQuaternion(double* xyzw)
{
    Eigen::Map<Eigen::Vector4d> q(xyzw);
    if (q.norm() > 1e-12)
        q.normalize();
    else
        q << 0, 0, 0, 1;
}

} // namespace

Hierarchy readHierarchy(const Source& src)
{
    const auto& nodes = src.model.nodes;
    const std::size_t n = nodes.size();
    Hierarchy h;
    h.parent.assign(n, -1);
    for (std::size_t i = 0; i < n; ++i)
        for (int c : nodes[i].children) {
            if (c < 0 || std::size_t(c) >= n)
                throw IoError(src.path, AnimationIo::tr("node %1 has child %2, which does not exist").arg(i).arg(c));
            if (h.parent[std::size_t(c)] != -1 || std::size_t(c) == i)
                throw IoError(src.path, AnimationIo::tr("node %1 has more than one parent").arg(c));
            h.parent[std::size_t(c)] = int(i);
        }
    // Parents before children, without recursion: a chain of 30,000 nodes must not take the stack.
    h.order.reserve(n);
    std::vector<int> stack;
    for (std::size_t i = 0; i < n; ++i) {
        if (h.parent[i] != -1)
            continue;
        stack.push_back(int(i));
        while (!stack.empty()) {
            const int node = stack.back();
            stack.pop_back();
            h.order.push_back(node);
            const auto& children = nodes[std::size_t(node)].children;
            stack.insert(stack.end(), children.rbegin(), children.rend());
        }
    }
    if (h.order.size() != n)
        throw IoError(src.path, AnimationIo::tr("the node hierarchy has a cycle"));

    h.translation.assign(n, Eigen::Vector3d::Zero());
    h.rotation.assign(n, Eigen::Quaterniond::Identity());
    h.scale.assign(n, Eigen::Vector3d::Ones());
    h.matrix.assign(n, Eigen::Matrix4d::Identity());
    h.hasMatrix.assign(n, 0);
    h.restGlobal.assign(n, Eigen::Matrix4d::Identity());
    for (std::size_t i = 0; i < n; ++i) {
        const tinygltf::Node& node = nodes[i];
        const bool sizes = (node.translation.empty() || node.translation.size() == 3)
            && (node.rotation.empty() || node.rotation.size() == 4) && (node.scale.empty() || node.scale.size() == 3)
            && (node.matrix.empty() || node.matrix.size() == 16);
        if (!sizes || !allFinite(node.translation) || !allFinite(node.rotation) || !allFinite(node.scale)
            || !allFinite(node.matrix))
            throw IoError(src.path, AnimationIo::tr("node %1 has a malformed transform").arg(i));
        if (!node.matrix.empty()) {
            h.matrix[i] = Eigen::Map<const Eigen::Matrix4d>(node.matrix.data()); // column-major, as Eigen's
            h.hasMatrix[i] = 1;
        }
        if (!node.translation.empty())
            h.translation[i] = Eigen::Vector3d(node.translation[0], node.translation[1], node.translation[2]);
        if (!node.rotation.empty()) {
            h.rotation[i] = quaternion(node.rotation.data());
            if (h.rotation[i].norm() < 1e-12)
                throw IoError(src.path, AnimationIo::tr("node %1 has a zero rotation quaternion").arg(i));
            h.rotation[i].normalize();
        }
        if (!node.scale.empty())
            h.scale[i] = Eigen::Vector3d(node.scale[0], node.scale[1], node.scale[2]);
    }
    for (int i : h.order) {
        const auto k = std::size_t(i);
        const Eigen::Matrix4d local
            = h.hasMatrix[k] ? h.matrix[k] : composeTrs(h.translation[k], h.rotation[k], h.scale[k]);
        h.restGlobal[k] = h.parent[k] < 0 ? local : Eigen::Matrix4d(h.restGlobal[std::size_t(h.parent[k])] * local);
    }
    return h;
}

std::vector<Track> readFirstAnimation(const Source& src, const Hierarchy& nodes, const std::vector<int>& morphTargets)
{
    std::vector<Track> tracks;
    // Only the first animation is read: a file with several (walk, run, jump) gives the first one;
    // choosing another would be an option of the import.
    if (src.model.animations.empty())
        return tracks;
    const tinygltf::Animation& animation = src.model.animations.front();
    for (std::size_t c = 0; c < animation.channels.size(); ++c) {
        const tinygltf::AnimationChannel& channel = animation.channels[c];
        if (channel.target_node < 0) // glTF allows channels for extensions only
            continue;
        if (std::size_t(channel.target_node) >= nodes.parent.size())
            throw IoError(src.path,
                AnimationIo::tr("animation channel %1 targets node %2, which does not exist")
                    .arg(c)
                    .arg(channel.target_node));
        Track track;
        track.node = channel.target_node;
        const auto node = std::size_t(track.node);
        if (channel.target_path == "translation") {
            track.path = TrackPath::Translation;
            track.width = 3;
        } else if (channel.target_path == "rotation") {
            track.path = TrackPath::Rotation;
            track.width = 4;
        } else if (channel.target_path == "scale") {
            track.path = TrackPath::Scale;
            track.width = 3;
        } else if (channel.target_path == "weights") {
            track.path = TrackPath::Weights;
            track.width = morphTargets[node];
            if (track.width == 0) // weights of a node without morph targets move nothing
                continue;
        } else {
            continue; // "pointer" and other extensions' paths
        }
        if (track.path != TrackPath::Weights && nodes.hasMatrix[node])
            throw IoError(src.path,
                AnimationIo::tr("animation channel %1 moves node %2, which is given as a matrix (glTF allows only "
                                "translation, rotation and scale on animated nodes)")
                    .arg(c)
                    .arg(track.node));
        if (channel.sampler < 0 || std::size_t(channel.sampler) >= animation.samplers.size())
            throw IoError(src.path,
                AnimationIo::tr("animation channel %1 names sampler %2, which does not exist")
                    .arg(c)
                    .arg(channel.sampler));
        const tinygltf::AnimationSampler& sampler = animation.samplers[std::size_t(channel.sampler)];
        if (sampler.interpolation == "LINEAR" || sampler.interpolation.empty())
            track.interpolation = Interpolation::Linear;
        else if (sampler.interpolation == "STEP")
            track.interpolation = Interpolation::Step;
        else if (sampler.interpolation == "CUBICSPLINE")
            track.interpolation = Interpolation::CubicSpline;
        else
            throw IoError(src.path,
                AnimationIo::tr("animation sampler %1 has an unknown interpolation \"%2\"")
                    .arg(channel.sampler)
                    .arg(QString::fromStdString(sampler.interpolation)));
        const QString what = AnimationIo::tr("animation sampler %1").arg(channel.sampler);
        track.times = readFloats(src, sampler.input, TINYGLTF_TYPE_SCALAR, what);
        if (track.times.empty())
            throw IoError(src.path, AnimationIo::tr("animation sampler %1 has no keys").arg(channel.sampler));
        for (std::size_t k = 0; k < track.times.size(); ++k)
            if (!std::isfinite(track.times[k]) || track.times[k] < 0.0f
                || (k > 0 && track.times[k] <= track.times[k - 1])) // glTF 2.0: strictly increasing
                throw IoError(src.path,
                    AnimationIo::tr("animation sampler %1: key %2 has time %3, not after the key before it")
                        .arg(channel.sampler)
                        .arg(k)
                        .arg(double(track.times[k])));
        const int outputType = track.path == TrackPath::Rotation ? TINYGLTF_TYPE_VEC4
            : track.path == TrackPath::Weights                   ? TINYGLTF_TYPE_SCALAR
                                                                 : TINYGLTF_TYPE_VEC3;
        track.values = readFloats(src, sampler.output, outputType, what);
        const std::size_t perKey
            = std::size_t(track.width) * (track.interpolation == Interpolation::CubicSpline ? 3 : 1);
        if (track.values.size() != track.times.size() * perKey)
            throw IoError(src.path,
                AnimationIo::tr("animation sampler %1 has %2 output values for %3 keys, expected %4")
                    .arg(channel.sampler)
                    .arg(track.values.size())
                    .arg(track.times.size())
                    .arg(track.times.size() * perKey));
        if (!std::all_of(track.values.begin(), track.values.end(), [](float v) { return std::isfinite(v); }))
            throw IoError(src.path,
                AnimationIo::tr("animation sampler %1 has a value that is not a finite number").arg(channel.sampler));
        tracks.push_back(std::move(track));
    }
    return tracks;
}

void sampleTrack(const Track& track, double t, double* out)
{
    const std::size_t w = std::size_t(track.width);
    const bool cubic = track.interpolation == Interpolation::CubicSpline;
    // The value of key k (in a cubic spline's key: in-tangent, value, out-tangent).
    const auto value = [&](std::size_t k) { return track.values.data() + (cubic ? (3 * k + 1) * w : k * w); };
    const std::size_t keys = track.times.size();
    // Before the first key and after the last, the ends hold.
    const auto after = std::upper_bound(track.times.begin(), track.times.end(), float(t));
    if (after == track.times.begin() || after == track.times.end()) {
        const float* v = value(after == track.times.begin() ? 0 : keys - 1);
        std::copy(v, v + w, out);
        if (track.path == TrackPath::Rotation)
            normaliseQuaternion(out);
        return;
    }
    const auto k1 = std::size_t(after - track.times.begin());
    const std::size_t k0 = k1 - 1;
    const double t0 = track.times[k0];
    const double dt = double(track.times[k1]) - t0; // > 0: upper_bound skips equal times
    const double u = std::clamp((t - t0) / dt, 0.0, 1.0);
    const float* a = value(k0);
    const float* b = value(k1);
    switch (track.interpolation) {
    case Interpolation::Step:
        std::copy(a, a + w, out);
        break;
    case Interpolation::Linear:
        if (track.path == TrackPath::Rotation) {
            // Spherical interpolation along the shorter arc (Eigen's slerp turns to it).
            const Eigen::Quaterniond q = keyQuaternion(a).slerp(u, keyQuaternion(b));
            out[0] = q.x();
            out[1] = q.y();
            out[2] = q.z();
            out[3] = q.w();
        } else {
            for (std::size_t i = 0; i < w; ++i)
                out[i] = a[i] + u * (double(b[i]) - a[i]);
        }
        break;
    case Interpolation::CubicSpline: {
        // Hermite spline (glTF 2.0 appendix C): the tangents are scaled by the key interval.
        const float* outTangent = a + w; // key k0's out-tangent follows its value
        const float* inTangent = b - w; // key k1's in-tangent precedes its value
        const double u2 = u * u;
        const double u3 = u2 * u;
        const double h00 = 2 * u3 - 3 * u2 + 1;
        const double h10 = u3 - 2 * u2 + u;
        const double h01 = -2 * u3 + 3 * u2;
        const double h11 = u3 - u2;
        for (std::size_t i = 0; i < w; ++i)
            out[i] = h00 * a[i] + h10 * dt * outTangent[i] + h01 * b[i] + h11 * dt * inTangent[i];
        break;
    }
    }
    if (track.path == TrackPath::Rotation)
        normaliseQuaternion(out);
}

void globalTransforms(
    const Hierarchy& nodes, const std::vector<Track>& tracks, double t, std::vector<Eigen::Matrix4d>& globals)
{
    const std::size_t n = nodes.parent.size();
    // Local transforms first, in globals, with the tracks' values over the rest TRS.
    std::vector<Eigen::Vector3d> translation = nodes.translation;
    std::vector<Eigen::Quaterniond> rotation = nodes.rotation;
    std::vector<Eigen::Vector3d> scale = nodes.scale;
    std::vector<char> moved(n, 0);
    double v[4];
    for (const Track& track : tracks) {
        if (track.path == TrackPath::Weights)
            continue;
        const auto k = std::size_t(track.node);
        sampleTrack(track, t, v);
        moved[k] = 1;
        if (track.path == TrackPath::Translation)
            translation[k] = Eigen::Vector3d(v[0], v[1], v[2]);
        else if (track.path == TrackPath::Scale)
            scale[k] = Eigen::Vector3d(v[0], v[1], v[2]);
        else
            rotation[k] = quaternion(v);
    }
    globals.resize(n);
    for (int i : nodes.order) {
        const auto k = std::size_t(i);
        const Eigen::Matrix4d local
            = nodes.hasMatrix[k] && !moved[k] ? nodes.matrix[k] : composeTrs(translation[k], rotation[k], scale[k]);
        globals[k] = nodes.parent[k] < 0 ? local : Eigen::Matrix4d(globals[std::size_t(nodes.parent[k])] * local);
    }
}

} // namespace celform::model::animio::gltf
