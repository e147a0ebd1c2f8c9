// The drawing's outer outline (outline.h): ink, disc closing through the Meijster distance
// transform, hole filling, component selection and marching squares on an ink-coverage field.
#include "celform/algorithms/outline.h"

#include "celform/algorithms/distance_transform.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace celform::algo {

namespace {

/// Rec. 709 luma of 8-bit sRGB values (the usual grey of a drawing), 0..255.
double luma(double r, double g, double b)
{
    return 0.2126 * r + 0.7152 * g + 0.0722 * b;
}

/// Whether the alpha channel carries the drawing: some pixels are see-through and some are not.
bool hasRealAlpha(const DrawingImage& image)
{
    if (image.channels != 2 && image.channels != 4)
        return false;
    const std::size_t n = std::size_t(image.width) * std::size_t(image.height);
    const std::size_t a = std::size_t(image.channels) - 1;
    bool clear = false, solid = false;
    for (std::size_t i = 0; i < n && !(clear && solid); ++i) {
        const std::uint8_t v = image.pixels[i * std::size_t(image.channels) + a];
        clear |= v < 128;
        solid |= v >= 128;
    }
    return clear && solid;
}

/// Luminance 0..255 of every pixel, colour composited over white paper.
std::vector<double> luminance(const DrawingImage& image)
{
    const std::size_t n = std::size_t(image.width) * std::size_t(image.height);
    const std::size_t c = std::size_t(image.channels);
    std::vector<double> out(n);
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint8_t* p = image.pixels.data() + i * c;
        double y = 0.0, alpha = 1.0;
        switch (image.channels) {
        case 1:
            y = p[0];
            break;
        case 2:
            y = p[0];
            alpha = p[1] / 255.0;
            break;
        case 3:
            y = luma(p[0], p[1], p[2]);
            break;
        default:
            y = luma(p[0], p[1], p[2]);
            alpha = p[3] / 255.0;
            break;
        }
        out[i] = alpha * y + (1.0 - alpha) * 255.0;
    }
    return out;
}

/// 0 / 1 mask of pixels within radius of a set pixel (disc dilation through the distance
/// transform), or, with invert, of pixels farther than radius from an unset pixel (erosion).
std::vector<std::uint8_t> dilate(
    const std::vector<std::uint8_t>& mask, int w, int h, double radius, DistanceTransformScratch& scratch)
{
    std::vector<float> d(mask.size());
    distanceTransform(mask.data(), w, h, d.data(), scratch);
    std::vector<std::uint8_t> out(mask.size());
    const float r = float(radius) + 1e-4f;
    for (std::size_t i = 0; i < mask.size(); ++i)
        out[i] = d[i] <= r ? 1 : 0;
    return out;
}

std::vector<std::uint8_t> erode(
    const std::vector<std::uint8_t>& mask, int w, int h, double radius, DistanceTransformScratch& scratch)
{
    std::vector<std::uint8_t> outside(mask.size());
    for (std::size_t i = 0; i < mask.size(); ++i)
        outside[i] = mask[i] ? 0 : 1;
    std::vector<float> d(mask.size());
    distanceTransform(outside.data(), w, h, d.data(), scratch);
    std::vector<std::uint8_t> out(mask.size());
    const float r = float(radius) + 1e-4f;
    for (std::size_t i = 0; i < mask.size(); ++i)
        out[i] = (mask[i] && d[i] > r) ? 1 : 0;
    return out;
}

} // namespace

void fillMaskHoles(std::vector<std::uint8_t>& mask, int w, int h)
{
    std::vector<std::uint8_t> reached;
    std::vector<std::int32_t> stack;
    fillMaskHoles(mask, w, h, reached, stack);
}

