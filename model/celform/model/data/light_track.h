// The key light and the shot's light over time (issue 26, "a light for the shot"): keyed lights
// interpolated over the sphere for directional lights (slerp) and along a spline for point lights.
#pragma once

#include <Eigen/Core>

#include <QString>

#include <vector>

namespace celform::model {

enum class LightType { Directional, Point };

/// The key light (DESIGN.md, "Look"), in model space.
struct Light {
    LightType type = LightType::Directional;
    /// Directional: unit vector from the model towards the light. Point: position in model space.
    Eigen::Vector3d vector{0.4, 0.6, 0.7};
    bool operator==(const Light& o) const { return type == o.type && vector == o.vector; }
    bool operator!=(const Light& o) const { return !(*this == o); }
};

/// A keyed light.
struct LightKey {
    int frame = 0;
    Light light;
    bool operator==(const LightKey& o) const { return frame == o.frame && light == o.light; }
};

/// Keyed lights, frames strictly increasing. Between two keys of directional lights the direction
/// turns along the great circle (slerp) at a constant rate; point lights follow a natural cubic
/// spline through the keys' positions (algo::splineWeights, as the camera path). Between keys of
/// different types the earlier key holds; outside the keys the end keys hold.
struct LightTrack {
    std::vector<LightKey> keys;

    [[nodiscard]] bool empty() const { return keys.empty(); }
    /// The light at a frame; fallback when the track has no keys.
    [[nodiscard]] Light at(double frame, const Light& fallback) const;
    /// Replaces or inserts the key at frame, keeping keys sorted.
    void setKey(int frame, const Light& light);
    [[nodiscard]] bool hasKey(int frame) const;
    bool operator==(const LightTrack& o) const { return keys == o.keys; }
    bool operator!=(const LightTrack& o) const { return !(*this == o); }
};

/// The first problem of a light, empty when valid: a finite vector, non-zero for a directional one.
[[nodiscard]] QString lightProblem(const Light& light);
/// The first problem of a track, empty when valid: frames strictly increasing and in range, every
/// light valid.
[[nodiscard]] QString lightTrackProblem(const LightTrack& track);

/// The angle in degrees between two directional lights' directions, or between two point lights'
/// positions as seen from centre (how far a light turns, for --max-turn).
[[nodiscard]] double lightTurnDegrees(const Light& a, const Light& b, const Eigen::Vector3d& centre);
/// b turned back towards a so that it is at most maxDegrees from a as seen from centre (slerp of
/// the direction; a point light's distance from centre interpolated alike). b itself when it is
/// within the limit or the types differ.
[[nodiscard]] Light limitLightTurn(const Light& a, const Light& b, const Eigen::Vector3d& centre, double maxDegrees);

} // namespace celform::model
