// How well a model meets a drawing (DESIGN.md, "Drawings and cameras"): the model's silhouette
// mask seen through the drawing's camera, the symmetric chamfer distance in drawing pixels between
// its boundary and the drawing's outline (through distance transforms, Meijster et al. 2002), and
// the intersection over union of the two filled masks. Fitting a camera or a shape to a drawing
// minimises the chamfer distance (fit_camera.h, fit_shape.h); both figures are reported.
#pragma once

#include "celform/algorithms/distance_transform.h"
#include "celform/algorithms/mesh_types.h"
#include "celform/algorithms/outline.h"
#include "celform/algorithms/raster.h"

#include <cstdint>
#include <vector>

namespace celform::algo {

/// Robust losses of a residual r (pixels) with scale c (pixels): rho(r), and the weight
/// rho'(r) / r of iteratively reweighted least squares.
///  - None: r^2 / 2, weight 1.
///  - Huber: r^2 / 2 for |r| <= c, else c (|r| - c / 2); weight min(1, c / |r|).
///  - Tukey: c^2 / 6 (1 - (1 - (r/c)^2)^3) for |r| <= c, else c^2 / 6; weight (1 - (r/c)^2)^2,
///    0 beyond c (outliers are ignored altogether).
enum class RobustLoss { None, Huber, Tukey };

struct RobustKernel {
    RobustLoss loss = RobustLoss::Huber;
    double scale = 3.0; ///< pixels
    [[nodiscard]] double rho(double r) const;
    [[nodiscard]] double weight(double r) const;
};

/// The figures of a fit, in drawing pixels.
struct FitMetrics {
    double iou = 0.0; ///< |silhouette and outline| / |silhouette or outline| of the filled masks
    double chamferPx = 0.0; ///< symmetric: the mean of the two directed means below
    double silhouetteToOutlinePx = 0.0; ///< mean distance of silhouette boundary pixels to the outline's
    double outlineToSilhouettePx = 0.0; ///< mean distance of outline boundary pixels to the silhouette's
    double robustCost = 0.0; ///< mean of the kernel's rho over both boundaries (the fits' objective)
    bool valid = false; ///< false when either mask is empty (then iou 0, distances infinite)
};

/// Working memory of the figures, kept by a caller that measures again and again (a fit, a live
/// panel): a megapixel drawing's transforms need tens of megabytes, and fresh pages cost more than
/// the transforms themselves.
struct FitScratch {
    DistanceTransformScratch transform;
    std::vector<float> inside;
    std::vector<float> outside;
    std::vector<std::uint8_t> bytes;
    std::vector<std::uint8_t> boundary;
    std::vector<std::uint8_t> mask;
    std::vector<std::uint8_t> reached;
    std::vector<std::int32_t> stack;
    std::vector<std::int32_t> nearest;
    std::vector<std::int32_t> owner;
};

/// The projection of every vertex of shape through camera: pixel x, pixel y, depth
/// (RasterCamera::project), #V rows.
Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> projectVertices(
    const Positions& shape, const RasterCamera& camera);

/// The silhouette mask (camera.width x camera.height, 1 where a triangle covers the pixel centre)
/// of the mesh through camera: the coverage of rasterise() (pixel-centre sampling) without the
/// depth test and the G-buffer, which a silhouette does not need. Triangles with a corner at or
/// behind the eye plane (depth <= 0) are skipped: the fits keep the model in front of the camera.
void silhouetteMask(
    const Positions& shape, const Faces& faces, const RasterCamera& camera, std::vector<std::uint8_t>& mask);

/// The same coverage for vertices already projected (pixel x, pixel y, depth per row), into a
/// width x height mask (the coarse levels of a pyramid scale x and y first).
void coverageMask(const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>& projected, const Faces& faces,
    int width, int height, std::vector<std::uint8_t>& mask);

/// Inner boundary pixels of a mask: inside, with a 4-neighbour outside or on the image border.
void maskBoundary(const std::uint8_t* mask, int width, int height, std::vector<std::uint8_t>& boundary);

/// Signed distance (pixels) to the boundary of a mask, sampled at pixel centres: negative inside,
/// positive outside, +/-0.5 on the pixels either side of the boundary, so bilinear interpolation
/// crosses zero half way between them. Two Meijster transforms.
void signedDistanceField(
    const std::uint8_t* mask, int width, int height, std::vector<float>& field, FitScratch* scratch = nullptr);

/// Bilinear interpolation of a width x height field at pixel position (x, y) (pixel centres at
/// +0.5), clamped to the border pixels; the gradient (d/dx, d/dy) when asked.
double sampleBilinear(
    const std::vector<float>& field, int width, int height, double x, double y, Eigen::Vector2d* gradient = nullptr);

/// The figures of two masks of the same size.
FitMetrics compareMasks(const std::uint8_t* silhouette, const std::uint8_t* outline, int width, int height,
    const RobustKernel& kernel = {}, FitScratch* scratch = nullptr);

/// The figures of a mesh seen through camera against a drawing's outline (outline.mask); the
/// camera's image size is taken from the outline; the silhouette's holes are filled when the
/// outline's were. Invalid when the outline failed.
FitMetrics measureFit(const Positions& shape, const Faces& faces, const RasterCamera& camera, const Outline& outline,
    const RobustKernel& kernel = {}, FitScratch* scratch = nullptr);

/// A mask shrunk by an integer factor (a pixel of the result is set when at least half of its
/// block is), for the coarse levels of the fits' image pyramids.
std::vector<std::uint8_t> downsampleMask(
    const std::vector<std::uint8_t>& mask, int width, int height, int factor, int& outWidth, int& outHeight);

} // namespace celform::algo
