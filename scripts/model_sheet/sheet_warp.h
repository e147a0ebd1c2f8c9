// The model sheet's exaggeration (scripts/make-model-sheet.sh): a smooth 2D displacement field of
// the image plane, the sum of Gaussian radial-basis fields, that enlarges the ears about their
// centres and stretches the trunk beyond its tip, and its inverse map, by which the warped images
// are resampled.
#pragma once

#include <Eigen/Core>

#include <vector>

namespace sheet {

/// An ear: its centre and the Gaussian's sigma in pixels; points near the centre move outward by
/// gain (q - centre) exp(-|q - centre|^2 / (2 sigma^2)), so the rim at about one sigma grows by
/// about 0.6 gain.
struct EarField {
    Eigen::Vector2d centre;
    double sigma = 1.0;
    double gain = 0.3;
};

/// A trunk: its centreline in pixels from the tip to the base, and the stretch. A point q near the
/// centreline moves by stretch (C(q) - base) T(q), where C(q) is the Gaussian-weighted mean of the
/// centreline points (about the nearest point of the centreline, but smooth everywhere) and T(q) =
/// 1 - prod_k (1 - g_k(q)) the soft union of the points' Gaussians: each cross-section of the trunk
/// slides along as its centreline point does, so the centreline becomes base + (1 + stretch)
/// (point - base), the trunk's shape scaled about its base, and the trunk is longer by stretch
/// without growing thicker.
struct TrunkField {
    std::vector<Eigen::Vector2d> centreline; ///< tip first, base last
    double sigma = 1.0;
    double stretch = 0.12;
};

struct Exaggeration {
    std::vector<EarField> ears;
    std::vector<TrunkField> trunks;

    /// The forward displacement d(q): a point q of the model's image moves to q + d(q).
    [[nodiscard]] Eigen::Vector2d displacement(const Eigen::Vector2d& q) const;
    /// The point q with q + d(q) = p, by the fixed-point iteration q <- p - d(q) (a contraction
    /// while |grad d| < 1, which minJacobian checks).
    [[nodiscard]] Eigen::Vector2d inverse(const Eigen::Vector2d& p) const;
};

/// The inverse map of a width x height image, sampled every step pixels and interpolated
/// bilinearly in between: for every pixel centre p of the warped image, the point of the source
/// image (same pixel units) that lands on it. scale multiplies pixel coordinates before the field
/// is evaluated (the field is given at the sheet's size, the images are supersampled).
class InverseMap {
public:
    InverseMap(const Exaggeration& field, int width, int height, double scale, int step);
    [[nodiscard]] Eigen::Vector2d at(int x, int y) const;

private:
    int width_;
    int height_;
    int step_;
    int gridWidth_;
    int gridHeight_;
    std::vector<Eigen::Vector2d> grid_;
};

/// The smallest determinant of I + grad d over a grid of the image (central differences): positive
/// means the warp folds nowhere.
double minJacobian(const Exaggeration& field, int width, int height, int step);

} // namespace sheet
