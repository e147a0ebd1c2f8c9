// The outer outline of a reference drawing, the target of fitting a model to a drawing (paper 1,
// future work: "semi-automatic alignment and deformation based on feature correspondence"; the
// correspondence here is the character's outline against the model's silhouette). The ink (alpha
// where the drawing has real alpha, else dark luminance under a threshold) is closed by a disc to
// bridge the gaps of open line art, its holes are filled, the largest component is kept and its
// boundary is traced to a closed sub-pixel polygon.
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <string>
#include <vector>

namespace celform::algo {

/// An 8-bit drawing as image files hold it (sRGB, not premultiplied): channels 1 (grey), 2 (grey,
/// alpha), 3 (RGB) or 4 (RGBA) interleaved per pixel, row 0 at the top, no row padding.
struct DrawingImage {
    int width = 0;
    int height = 0;
    int channels = 4;
    std::vector<std::uint8_t> pixels; ///< width * height * channels
};

struct OutlineSettings {
    /// Ink where the luminance (0 black .. 1 white) is below this; negative: Otsu's threshold,
    /// chosen from the histogram. Unused when the alpha channel decides.
    double threshold = -1.0;
    /// Radius in pixels of the disc closing the ink (dilation, hole filling, erosion): gaps of
    /// open line art up to about twice this wide close. 0 closes nothing.
    double closingRadius = 2.0;
    /// Use the alpha channel where the drawing has real alpha (some pixels not opaque); the ink is
    /// then alpha >= 0.5. Off: always the luminance of the colour composited over white.
    bool useAlpha = true;
    /// Fill the holes of the kept region (the interior of line art, eyes, gaps between legs that
    /// the outline encloses). Off keeps only the ink itself.
    bool fillHoles = true;
    /// 0: keep the largest component only; > 0: keep every component of at least this many pixels
    /// (the largest is always kept).
    int minComponentPixels = 0;
    /// The thinnest region accepted as a filled figure: the largest disc inside the kept region
    /// must have at least this radius in pixels, else the ink never closed into an outline. 0
    /// chooses max(4, closingRadius + 2, 1 % of the image's shorter side).
    double minThickness = 0.0;
    /// Refuse an outline whose region touches the image border (the figure is cut by the frame).
    bool rejectBorder = true;
};

enum class OutlineError {
    None,
    EmptyImage, ///< no pixels, or a pixel buffer of the wrong size
    NothingFound, ///< all background or all ink: nothing to separate
    NoClosedOutline, ///< the ink stays thin line work: no enclosed figure
    TouchesBorder, ///< the figure reaches the image border
};

/// A short English sentence for the error (the editor translates by error, not by sentence).
std::string outlineErrorMessage(OutlineError error);

/// The extracted outline. Pixel coordinates: x right, y down, origin at the top-left corner of
/// the top-left pixel, pixel centres at +0.5 (the convention of projectToImage and RasterCamera).
struct Outline {
    OutlineError error = OutlineError::None;
    int width = 0;
    int height = 0;
    /// The filled figure, 1 inside, width * height (empty on error).
    std::vector<std::uint8_t> mask;
    /// Closed polygons (last point not repeated) around each kept component, largest area first,
    /// with the figure on their left: outer boundaries have a positive polygonArea, the boundaries
    /// of holes (kept only without fillHoles) a negative one. Either way, for an edge direction
    /// (dx, dy) the normal pointing away from the figure is (dy, -dx) in pixel coordinates.
    std::vector<std::vector<Eigen::Vector2d>> contours;
    double thresholdUsed = -1.0; ///< luminance threshold in [0, 1], or -1 when alpha decided
    bool usedAlpha = false;
    /// Whether the figure's holes were filled (OutlineSettings::fillHoles): the fits then compare
    /// it with the model's silhouette with its holes filled too, like with like.
    bool holesFilled = true;
    [[nodiscard]] bool ok() const { return error == OutlineError::None; }
};

/// The drawing's outline with the given settings (see OutlineSettings for each step).
Outline extractOutline(const DrawingImage& image, const OutlineSettings& settings = {});

/// Background pixels of a 0 / 1 mask not connected (4-connectivity) to the image border become
/// set: the holes of the figure are filled, its 8-connected outline kept.
void fillMaskHoles(std::vector<std::uint8_t>& mask, int width, int height);
/// The same with working memory kept by the caller.
void fillMaskHoles(std::vector<std::uint8_t>& mask, int width, int height, std::vector<std::uint8_t>& reached,
    std::vector<std::int32_t>& stack);

/// Otsu's threshold of an 8-bit histogram (256 bins): the level t in [0, 255] that maximises the
/// between-class variance of {< t} and {>= t}; -1 when the histogram has fewer than two levels.
int otsuThreshold(const std::vector<std::int64_t>& histogram);

/// A closed polygon resampled at (about) equal arc-length spacing in pixels.
std::vector<Eigen::Vector2d> resampleClosed(const std::vector<Eigen::Vector2d>& polygon, double spacing);

/// Signed area of a closed polygon (positive when counter-clockwise in x right, y up axes, so
/// negative for the same turn on screen with y down).
double polygonArea(const std::vector<Eigen::Vector2d>& polygon);

} // namespace celform::algo