void fillMaskHoles(
    std::vector<std::uint8_t>& mask, int w, int h, std::vector<std::uint8_t>& reached, std::vector<std::int32_t>& stack)
{
    // Background reached from the border through 4-connected background stays; the foreground is
    // 8-connected, so a diagonal gap in the ink does not leak.
    if (w <= 0 || h <= 0 || mask.size() != std::size_t(w) * std::size_t(h))
        return;
    // Span filling: a seed grows to its whole run of background along the row, and the rows above
    // and below are seeded once per run they touch (far fewer pushes than a pixel flood fill).
    reached.assign(mask.size(), 0);
    stack.clear();
    const std::size_t width = std::size_t(w);
    auto open = [&](int x, int y) {
        const std::size_t i = std::size_t(y) * width + std::size_t(x);
        return !mask[i] && !reached[i];
    };
    auto seed = [&](int x, int y) {
        if (open(x, y))
            stack.push_back(std::int32_t(std::size_t(y) * width + std::size_t(x)));
    };
    for (int x = 0; x < w; ++x) {
        seed(x, 0);
        seed(x, h - 1);
    }
    for (int y = 0; y < h; ++y) {
        seed(0, y);
        seed(w - 1, y);
    }
    while (!stack.empty()) {
        const std::int32_t i = stack.back();
        stack.pop_back();
        const int y = int(std::size_t(i) / width);
        int x = int(std::size_t(i) % width);
        if (!open(x, y))
            continue;
        int left = x, right = x;
        while (left > 0 && open(left - 1, y))
            --left;
        while (right + 1 < w && open(right + 1, y))
            ++right;
        std::uint8_t* row = reached.data() + std::size_t(y) * width;
        std::fill(row + left, row + right + 1, std::uint8_t(1));
        for (int ny : {y - 1, y + 1}) {
            if (ny < 0 || ny >= h)
                continue;
            bool inRun = false;
            for (x = left; x <= right; ++x) {
                const bool o = open(x, ny);
                if (o && !inRun)
                    stack.push_back(std::int32_t(std::size_t(ny) * width + std::size_t(x)));
                inRun = o;
            }
        }
    }
    for (std::size_t i = 0; i < mask.size(); ++i)
        mask[i] = reached[i] ? 0 : 1;
}

namespace {

/// 8-connected components of the mask: label per pixel (-1 outside) and the pixel count of each.
std::vector<std::int64_t> labelComponents(
    const std::vector<std::uint8_t>& mask, int w, int h, std::vector<std::int32_t>& label)
{
    label.assign(mask.size(), -1);
    std::vector<std::int64_t> sizes;
    std::vector<std::int32_t> stack;
    for (std::size_t start = 0; start < mask.size(); ++start) {
        if (!mask[start] || label[start] >= 0)
            continue;
        const std::int32_t id = std::int32_t(sizes.size());
        std::int64_t count = 0;
        label[start] = id;
        stack.push_back(std::int32_t(start));
        while (!stack.empty()) {
            const std::int32_t i = stack.back();
            stack.pop_back();
            ++count;
            const int x = i % w, y = i / w;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= w || ny >= h)
                        continue;
                    const std::size_t j = std::size_t(ny) * std::size_t(w) + std::size_t(nx);
                    if (mask[j] && label[j] < 0) {
                        label[j] = id;
                        stack.push_back(std::int32_t(j));
                    }
                }
        }
        sizes.push_back(count);
    }
    return sizes;
}

