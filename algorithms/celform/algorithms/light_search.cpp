// Compass search of the light (light_search.h).
#include "celform/algorithms/light_search.h"

#include <Eigen/Geometry>

#include <cmath>

namespace celform::algo {
namespace {

/// Two unit vectors perpendicular to l and to each other.
void tangentBasis(const Eigen::Vector3d& l, Eigen::Vector3d& u, Eigen::Vector3d& v)
{
    const Eigen::Vector3d helper = std::abs(l.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    u = l.cross(helper).normalized();
    v = l.cross(u).normalized();
}

/// The k-th poll around light (k < 4 for a direction, < 6 for a position).
LightPose polled(const LightPose& light, int k, double step, double scale)
{
    LightPose next = light;
    const double sign = (k % 2 == 0) ? 1.0 : -1.0;
    if (light.point) {
        next.vector[k / 2] += sign * step * scale;
        return next;
    }
    Eigen::Vector3d u, v;
    tangentBasis(light.vector, u, v);
    const Eigen::Vector3d axis = k < 2 ? v : u;
    next.vector = (Eigen::AngleAxisd(sign * step, axis) * light.vector).normalized();
    return next;
}

} // namespace

LightSearchResult searchLight(const LightPose& start, const std::function<double(const LightPose&)>& objective,
    const LightSearchSettings& settings, Progress* progress)
{
    LightSearchResult result;
    result.best = start;
    if (!start.point) {
        const double n = start.vector.norm();
        if (n > 1e-12)
            result.best.vector /= n;
    }
    const int budget = std::max(1, settings.maxEvaluations);
    int evaluations = 0;
    auto evaluate = [&](const LightPose& pose, double step) {
        const double value = objective(pose);
        ++evaluations;
        report(progress, evaluations, budget);
        result.visits.push_back({pose.vector, value, step, false});
        return value;
    };
    result.bestValue = result.startValue = evaluate(result.best, 0.0);
    result.visits.back().accepted = true;
    const int polls = start.point ? 6 : 4;
    double step = settings.initialStep;
    // The poll that last succeeded is tried first next time: a descent keeps its direction.
    int first = 0;
    while (step >= settings.minStep && evaluations < budget) {
        bool improved = false;
        for (int i = 0; i < polls && evaluations < budget; ++i) {
            const int k = (first + i) % polls;
            const LightPose candidate = polled(result.best, k, step, settings.scale);
            if (!candidate.vector.allFinite())
                continue;
            const double value = evaluate(candidate, step);
            if (cancelRequested(progress)) {
                result.cancelled = true;
                return result;
            }
            if (value < result.bestValue) {
                result.best = candidate;
                result.bestValue = value;
                result.visits.back().accepted = true;
                first = k;
                improved = true;
                break;
            }
        }
        if (!improved)
            step *= 0.5;
    }
    return result;
}

} // namespace celform::algo
