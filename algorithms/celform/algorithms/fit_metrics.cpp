// Silhouette masks, chamfer distances and IoU of a model against a drawing (fit_metrics.h).
#include "celform/algorithms/fit_metrics.h"

#include "celform/algorithms/distance_transform.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace celform::algo {

double RobustKernel::rho(double r) const
{
    const double a = std::abs(r), c = scale;
    switch (loss) {
    case RobustLoss::None:
        break;
    case RobustLoss::Huber:
        return a <= c ? 0.5 * a * a : c * (a - 0.5 * c);
    case RobustLoss::Tukey: {
        if (a >= c)
            return c * c / 6.0;
        const double u = 1.0 - (a / c) * (a / c);
        return c * c / 6.0 * (1.0 - u * u * u);
    }
    }
    return 0.5 * a * a;
}

double RobustKernel::weight(double r) const
{
    const double a = std::abs(r), c = scale;
    switch (loss) {
    case RobustLoss::None:
        break;
    case RobustLoss::Huber:
        return a <= c ? 1.0 : c / a;
    case RobustLoss::Tukey: {
        if (a >= c)
            return 0.0;
        const double u = 1.0 - (a / c) * (a / c);
        return u * u;
    }
    }
    return 1.0;
}

Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> projectVertices(
    const Positions& shape, const RasterCamera& camera)
{
    const ProjectionFrame frame(camera);
    Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> out(shape.rows(), 3);
    for (Eigen::Index v = 0; v < shape.rows(); ++v)
        out.row(v) = frame.project(shape.row(v).transpose().cast<double>()).transpose();
    return out;
}

void coverageMask(const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>& projected, const Faces& faces,
    int width, int height, std::vector<std::uint8_t>& mask)
{
    mask.assign(std::size_t(std::max(width, 0)) * std::size_t(std::max(height, 0)), 0);
    if (width <= 0 || height <= 0)
        return;
    // Scan conversion by spans: at each pixel-centre row the triangle covers one interval of x,
    // bounded by the crossings of its edges. A silhouette is the union of all triangles, so no
    // depth test and no fill rule: a centre exactly on an edge is covered.
    for (Eigen::Index f = 0; f < faces.rows(); ++f) {
        Eigen::Vector3d p[3];
        bool usable = true;
        for (int k = 0; k < 3; ++k) {
            const std::int32_t v = faces(f, k);
            if (v < 0 || v >= projected.rows()) {
                usable = false;
                break;
            }
            p[k] = projected.row(v).transpose();
            usable = usable && p[k].allFinite() && p[k].z() > 0.0;
        }
        if (!usable)
            continue;
        const double minY = std::min({p[0].y(), p[1].y(), p[2].y()});
        const double maxY = std::max({p[0].y(), p[1].y(), p[2].y()});
        const double minX = std::min({p[0].x(), p[1].x(), p[2].x()});
        const double maxX = std::max({p[0].x(), p[1].x(), p[2].x()});
        const int j0 = std::max(0, int(std::ceil(minY - 0.5)));
        const int j1 = std::min(height - 1, int(std::floor(maxY - 0.5)));
        if (j0 > j1 || maxX < 0.5 - 1.0 || minX > width + 0.5)
            continue;
        for (int j = j0; j <= j1; ++j) {
            const double y = j + 0.5;
            double lo = std::numeric_limits<double>::infinity(), hi = -lo;
            for (int k = 0; k < 3; ++k) {
                const Eigen::Vector3d& a = p[k];
                const Eigen::Vector3d& b = p[(k + 1) % 3];
                if ((y < a.y() && y < b.y()) || (y > a.y() && y > b.y()))
                    continue;
                if (a.y() == b.y()) {
                    lo = std::min({lo, a.x(), b.x()});
                    hi = std::max({hi, a.x(), b.x()});
                } else {
                    const double x = a.x() + (y - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
                    lo = std::min(lo, x);
                    hi = std::max(hi, x);
                }
            }
            if (!(lo <= hi))
                continue;
            const int i0 = std::max(0, int(std::ceil(lo - 0.5)));
            const int i1 = std::min(width - 1, int(std::floor(hi - 0.5)));
            if (i0 <= i1)
                std::fill_n(mask.begin() + std::ptrdiff_t(std::size_t(j) * std::size_t(width) + std::size_t(i0)),
                    i1 - i0 + 1, std::uint8_t(1));
        }
    }
}

void silhouetteMask(
    const Positions& shape, const Faces& faces, const RasterCamera& camera, std::vector<std::uint8_t>& mask)
{
    coverageMask(projectVertices(shape, camera), faces, camera.width, camera.height, mask);
}

void maskBoundary(const std::uint8_t* mask, int width, int height, std::vector<std::uint8_t>& boundary)
{
    boundary.assign(std::size_t(width) * std::size_t(height), 0);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(width) + std::size_t(x);
            if (!mask[i])
                continue;
            const bool edge = x == 0 || y == 0 || x + 1 == width || y + 1 == height || !mask[i - 1] || !mask[i + 1]
                || !mask[i - std::size_t(width)] || !mask[i + std::size_t(width)];
            boundary[i] = edge ? 1 : 0;
        }
}

