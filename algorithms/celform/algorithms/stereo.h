// Stereo previews (paper 3, section 3.1): a camera pair from the working camera, off-axis
// (default) or toe-in, and the anaglyph and side-by-side compositions.
#pragma once

#include "celform/algorithms/image.h"
#include "celform/algorithms/raster.h"

#include <Eigen/Core>

#include <utility>

namespace celform::algo {

struct StereoSettings {
    double interocular = 0.065; ///< eye separation, model units
    double convergence = 2.0; ///< distance of the zero-parallax plane from the centre eye
    bool toeIn = false; ///< rotate the eyes towards the convergence point instead of shifting
    bool swapEyes = false;
    bool operator==(const StereoSettings& o) const
    {
        return interocular == o.interocular && convergence == o.convergence && toeIn == o.toeIn
            && swapEyes == o.swapEyes;
    }
};

/// Left and right eye cameras from the centre camera. Off-axis: eyes moved by -/+ interocular/2
/// along the camera's right vector, same direction, frusta shifted so that points at the
/// convergence distance project to the same pixel in both eyes (zero disparity):
/// horizontalShift -/+ f b / (C w) with b = interocular / 2, f the focal length in pixels.
/// Sign convention (tested): disparity = x_right - x_left = 2 f b (1/C - 1/D) for depth D is
/// negative (crossed, x_left > x_right) in front of the convergence plane, positive (uncrossed)
/// behind it. Toe-in: eyes at -/+ b, both aimed at eye + C forward, no shift.
/// Orthographic cameras: shifting parallel eyes would give no depth at all, so both eyes are
/// turned by atan(b / C) about the up axis through the convergence point instead (toe-in, same
/// signs, disparity linear in depth), whatever toeIn says. swapEyes exchanges the two cameras.
/// convergence must be > 0 (asserted); a non-finite convergence gives parallel eyes.
std::pair<RasterCamera, RasterCamera> stereoPair(const RasterCamera& centre, const StereoSettings& settings);

enum class StereoOutput { Off, Anaglyph, Dubois, HalfColor, SideBySide, TopBottom };

/// Dubois least-squares red/cyan matrices (rows give output R, G, B from input R, G, B).
struct DuboisMatrices {
    Eigen::Matrix3f left;
    Eigen::Matrix3f right;
    static DuboisMatrices redCyan();
};

/// The compositions need images of the same size and return an empty image otherwise; alpha is
/// the larger of the two eyes' alphas.
/// Red/cyan by channel mask, paper 3, section 4.5.2: left * (1, 0, 0) + right * (0, 1, 1).
ImageRGBA composeAnaglyph(const ImageRGBA& left, const ImageRGBA& right);
/// Dubois: the matrices applied to linear-light colours, clamped to [0, 1] (images here are
/// linear already; encoding happens when the file is written).
ImageRGBA composeDubois(
    const ImageRGBA& left, const ImageRGBA& right, const DuboisMatrices& m = DuboisMatrices::redCyan());
/// Half-colour: red from the left eye's luminance, green and blue from the right eye.
ImageRGBA composeHalfColor(const ImageRGBA& left, const ImageRGBA& right);
/// Side by side (left eye on the left) or top-bottom (left eye on top), full resolution each.
ImageRGBA composeSideBySide(const ImageRGBA& left, const ImageRGBA& right);
ImageRGBA composeTopBottom(const ImageRGBA& left, const ImageRGBA& right);

} // namespace celform::algo
