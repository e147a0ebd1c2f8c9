// Inking the warped silhouette (sheet_ink.h). Line bands come from exact distance transforms
// (Meijster et al. 2002, algo::nearestFeatureTransform): a pixel is ink when it lies within the
// width of the nearest contour pixel, whose width is set by the contour's normal there.
#include "sheet_ink.h"

#include "celform/algorithms/distance_transform.h"
#include "celform/algorithms/fit_metrics.h"

#include <algorithm>
#include <cmath>

namespace sheet {

namespace {

using celform::algo::DistanceTransformScratch;

/// One running-sum box pass of radius r along rows (horizontal) or columns, in place.
void boxPass(std::vector<float>& image, int width, int height, int radius, bool horizontal)
{
    const int lines = horizontal ? height : width;
    const int length = horizontal ? width : height;
    std::vector<float> line(std::size_t(length), 0.0f);
    const auto index = [&](int l, int i) {
        return horizontal ? std::size_t(l) * std::size_t(width) + std::size_t(i)
                          : std::size_t(i) * std::size_t(width) + std::size_t(l);
    };
    for (int l = 0; l < lines; ++l) {
        for (int i = 0; i < length; ++i)
            line[std::size_t(i)] = image[index(l, i)];
        double sum = 0.0;
        const auto value = [&](int i) { return line[std::size_t(std::clamp(i, 0, length - 1))]; };
        for (int i = -radius; i <= radius; ++i)
            sum += value(i);
        for (int i = 0; i < length; ++i) {
            image[index(l, i)] = float(sum / (2 * radius + 1));
            sum += value(i + radius + 1) - value(i - radius);
        }
    }
}

/// Three box passes each way: close to a Gaussian of sigma about radius.
std::vector<float> blurred(const std::vector<std::uint8_t>& mask, int width, int height, int radius)
{
    std::vector<float> image(mask.begin(), mask.end());
    for (int pass = 0; pass < 3; ++pass) {
        boxPass(image, width, height, radius, true);
        boxPass(image, width, height, radius, false);
    }
    return image;
}

/// A slow wobble of the brush along the page, in [-1, 1]: hands do not hold a width steady.
double wobble(double x, double y)
{
    return 0.6 * std::sin(x / 41.0 + 1.3 * std::sin(y / 67.0)) + 0.4 * std::sin(y / 29.0 - x / 83.0);
}

/// Drops 8-connected components of lines smaller than minPixels.
void dropSpecks(std::vector<std::uint8_t>& lines, int width, int height, int minPixels)
{
    std::vector<std::uint8_t> seen(lines.size(), 0);
    std::vector<std::int32_t> stack;
    std::vector<std::int32_t> component;
    for (std::size_t start = 0; start < lines.size(); ++start) {
        if (!lines[start] || seen[start])
            continue;
        component.clear();
        stack.assign(1, std::int32_t(start));
        seen[start] = 1;
        while (!stack.empty()) {
            const std::int32_t p = stack.back();
            stack.pop_back();
            component.push_back(p);
            const int x = p % width;
            const int y = p / width;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = x + dx;
                    const int ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= width || ny >= height)
                        continue;
                    const std::size_t n = std::size_t(ny) * std::size_t(width) + std::size_t(nx);
                    if (lines[n] && !seen[n]) {
                        seen[n] = 1;
                        stack.push_back(std::int32_t(n));
                    }
                }
        }
        if (int(component.size()) < minPixels)
            for (const std::int32_t p : component)
                lines[std::size_t(p)] = 0;
    }
}

/// Ink coverage where a pixel of the figure lies within the half width (or full width, inside)
/// of its nearest feature pixel. widthOf gives a feature pixel's width in supersampled pixels.
template <typename WidthOf>
void inkBand(const std::vector<std::uint8_t>& features, const std::vector<std::uint8_t>& figure, int width, int height,
    bool centred, WidthOf widthOf, DistanceTransformScratch& scratch, std::vector<std::uint8_t>& ink)
{
    std::vector<std::int32_t> nearest(features.size());
    std::vector<std::uint32_t> squared(features.size());
    celform::algo::nearestFeatureTransform(features.data(), width, height, nearest.data(), squared.data(), scratch);
    for (std::size_t p = 0; p < features.size(); ++p) {
        if (!figure[p] || nearest[p] < 0)
            continue;
        const double reach = centred ? 0.5 * widthOf(nearest[p]) : widthOf(nearest[p]);
        if (std::sqrt(double(squared[p])) + 0.5 <= reach)
            ink[p] = 1;
    }
}

} // namespace