void signedDistanceField(
    const std::uint8_t* mask, int width, int height, std::vector<float>& field, FitScratch* scratchIn)
{
    const std::size_t n = std::size_t(std::max(width, 0)) * std::size_t(std::max(height, 0));
    field.resize(n);
    if (n == 0)
        return;
    FitScratch local;
    FitScratch& s = scratchIn ? *scratchIn : local;
    std::vector<float>& toInside = s.inside;
    std::vector<float>& toOutside = s.outside;
    std::vector<std::uint8_t>& outside = s.bytes;
    toInside.resize(n);
    toOutside.resize(n);
    outside.resize(n);
    for (std::size_t i = 0; i < n; ++i)
        outside[i] = mask[i] ? 0 : 1;
    distanceTransform(mask, width, height, toInside.data(), s.transform);
    distanceTransform(outside.data(), width, height, toOutside.data(), s.transform);
    const float far = float(width + height);
    for (std::size_t i = 0; i < n; ++i) {
        const float d = mask[i] ? toOutside[i] : toInside[i];
        const float v = (std::isfinite(d) ? d : far) - 0.5f;
        field[i] = mask[i] ? -v : v;
    }
}

double sampleBilinear(
    const std::vector<float>& field, int width, int height, double x, double y, Eigen::Vector2d* gradient)
{
    const double fx = std::clamp(x - 0.5, 0.0, double(width - 1));
    const double fy = std::clamp(y - 0.5, 0.0, double(height - 1));
    const int x0 = std::min(int(fx), std::max(width - 2, 0));
    const int y0 = std::min(int(fy), std::max(height - 2, 0));
    const int x1 = std::min(x0 + 1, width - 1), y1 = std::min(y0 + 1, height - 1);
    const double tx = fx - x0, ty = fy - y0;
    const std::size_t w = std::size_t(width);
    const double f00 = field[std::size_t(y0) * w + std::size_t(x0)], f10 = field[std::size_t(y0) * w + std::size_t(x1)];
    const double f01 = field[std::size_t(y1) * w + std::size_t(x0)], f11 = field[std::size_t(y1) * w + std::size_t(x1)];
    if (gradient)
        *gradient = {(1 - ty) * (f10 - f00) + ty * (f11 - f01), (1 - tx) * (f01 - f00) + tx * (f11 - f10)};
    return (1 - ty) * ((1 - tx) * f00 + tx * f10) + ty * ((1 - tx) * f01 + tx * f11);
}

