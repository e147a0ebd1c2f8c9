// Internal to the glTF half of the animated base import: the loaded file, its accessors read
// with every bound checked, the node hierarchy, and the animation tracks that are sampled.
#pragma once

#include "celform/model/io/animation_io_common.h"

#include <tiny_gltf.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <vector>

namespace celform::model::animio::gltf {

/// A parsed glTF file and its path, for the messages.
struct Source {
    QString path;
    tinygltf::Model model;
};

/// animation_io_gltf_load.cpp: parses the .gltf or .glb file (external buffers from regular files
/// only, images not decoded). Throws IoError for a missing, empty, truncated or malformed file.
Source load(const QString& path);

/// animation_io_gltf_accessor.cpp: the elements of accessor `index`, which must have the glTF
/// type `type` (TINYGLTF_TYPE_*), as count * components values, byteStride and sparse
/// substitution applied. Float output takes float components and integers (normalised ones
/// mapped to [0, 1] or [-1, 1]); integer output takes unsigned integer components only. `what`
/// names the use in messages ("POSITION of mesh 2"). Throws IoError for an index, a view or a
/// range outside the file, a wrong type, and counts the buffers cannot hold.
std::vector<float> readFloats(const Source& src, int index, int type, const QString& what);
std::vector<std::uint32_t> readIntegers(const Source& src, int index, int type, const QString& what);

/// The node tree: parents, an order with parents before children, rest transforms.
struct Hierarchy {
    std::vector<int> parent; ///< -1 for a root
    std::vector<int> order; ///< every node, each after its parent
    /// Each node's rest TRS (a node given as a matrix keeps it in `matrix`).
    std::vector<Eigen::Vector3d> translation;
    std::vector<Eigen::Quaterniond> rotation;
    std::vector<Eigen::Vector3d> scale;
    std::vector<Eigen::Matrix4d> matrix;
    std::vector<char> hasMatrix;
    std::vector<Eigen::Matrix4d> restGlobal;
};

/// animation_io_gltf_animation.cpp: throws IoError for a node reached twice, a cycle, or an
/// index out of range.
Hierarchy readHierarchy(const Source& src);

enum class TrackPath { Translation, Rotation, Scale, Weights };
enum class Interpolation { Linear, Step, CubicSpline };

/// One channel of the animation with its sampler's keys: `width` values per key (3, 4 or the
/// node's morph target count), three times as many for CUBICSPLINE (in-tangent, value,
/// out-tangent).
struct Track {
    int node = -1;
    TrackPath path = TrackPath::Translation;
    Interpolation interpolation = Interpolation::Linear;
    int width = 0;
    std::vector<float> times;
    std::vector<float> values;
};

/// The channels of the file's first animation (the others are not read) that act on a node;
/// morphTargets[n] is node n's morph target count (a weights channel must give that many
/// values per key). Throws IoError for malformed samplers.
std::vector<Track> readFirstAnimation(const Source& src, const Hierarchy& nodes, const std::vector<int>& morphTargets);

/// Writes track's value at time t to out[0 .. width).
void sampleTrack(const Track& track, double t, double* out);

/// Every node's global transform at time t under the tracks (weights tracks ignored); globals
/// must have one matrix per node.
/// (C++17 allocates the over-aligned matrices of std::vector correctly.)
void globalTransforms(
    const Hierarchy& nodes, const std::vector<Track>& tracks, double t, std::vector<Eigen::Matrix4d>& globals);

} // namespace celform::model::animio::gltf
