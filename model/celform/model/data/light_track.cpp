// The shot's light over time (light_track.h).
#include "celform/model/data/light_track.h"

#include "celform/algorithms/blend.h"
#include "celform/model/data/project_data.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace celform::model {
namespace {

struct TrackText {
    Q_DECLARE_TR_FUNCTIONS(LightTrack)
};

constexpr double kPi = 3.14159265358979323846;

/// Spherical linear interpolation of unit vectors (Shoemake 1985), t in [0, 1]; the normalised
/// chord where they are (nearly) opposite or equal.
Eigen::Vector3d slerp(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double t)
{
    const double cosine = std::clamp(a.dot(b), -1.0, 1.0);
    const double angle = std::acos(cosine);
    const double s = std::sin(angle);
    if (s < 1e-9) {
        const Eigen::Vector3d chord = (1.0 - t) * a + t * b;
        return chord.norm() > 1e-12 ? Eigen::Vector3d(chord.normalized()) : a;
    }
    return (std::sin((1.0 - t) * angle) / s) * a + (std::sin(t * angle) / s) * b;
}

} // namespace

Light LightTrack::at(double frame, const Light& fallback) const
{
    if (keys.empty())
        return fallback;
    if (keys.size() == 1 || frame <= keys.front().frame)
        return keys.front().light;
    if (frame >= keys.back().frame)
        return keys.back().light;
    const auto hit = std::lower_bound(
        keys.begin(), keys.end(), frame, [](const LightKey& k, double f) { return double(k.frame) < f; });
    if (double(hit->frame) == frame)
        return hit->light;
    const LightKey& before = *std::prev(hit);
    const LightKey& after = *hit;
    if (before.light.type != after.light.type)
        return before.light;
    if (before.light.type == LightType::Directional) {
        const double t = (frame - before.frame) / double(after.frame - before.frame);
        Light out = before.light;
        out.vector = slerp(before.light.vector.normalized(), after.light.vector.normalized(), t);
        return out;
    }
    // Point lights: the natural spline through the run of point keys around the frame.
    auto first = std::prev(hit), last = hit;
    while (first != keys.begin() && std::prev(first)->light.type == LightType::Point)
        --first;
    while (std::next(last) != keys.end() && std::next(last)->light.type == LightType::Point)
        ++last;
    std::vector<double> knots;
    for (auto it = first; it != std::next(last); ++it)
        knots.push_back(double(it->frame));
    const std::vector<double> w = algo::splineWeights(knots, frame, false);
    Light out = before.light;
    out.vector.setZero();
    for (std::size_t i = 0; i < w.size(); ++i)
        out.vector += w[i] * (first + std::ptrdiff_t(i))->light.vector;
    return out;
}

void LightTrack::setKey(int frame, const Light& light)
{
    const auto it
        = std::lower_bound(keys.begin(), keys.end(), frame, [](const LightKey& k, int f) { return k.frame < f; });
    if (it != keys.end() && it->frame == frame)
        it->light = light;
    else
        keys.insert(it, LightKey{frame, light});
}

bool LightTrack::hasKey(int frame) const
{
    return std::any_of(keys.begin(), keys.end(), [frame](const LightKey& k) { return k.frame == frame; });
}

QString lightProblem(const Light& light)
{
    if (!light.vector.allFinite())
        return TrackText::tr("the light's vector is not finite");
    if (light.type == LightType::Directional && light.vector.norm() == 0.0)
        return TrackText::tr("a directional light needs a direction");
    return {};
}

QString lightTrackProblem(const LightTrack& track)
{
    for (std::size_t i = 0; i < track.keys.size(); ++i) {
        const LightKey& k = track.keys[i];
        if (std::abs(k.frame) > kMaxFrame)
            return TrackText::tr("light key frame %1 is out of range").arg(k.frame);
        if (i > 0 && k.frame <= track.keys[i - 1].frame)
            return TrackText::tr("light key frames are not strictly increasing (%1 after %2)")
                .arg(k.frame)
                .arg(track.keys[i - 1].frame);
        const QString problem = lightProblem(k.light);
        if (!problem.isEmpty())
            return TrackText::tr("light key at frame %1: %2").arg(k.frame).arg(problem);
    }
    return {};
}

namespace {

/// The direction a light lies in as seen from centre (unit; +Z when it is at the centre).
Eigen::Vector3d seenFrom(const Light& light, const Eigen::Vector3d& centre)
{
    const Eigen::Vector3d v = light.type == LightType::Point ? Eigen::Vector3d(light.vector - centre) : light.vector;
    return v.norm() > 1e-12 ? Eigen::Vector3d(v.normalized()) : Eigen::Vector3d(Eigen::Vector3d::UnitZ());
}

} // namespace

double lightTurnDegrees(const Light& a, const Light& b, const Eigen::Vector3d& centre)
{
    const double cosine = std::clamp(seenFrom(a, centre).dot(seenFrom(b, centre)), -1.0, 1.0);
    return std::acos(cosine) * 180.0 / kPi;
}

Light limitLightTurn(const Light& a, const Light& b, const Eigen::Vector3d& centre, double maxDegrees)
{
    const double turn = lightTurnDegrees(a, b, centre);
    if (a.type != b.type || !(turn > maxDegrees) || turn <= 0.0)
        return b;
    const double t = std::max(0.0, maxDegrees) / turn;
    const Eigen::Vector3d direction = slerp(seenFrom(a, centre), seenFrom(b, centre), t);
    Light out = b;
    if (b.type == LightType::Directional) {
        out.vector = direction;
    } else {
        const double ra = (a.vector - centre).norm(), rb = (b.vector - centre).norm();
        out.vector = centre + ((1.0 - t) * ra + t * rb) * direction;
    }
    return out;
}

} // namespace celform::model
