// The exaggeration field and its inverse (sheet_warp.h).
#include "sheet_warp.h"

#include <algorithm>
#include <cmath>

namespace sheet {

namespace {

double gaussian(const Eigen::Vector2d& offset, double sigma)
{
    return std::exp(-offset.squaredNorm() / (2.0 * sigma * sigma));
}

Eigen::Vector2d trunkDisplacement(const TrunkField& trunk, const Eigen::Vector2d& q)
{
    if (trunk.centreline.empty())
        return Eigen::Vector2d::Zero();
    Eigen::Vector2d weighted = Eigen::Vector2d::Zero();
    double total = 0.0;
    double outside = 1.0;
    for (const Eigen::Vector2d& c : trunk.centreline) {
        const double g = gaussian(q - c, trunk.sigma);
        weighted += g * c;
        total += g;
        outside *= 1.0 - g;
    }
    if (total < 1e-300)
        return Eigen::Vector2d::Zero();
    const Eigen::Vector2d nearest = weighted / total;
    return trunk.stretch * (1.0 - outside) * (nearest - trunk.centreline.back());
}

} // namespace

Eigen::Vector2d Exaggeration::displacement(const Eigen::Vector2d& q) const
{
    Eigen::Vector2d d = Eigen::Vector2d::Zero();
    for (const EarField& ear : ears)
        d += ear.gain * gaussian(q - ear.centre, ear.sigma) * (q - ear.centre);
    for (const TrunkField& trunk : trunks)
        d += trunkDisplacement(trunk, q);
    return d;
}

Eigen::Vector2d Exaggeration::inverse(const Eigen::Vector2d& p) const
{
    Eigen::Vector2d q = p;
    for (int i = 0; i < 30; ++i) {
        const Eigen::Vector2d next = p - displacement(q);
        const bool settled = (next - q).squaredNorm() < 1e-8;
        q = next;
        if (settled)
            break;
    }
    return q;
}

InverseMap::InverseMap(const Exaggeration& field, int width, int height, double scale, int step)
    : width_(width)
    , height_(height)
    , step_(step)
    , gridWidth_(width / step + 2)
    , gridHeight_(height / step + 2)
    , grid_(std::size_t(gridWidth_) * std::size_t(gridHeight_))
{
    for (int gy = 0; gy < gridHeight_; ++gy)
        for (int gx = 0; gx < gridWidth_; ++gx) {
            const Eigen::Vector2d p((gx * step + 0.5) / scale, (gy * step + 0.5) / scale);
            grid_[std::size_t(gy) * std::size_t(gridWidth_) + std::size_t(gx)] = field.inverse(p) * scale;
        }
}

Eigen::Vector2d InverseMap::at(int x, int y) const
{
    const int gx = std::min(x / step_, gridWidth_ - 2);
    const int gy = std::min(y / step_, gridHeight_ - 2);
    const double fx = double(x - gx * step_) / step_;
    const double fy = double(y - gy * step_) / step_;
    const auto g = [&](int ix, int iy) { return grid_[std::size_t(iy) * std::size_t(gridWidth_) + std::size_t(ix)]; };
    return (1 - fy) * ((1 - fx) * g(gx, gy) + fx * g(gx + 1, gy))
        + fy * ((1 - fx) * g(gx, gy + 1) + fx * g(gx + 1, gy + 1));
}

double minJacobian(const Exaggeration& field, int width, int height, int step)
{
    double lowest = 1e300;
    const double h = 0.5;
    for (int y = 0; y < height; y += step)
        for (int x = 0; x < width; x += step) {
            const Eigen::Vector2d q(x + 0.5, y + 0.5);
            const Eigen::Vector2d dx
                = (field.displacement(q + Eigen::Vector2d(h, 0)) - field.displacement(q - Eigen::Vector2d(h, 0)))
                / (2 * h);
            const Eigen::Vector2d dy
                = (field.displacement(q + Eigen::Vector2d(0, h)) - field.displacement(q - Eigen::Vector2d(0, h)))
                / (2 * h);
            lowest = std::min(lowest, (1.0 + dx.x()) * (1.0 + dy.y()) - dx.y() * dy.x());
        }
    return lowest;
}

} // namespace sheet