/// Marching squares at the 0.5 level of field (w x h, pixel centres at +0.5), the image padded with
/// zeros so every curve closes. Each cell's crossings are joined into segments oriented with the
/// inside on their left (in pixel coordinates), and the segments are linked through the grid edges
/// they share into closed loops.
std::vector<std::vector<Eigen::Vector2d>> marchingSquares(const std::vector<float>& field, int w, int h)
{
    auto value = [&](int x, int y) -> float {
        if (x < 0 || y < 0 || x >= w || y >= h)
            return 0.0f;
        return field[std::size_t(y) * std::size_t(w) + std::size_t(x)];
    };
    const std::int64_t stride = std::int64_t(w) + 2;
    // Grid point (x, y), x in [-1, w], y in [-1, h]; an edge key is 2 * point + (0 horizontal, 1 vertical).
    auto point = [&](int x, int y) { return (std::int64_t(y) + 1) * stride + (std::int64_t(x) + 1); };
    std::unordered_map<std::int64_t, std::int64_t> next;
    std::unordered_map<std::int64_t, Eigen::Vector2d> where;
    auto crossing = [&](int ax, int ay, int bx, int by) {
        const float fa = value(ax, ay), fb = value(bx, by);
        const double t = std::clamp((0.5 - double(fa)) / (double(fb) - double(fa)), 0.0, 1.0);
        return Eigen::Vector2d(ax + 0.5 + t * (bx - ax), ay + 0.5 + t * (by - ay));
    };
    for (int y = -1; y < h; ++y)
        for (int x = -1; x < w; ++x) {
            // Corners c0 (x, y), c1 (x+1, y), c2 (x+1, y+1), c3 (x, y+1); edge k joins c_k and c_k+1.
            const std::array<int, 4> cx = {x, x + 1, x + 1, x}, cy = {y, y, y + 1, y + 1};
            std::array<bool, 4> in;
            int inside = 0;
            for (int k = 0; k < 4; ++k) {
                in[std::size_t(k)] = value(cx[std::size_t(k)], cy[std::size_t(k)]) >= 0.5f;
                inside += in[std::size_t(k)];
            }
            if (inside == 0 || inside == 4)
                continue;
            const std::array<std::int64_t, 4> key
                = {2 * point(x, y), 2 * point(x + 1, y) + 1, 2 * point(x, y + 1), 2 * point(x, y) + 1};
            auto crossingOf = [&](int k) {
                const int a = k, b = (k + 1) % 4;
                return crossing(cx[std::size_t(a)], cy[std::size_t(a)], cx[std::size_t(b)], cy[std::size_t(b)]);
            };
            // Segments cut a lone corner off the cell: between the edges before and after it.
            std::array<int, 2> lone = {-1, -1};
            int loneCount = 0;
            if (inside == 2 && in[0] == in[2]) {
                double centre = 0.0;
                for (int k = 0; k < 4; ++k)
                    centre += value(cx[std::size_t(k)], cy[std::size_t(k)]);
                const bool centreIn = centre * 0.25 >= 0.5;
                // Centre inside joins the inside corners: the outside ones are cut off alone.
                for (int k = 0; k < 4; ++k)
                    if (in[std::size_t(k)] != centreIn)
                        lone[std::size_t(loneCount++)] = k;
            } else {
                const bool minority = inside == 1; // the lone corner is the one inside, or the one outside
                for (int k = 0; k < 4; ++k)
                    if (in[std::size_t(k)] == minority)
                        lone[std::size_t(loneCount++)] = k;
                if (loneCount != 1) {
                    // Two adjacent corners inside: one segment across the cell. Treat the pair as
                    // a lone side: the segment joins the two edges with one crossing each.
                    loneCount = 0;
                }
            }
            // Walking the corners in order (clockwise on screen), a segment runs from the edge
            // where the walk leaves the inside to the edge where it comes back in: the inside is
            // then on its left in pixel coordinates (positive polygonArea). Decided by the corners,
            // not by geometry, so crossings that land exactly on a corner orient correctly too.
            auto emit = [&](int ea, int eb) {
                const bool leavesA = in[std::size_t(ea)] && !in[std::size_t((ea + 1) % 4)];
                const int from = leavesA ? ea : eb, to = leavesA ? eb : ea;
                where[key[std::size_t(from)]] = crossingOf(from);
                where[key[std::size_t(to)]] = crossingOf(to);
                next[key[std::size_t(from)]] = key[std::size_t(to)];
            };
            if (loneCount > 0) {
                for (int s = 0; s < loneCount; ++s) {
                    const int k = lone[std::size_t(s)];
                    emit((k + 3) % 4, k); // the edges before and after the lone corner
                }
            } else {
                std::array<int, 2> crossed{};
                int count = 0;
                for (int k = 0; k < 4; ++k)
                    if (in[std::size_t(k)] != in[std::size_t((k + 1) % 4)])
                        crossed[std::size_t(count++)] = k;
                emit(crossed[0], crossed[1]);
            }
        }
    std::vector<std::vector<Eigen::Vector2d>> loops;
    while (!next.empty()) {
        const std::int64_t first = next.begin()->first;
        std::vector<Eigen::Vector2d> loop;
        std::int64_t k = first;
        for (;;) {
            const auto it = next.find(k);
            if (it == next.end())
                break;
            loop.push_back(where[k]);
            k = it->second;
            next.erase(it);
            if (k == first)
                break;
        }
        if (loop.size() >= 3)
            loops.push_back(std::move(loop));
    }
    return loops;
}

} // namespace

std::string outlineErrorMessage(OutlineError error)
{
    switch (error) {
    case OutlineError::None:
        return {};
    case OutlineError::EmptyImage:
        return "The drawing is empty.";
    case OutlineError::NothingFound:
        return "The drawing has no figure to outline: it is all background or all ink.";
    case OutlineError::NoClosedOutline:
        return "The drawing's lines do not close into an outline: raise the closing radius.";
    case OutlineError::TouchesBorder:
        return "The drawing's figure touches the image border: its outline is cut by the frame.";
    }
    return {};
}

