#include "celform/algorithms/symmetry.h"

#include "celform/algorithms/brush.h"

#include <algorithm>
#include <cmath>

namespace celform::algo {

Eigen::Vector3d reflect(const AxisPlane& plane, const Eigen::Vector3d& p)
{
    Eigen::Vector3d q = p;
    q[plane.axis] = 2.0 * plane.offset - p[plane.axis];
    return q;
}

AxisPlane centrePlane(const Positions& vertices, int axis)
{
    const Eigen::AlignedBox3d box = boundingBox(vertices);
    const double centre = box.isEmpty() ? 0.0 : box.center()[axis];
    return {axis, std::isfinite(centre) ? centre : 0.0};
}

SymmetryEstimate detectSymmetry(const Positions& vertices, double maxRelativeError, int sampleCount)
{
    SymmetryEstimate estimate;
    const Eigen::Index n = vertices.rows();
    const double diagonal = boundingBox(vertices).diagonal().norm();
    if (n == 0 || !(diagonal > 0.0) || !std::isfinite(diagonal))
        return estimate;
    const VertexGrid grid(vertices);
    const double cap = 0.1 * diagonal;
    const Eigen::Index step = std::max<Eigen::Index>(1, n / std::max(1, sampleCount));
    double best = maxRelativeError;
    std::vector<double> distances;
    distances.reserve(std::size_t(std::min<Eigen::Index>(n, sampleCount + 1)));
    for (int axis = 0; axis < 3; ++axis) {
        const AxisPlane plane = centrePlane(vertices, axis);
        distances.clear();
        for (Eigen::Index i = 0; i < n; i += step) {
            const Eigen::Vector3d p = vertices.row(i).transpose().cast<double>();
            if (!p.allFinite())
                continue;
            const Eigen::Vector3d q = reflect(plane, p);
            const std::int64_t j = grid.nearest(q, cap);
            distances.push_back(j < 0 ? cap : (vertices.row(j).transpose().cast<double>() - q).norm());
        }
        if (distances.empty())
            continue;
        // The median, not the mean: a posed limb or a curled trunk is far from its mirror image
        // while the rest of the body mirrors well.
        const auto middle = distances.begin() + std::ptrdiff_t(distances.size() / 2);
        std::nth_element(distances.begin(), middle, distances.end());
        estimate.error[std::size_t(axis)] = *middle / diagonal;
        if (estimate.error[std::size_t(axis)] <= best) {
            best = estimate.error[std::size_t(axis)];
            estimate.axis = axis;
        }
    }
    return estimate;
}

std::vector<std::int32_t> mirrorMap(const Positions& base, const AxisPlane& plane, double tolerance)
{
    const VertexGrid grid(base);
    std::vector<std::int32_t> map(std::size_t(base.rows()), -1);
    for (Eigen::Index i = 0; i < base.rows(); ++i) {
        const Eigen::Vector3d p = base.row(i).transpose().cast<double>();
        if (!p.allFinite())
            continue;
        const Eigen::Vector3d mirrored = reflect(plane, p);
        const std::int64_t j = grid.nearest(mirrored, tolerance);
        if (j < 0)
            continue;
        // A vertex on the plane is its own mirror even when a coincident duplicate has a lower index.
        const double self = (p - mirrored).norm();
        const double other = (base.row(j).transpose().cast<double>() - mirrored).norm();
        map[std::size_t(i)] = self <= other ? std::int32_t(i) : std::int32_t(j);
    }
    return map;
}

} // namespace celform::algo
