// The model sheet's inking (scripts/make-model-sheet.sh): the warped silhouette's contour drawn
// with a brush whose width follows the contour's normal (thick on the shadow side, thin in the
// light, with a slow wobble), thinner inner lines, white paint inside, transparent outside.
#pragma once

#include "celform/algorithms/outline.h"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace sheet {

struct InkSettings {
    int supersample = 3; ///< the masks are this many times the sheet's size in each direction
    double outlineThin = 2.2; ///< contour width in sheet pixels where the normal faces the light
    double outlineThick = 5.0; ///< contour width in sheet pixels on the shadow side
    /// Radius in sheet pixels of the box passes (three each way, about a Gaussian of this sigma)
    /// that round the figure's facet corners before inking; 0 keeps the figure as it is.
    double smoothing = 2.0;
    double innerThin = 1.0; ///< inner line widths in sheet pixels
    double innerThick = 2.2;
    /// Image direction (x right, y down) of the shadow side: contours whose outward normal points
    /// this way get the thick line.
    Eigen::Vector2d shadow{0.35, 0.94};
    /// Inner lines with fewer supersampled pixels than this are dropped as specks.
    int minInnerPixels = 120;
};

/// Inks a figure: rawFigure and innerLines are supersampled masks (width * supersample by height *
/// supersample, 1 = set); returns an 8-bit RGBA drawing of width x height, black ink on white
/// paint inside the figure, transparent outside.
celform::algo::DrawingImage inkFigure(const std::vector<std::uint8_t>& figure,
    const std::vector<std::uint8_t>& innerLines, int width, int height, const InkSettings& settings);

} // namespace sheet