int otsuThreshold(const std::vector<std::int64_t>& histogram)
{
    double total = 0.0, sum = 0.0;
    int levels = 0;
    for (std::size_t i = 0; i < histogram.size(); ++i) {
        total += double(histogram[i]);
        sum += double(i) * double(histogram[i]);
        levels += histogram[i] > 0;
    }
    if (levels < 2)
        return -1;
    // Levels between two populated bins all split the histogram the same way (black ink on
    // white paper ties every level from 1 to 255): the middle of the tied range is the threshold
    // an artist expects, not its first level.
    double below = 0.0, sumBelow = 0.0, best = -1.0;
    int bestT = -1, lastT = -1;
    for (std::size_t t = 1; t < histogram.size(); ++t) {
        below += double(histogram[t - 1]);
        sumBelow += double(t - 1) * double(histogram[t - 1]);
        const double above = total - below;
        if (below <= 0.0 || above <= 0.0)
            continue;
        const double m0 = sumBelow / below, m1 = (sum - sumBelow) / above;
        const double between = below * above * (m0 - m1) * (m0 - m1);
        if (between > best * (1.0 + 1e-12)) {
            best = between;
            bestT = lastT = int(t);
        } else if (between >= best * (1.0 - 1e-12)) {
            lastT = int(t);
        }
    }
    return bestT < 0 ? -1 : (bestT + lastT) / 2;
}

double polygonArea(const std::vector<Eigen::Vector2d>& polygon)
{
    double a = 0.0;
    for (std::size_t i = 0, n = polygon.size(); i < n; ++i) {
        const Eigen::Vector2d& p = polygon[i];
        const Eigen::Vector2d& q = polygon[(i + 1) % n];
        a += p.x() * q.y() - q.x() * p.y();
    }
    return 0.5 * a;
}

std::vector<Eigen::Vector2d> resampleClosed(const std::vector<Eigen::Vector2d>& polygon, double spacing)
{
    const std::size_t n = polygon.size();
    if (n < 2 || !(spacing > 0.0))
        return polygon;
    double length = 0.0;
    for (std::size_t i = 0; i < n; ++i)
        length += (polygon[(i + 1) % n] - polygon[i]).norm();
    const std::size_t count = std::max<std::size_t>(3, std::size_t(std::ceil(length / spacing)));
    const double step = length / double(count);
    std::vector<Eigen::Vector2d> out;
    out.reserve(count);
    double along = 0.0; // arc length at the start of segment i
    std::size_t i = 0;
    for (std::size_t k = 0; k < count; ++k) {
        const double s = double(k) * step;
        double segment = (polygon[(i + 1) % n] - polygon[i]).norm();
        while (along + segment < s && i + 1 < n) {
            along += segment;
            ++i;
            segment = (polygon[(i + 1) % n] - polygon[i]).norm();
        }
        const double t = segment > 0.0 ? std::clamp((s - along) / segment, 0.0, 1.0) : 0.0;
        out.push_back(polygon[i] + t * (polygon[(i + 1) % n] - polygon[i]));
    }
    return out;
}