celform::algo::DrawingImage inkFigure(const std::vector<std::uint8_t>& rawFigure,
    const std::vector<std::uint8_t>& innerLines, int width, int height, const InkSettings& settings)
{
    const int s = settings.supersample;
    const int bigWidth = width * s;
    const int bigHeight = height * s;
    DistanceTransformScratch scratch;
    std::vector<std::uint8_t> ink(rawFigure.size(), 0);

    // A hand does not follow the facets of a mesh: the figure blurred and cut at half.
    std::vector<std::uint8_t> figure = rawFigure;
    if (settings.smoothing > 0.0) {
        const std::vector<float> rounded
            = blurred(rawFigure, bigWidth, bigHeight, int(std::lround(settings.smoothing * s)));
        for (std::size_t p = 0; p < figure.size(); ++p)
            figure[p] = rounded[p] >= 0.5f ? 1 : 0;
    }

    // The contour: inner boundary pixels; the outward normal from a blurred copy of the figure.
    std::vector<std::uint8_t> boundary;
    celform::algo::maskBoundary(figure.data(), bigWidth, bigHeight, boundary);
    const std::vector<float> soft = blurred(figure, bigWidth, bigHeight, 2 * s);
    const Eigen::Vector2d shadow = settings.shadow.normalized();
    std::vector<float> contourWidth(figure.size(), 0.0f);
    for (int y = 1; y + 1 < bigHeight; ++y)
        for (int x = 1; x + 1 < bigWidth; ++x) {
            const std::size_t p = std::size_t(y) * std::size_t(bigWidth) + std::size_t(x);
            if (!boundary[p])
                continue;
            const Eigen::Vector2d gradient(
                soft[p + 1] - soft[p - 1], soft[p + std::size_t(bigWidth)] - soft[p - std::size_t(bigWidth)]);
            const Eigen::Vector2d outward
                = gradient.norm() > 1e-9 ? Eigen::Vector2d(-gradient.normalized()) : Eigen::Vector2d::Zero();
            const double t = std::clamp((outward.dot(shadow) + 0.35) / 1.35, 0.0, 1.0);
            const double lit = t * t * (3.0 - 2.0 * t);
            const double w = settings.outlineThin + (settings.outlineThick - settings.outlineThin) * lit;
            contourWidth[p] = float(s * w * (1.0 + 0.15 * wobble(double(x) / s, double(y) / s)));
        }
    inkBand(
        boundary, figure, bigWidth, bigHeight, false,
        [&](std::int32_t f) { return double(contourWidth[std::size_t(f)]); }, scratch, ink);

    // Inner lines: centred on their pixels, tapered by the same wobble.
    std::vector<std::uint8_t> lines = innerLines;
    for (std::size_t p = 0; p < lines.size(); ++p)
        lines[p] = lines[p] && figure[p] && !boundary[p];
    dropSpecks(lines, bigWidth, bigHeight, settings.minInnerPixels);
    inkBand(
        lines, figure, bigWidth, bigHeight, true,
        [&](std::int32_t f) {
            const double x = double(f % bigWidth) / s;
            const double y = double(f / bigWidth) / s;
            const double t = 0.5 * (1.0 + wobble(1.7 * x, 1.7 * y));
            return s * (settings.innerThin + (settings.innerThick - settings.innerThin) * t);
        },
        scratch, ink);

    // Down to the sheet's size: the block means are the anti-aliased coverages.
    celform::algo::DrawingImage image;
    image.width = width;
    image.height = height;
    image.channels = 4;
    image.pixels.assign(std::size_t(width) * std::size_t(height) * 4, 0);
    const double block = double(s * s);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            int covered = 0;
            int inked = 0;
            for (int dy = 0; dy < s; ++dy)
                for (int dx = 0; dx < s; ++dx) {
                    const std::size_t p = std::size_t(y * s + dy) * std::size_t(bigWidth) + std::size_t(x * s + dx);
                    covered += figure[p];
                    inked += ink[p];
                }
            std::uint8_t* out = image.pixels.data() + (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4;
            const double alpha = covered / block;
            const double darkness = covered > 0 ? double(inked) / double(covered) : 0.0;
            const auto grey = std::uint8_t(std::lround(255.0 - (255.0 - 16.0) * darkness));
            out[0] = grey;
            out[1] = grey;
            out[2] = grey;
            out[3] = std::uint8_t(std::lround(255.0 * alpha));
        }
    return image;
}

} // namespace sheet