FitMetrics compareMasks(const std::uint8_t* silhouette, const std::uint8_t* outline, int width, int height,
    const RobustKernel& kernel, FitScratch* scratchIn)
{
    FitMetrics m;
    const std::size_t n = std::size_t(std::max(width, 0)) * std::size_t(std::max(height, 0));
    std::size_t both = 0, either = 0;
    for (std::size_t i = 0; i < n; ++i) {
        both += (silhouette[i] && outline[i]) ? 1 : 0;
        either += (silhouette[i] || outline[i]) ? 1 : 0;
    }
    m.silhouetteToOutlinePx = m.outlineToSilhouettePx = m.chamferPx = std::numeric_limits<double>::infinity();
    m.robustCost = std::numeric_limits<double>::infinity();
    if (n == 0)
        return m;
    m.iou = either > 0 ? double(both) / double(either) : 0.0;
    FitScratch local;
    FitScratch& s = scratchIn ? *scratchIn : local;
    std::vector<std::uint8_t>& a = s.bytes;
    std::vector<std::uint8_t>& b = s.boundary;
    maskBoundary(silhouette, width, height, a);
    maskBoundary(outline, width, height, b);
    std::vector<float>& toA = s.inside;
    std::vector<float>& toB = s.outside;
    toA.resize(n);
    toB.resize(n);
    distanceTransform(a.data(), width, height, toA.data(), s.transform);
    distanceTransform(b.data(), width, height, toB.data(), s.transform);
    double sumA = 0.0, sumB = 0.0, robust = 0.0;
    std::size_t countA = 0, countB = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (a[i] && std::isfinite(toB[i])) {
            sumA += toB[i];
            robust += kernel.rho(toB[i]);
            ++countA;
        }
        if (b[i] && std::isfinite(toA[i])) {
            sumB += toA[i];
            robust += kernel.rho(toA[i]);
            ++countB;
        }
    }
    if (countA == 0 || countB == 0)
        return m;
    m.silhouetteToOutlinePx = sumA / double(countA);
    m.outlineToSilhouettePx = sumB / double(countB);
    m.chamferPx = 0.5 * (m.silhouetteToOutlinePx + m.outlineToSilhouettePx);
    m.robustCost = robust / double(countA + countB);
    m.valid = true;
    return m;
}

FitMetrics measureFit(const Positions& shape, const Faces& faces, const RasterCamera& camera, const Outline& outline,
    const RobustKernel& kernel, FitScratch* scratchIn)
{
    if (!outline.ok() || outline.mask.size() != std::size_t(outline.width) * std::size_t(outline.height))
        return {};
    RasterCamera c = camera;
    c.width = outline.width;
    c.height = outline.height;
    FitScratch local;
    FitScratch& s = scratchIn ? *scratchIn : local;
    silhouetteMask(shape, faces, c, s.mask);
    if (outline.holesFilled)
        fillMaskHoles(s.mask, c.width, c.height, s.reached, s.stack);
    return compareMasks(s.mask.data(), outline.mask.data(), outline.width, outline.height, kernel, &s);
}

std::vector<std::uint8_t> downsampleMask(
    const std::vector<std::uint8_t>& mask, int width, int height, int factor, int& outWidth, int& outHeight)
{
    factor = std::max(factor, 1);
    outWidth = (width + factor - 1) / factor;
    outHeight = (height + factor - 1) / factor;
    std::vector<std::uint8_t> out(std::size_t(outWidth) * std::size_t(outHeight), 0);
    for (int y = 0; y < outHeight; ++y)
        for (int x = 0; x < outWidth; ++x) {
            int set = 0, total = 0;
            for (int dy = 0; dy < factor; ++dy)
                for (int dx = 0; dx < factor; ++dx) {
                    const int sx = x * factor + dx, sy = y * factor + dy;
                    if (sx >= width || sy >= height)
                        continue;
                    ++total;
                    set += mask[std::size_t(sy) * std::size_t(width) + std::size_t(sx)] ? 1 : 0;
                }
            out[std::size_t(y) * std::size_t(outWidth) + std::size_t(x)] = 2 * set >= total && total > 0 ? 1 : 0;
        }
    return out;
}

} // namespace celform::algo
