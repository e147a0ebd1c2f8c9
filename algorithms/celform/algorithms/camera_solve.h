// Semi-automatic alignment: a camera from at least six 3D model points and their 2D positions
// on a drawing (DLT, then Levenberg-Marquardt on the reprojection error).
#pragma once

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace celform::algo {

/// A pinhole camera: eye, target, up and vertical field of view, as the document stores it.
struct SolvedCamera {
    Eigen::Vector3d eye;
    Eigen::Vector3d target;
    Eigen::Vector3d up;
    double fovYDegrees = 30.0;
    double rmsPixelError = 0.0; ///< root mean square of the per-point pixel distances after refinement
};

/// points3d: model-space points; points2d: their pixel positions on the drawing (x right, y down,
/// origin at the top-left corner of the top-left pixel, so the image centre is (w/2, h/2)) in an
/// image of imageWidth x imageHeight. Square pixels and a principal point at the image centre are
/// assumed after the DLT. Needs >= 6 pairs in general position. The result's up is the camera's up
/// (minus the image y axis) and target lies on the view axis at the distance of the points'
/// centroid. Returns nothing (and sets an English error) for fewer pairs, mismatched sizes,
/// non-finite input, a non-positive image size, (near-)coplanar 3D points (the DLT needs depth),
/// points behind the solved camera or a solve that does not converge.
std::optional<SolvedCamera> solveCamera(const std::vector<Eigen::Vector3d>& points3d,
    const std::vector<Eigen::Vector2d>& points2d, int imageWidth, int imageHeight, std::string* error = nullptr);

/// Projects a model point with a camera to drawing pixels (same conventions as solveCamera), for
/// tests and the overlay of correspondences. up need not be orthogonal to the view axis. Points
/// not in front of the eye give (NaN, NaN).
Eigen::Vector2d projectToImage(
    const SolvedCamera& camera, const Eigen::Vector3d& point, int imageWidth, int imageHeight);

} // namespace celform::algo