Outline extractOutline(const DrawingImage& image, const OutlineSettings& settings)
{
    Outline result;
    const int w = image.width, h = image.height;
    const std::size_t n = std::size_t(std::max(w, 0)) * std::size_t(std::max(h, 0));
    if (w <= 0 || h <= 0 || image.channels < 1 || image.channels > 4
        || image.pixels.size() != n * std::size_t(image.channels)) {
        result.error = OutlineError::EmptyImage;
        return result;
    }
    result.width = w;
    result.height = h;

    // 1. Ink and its coverage in [0, 1] (for the sub-pixel contour): alpha, or the luminance
    // between the paper's and the ink's mean levels.
    std::vector<std::uint8_t> ink(n);
    std::vector<float> coverage(n);
    if (settings.useAlpha && hasRealAlpha(image)) {
        result.usedAlpha = true;
        const std::size_t c = std::size_t(image.channels);
        for (std::size_t i = 0; i < n; ++i) {
            const std::uint8_t a = image.pixels[i * c + c - 1];
            ink[i] = a >= 128 ? 1 : 0;
            coverage[i] = float(a) / 255.0f;
        }
    } else {
        const std::vector<double> y = luminance(image);
        std::vector<std::int64_t> histogram(256, 0);
        for (double v : y)
            ++histogram[std::size_t(std::clamp(int(std::lround(v)), 0, 255))];
        double t = settings.threshold * 255.0;
        if (settings.threshold < 0.0) {
            const int otsu = otsuThreshold(histogram);
            if (otsu < 0) {
                result.error = OutlineError::NothingFound;
                return result;
            }
            t = double(otsu) - 0.5; // class {< otsu} is ink
        }
        result.thresholdUsed = std::clamp(t / 255.0, 0.0, 1.0);
        double inkSum = 0.0, paperSum = 0.0, inkCount = 0.0, paperCount = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            ink[i] = y[i] < t ? 1 : 0;
            (ink[i] ? inkSum : paperSum) += y[i];
            (ink[i] ? inkCount : paperCount) += 1.0;
        }
        const double inkLevel = inkCount > 0 ? inkSum / inkCount : 0.0;
        const double paperLevel = paperCount > 0 ? paperSum / paperCount : 255.0;
        const double range = std::max(paperLevel - inkLevel, 1.0);
        for (std::size_t i = 0; i < n; ++i)
            coverage[i] = float(std::clamp((paperLevel - y[i]) / range, 0.0, 1.0));
    }
    std::size_t inkCount = 0;
    for (std::uint8_t v : ink)
        inkCount += v;
    if (inkCount == 0 || inkCount == n) {
        result.error = OutlineError::NothingFound;
        return result;
    }

    // 2. Disc closing (dilation, then erosion by the same radius) bridges the gaps of open line art.
    DistanceTransformScratch scratch;
    // 3. Holes filled: the figure enclosed by its outline. The holes are filled between the
    // dilation and the erosion: a disc closing alone never bridges the gap between two collinear
    // thin lines (a disc beside the gap touches neither end), but once the dilated ink encloses
    // the figure, filling it first leaves the erosion only the outer boundary to bring back.
    result.holesFilled = settings.fillHoles;
    std::vector<std::uint8_t> region = ink;
    if (settings.closingRadius > 0.0)
        region = dilate(ink, w, h, settings.closingRadius, scratch);
    if (settings.fillHoles)
        fillMaskHoles(region, w, h);
    if (settings.closingRadius > 0.0)
        region = erode(region, w, h, settings.closingRadius, scratch);

    // 4. Components: the largest, or every one of at least minComponentPixels.
    std::vector<std::int32_t> label;
    const std::vector<std::int64_t> sizes = labelComponents(region, w, h, label);
    if (sizes.empty()) {
        result.error = OutlineError::NoClosedOutline;
        return result;
    }
    const std::size_t largest = std::size_t(std::max_element(sizes.begin(), sizes.end()) - sizes.begin());
    std::vector<std::uint8_t> keepLabel(sizes.size(), 0);
    keepLabel[largest] = 1;
    if (settings.minComponentPixels > 0)
        for (std::size_t k = 0; k < sizes.size(); ++k)
            keepLabel[k] |= sizes[k] >= settings.minComponentPixels ? 1 : 0;
    std::vector<std::uint8_t> kept(n, 0);
    for (std::size_t i = 0; i < n; ++i)
        kept[i] = (label[i] >= 0 && keepLabel[std::size_t(label[i])]) ? 1 : 0;

    // 5. A figure, not line work: its largest inscribed disc is thicker than a line.
    {
        std::vector<std::uint8_t> outside(n);
        for (std::size_t i = 0; i < n; ++i)
            outside[i] = kept[i] ? 0 : 1;
        std::vector<float> d(n);
        distanceTransform(outside.data(), w, h, d.data(), scratch);
        float deepest = 0.0f;
        for (std::size_t i = 0; i < n; ++i)
            if (kept[i])
                deepest = std::max(deepest, std::isfinite(d[i]) ? d[i] : float(std::max(w, h)));
        const double minimum = settings.minThickness > 0.0
            ? settings.minThickness
            : std::max({4.0, settings.closingRadius + 2.0, 0.01 * std::min(w, h)});
        if (double(deepest) < minimum) {
            result.error = OutlineError::NoClosedOutline;
            return result;
        }
    }
    if (settings.rejectBorder) {
        bool touches = false;
        for (int x = 0; x < w && !touches; ++x)
            touches = kept[std::size_t(x)] || kept[std::size_t(h - 1) * std::size_t(w) + std::size_t(x)];
        for (int y = 0; y < h && !touches; ++y)
            touches
                = kept[std::size_t(y) * std::size_t(w)] || kept[std::size_t(y) * std::size_t(w) + std::size_t(w - 1)];
        if (touches) {
            result.error = OutlineError::TouchesBorder;
            return result;
        }
    }

    // 6. Sub-pixel contour: marching squares at 0.5 on the ink's coverage (the anti-aliased edge
    // is the box-filtered figure, whose half level interpolated between pixel centres lies within
    // a tenth of a pixel of the true edge), held at or above 0.5 in the kept region and below it
    // outside, so the curve follows the kept region exactly.
    std::vector<float> field(n);
    for (std::size_t i = 0; i < n; ++i)
        field[i] = kept[i] ? std::max(coverage[i], 0.5f) : std::min(coverage[i], 0.499f);
    result.contours = marchingSquares(field, w, h);
    std::sort(result.contours.begin(), result.contours.end(),
        [](const auto& a, const auto& b) { return std::abs(polygonArea(a)) > std::abs(polygonArea(b)); });
    if (result.contours.empty()) {
        result.error = OutlineError::NoClosedOutline;
        return result;
    }
    result.mask = std::move(kept);
    return result;
}

} // namespace celform::algo
