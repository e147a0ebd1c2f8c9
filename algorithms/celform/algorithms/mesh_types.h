// The array types every module shares: Eigen row-major storage, so a whole array can be handed to
// VTK or written to a file without reshuffling.
#pragma once

#include <Eigen/Core>

#include <cstdint>

namespace celform::algo {

/// #V by 3 vertex positions (x, y, z), float as in every mesh file format.
using Positions = Eigen::Matrix<float, Eigen::Dynamic, 3, Eigen::RowMajor>;
/// #F by 3 vertex indices of counter-clockwise triangles.
using Faces = Eigen::Matrix<std::int32_t, Eigen::Dynamic, 3, Eigen::RowMajor>;
/// #T by 2 texture coordinates.
using TexCoords = Eigen::Matrix<float, Eigen::Dynamic, 2, Eigen::RowMajor>;

} // namespace celform::algo
