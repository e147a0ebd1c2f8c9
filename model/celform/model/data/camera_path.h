// The shot's camera over time (paper 1, figures 10-12: the camera moving around the
// view-dependent model): keyed render cameras interpolated smoothly, and the turntable generator.
#pragma once

#include "celform/model/data/camera.h"

#include <Eigen/Core>

#include <QString>

#include <vector>

namespace celform::model {

/// A keyed render camera.
struct CameraKey {
    int frame = 0;
    Camera camera;
    bool operator==(const CameraKey& o) const { return frame == o.frame && camera == o.camera; }
};

/// Keyed cameras, frames strictly increasing. Between keys each of eye, target, up and the field
/// of view (or orthographic height) follows a natural cubic spline through the keys
/// (algo::splineWeights, the spline the key deformations use over time); outside the keys the
/// end keys hold. The projection is the earlier key's.
struct CameraPath {
    std::vector<CameraKey> keys;

    [[nodiscard]] bool empty() const { return keys.empty(); }
    [[nodiscard]] Camera at(double frame) const;
    /// Replaces or inserts the key at frame, keeping keys sorted.
    void setKey(int frame, const Camera& camera);
    /// Whether frame holds a key.
    [[nodiscard]] bool hasKey(int frame) const;
    bool operator==(const CameraPath& o) const { return keys == o.keys; }
    bool operator!=(const CameraPath& o) const { return !(*this == o); }
};

/// The first problem of a path, empty when valid: frames strictly increasing, every camera valid.
[[nodiscard]] QString cameraPathProblem(const CameraPath& path);

/// A turntable: the camera goes once round the axis through the target in `frames` frames,
/// starting at frame `startFrame` and angle `startDegrees` (0 = the side the default view looks
/// from), raised `elevationDegrees` above the plane normal to the axis.
struct Turntable {
    int frames = 48; ///< one revolution; frame startFrame + frames would repeat the first
    Eigen::Vector3d axis{0.0, 1.0, 0.0};
    double elevationDegrees = 15.0;
    int startFrame = 0;
    double startDegrees = 0.0;
};

/// The largest start angle of a turntable, in degrees either way (ten turns).
constexpr double kMaxTurntableStartDegrees = 3600.0;

/// The first problem of turntable settings, empty when valid: frames in [2, kMaxFrame], start
/// frame in range, a finite non-zero axis, elevation strictly between -90 and 90 degrees.
[[nodiscard]] QString turntableProblem(const Turntable& turntable);

/// A path keyed at every frame of the revolution (so the turntable is exact on whole frames),
/// looking at target from distance, with the field of view and projection of lens.
[[nodiscard]] CameraPath turntablePath(
    const Turntable& turntable, const Eigen::Vector3d& target, double distance, const Camera& lens);

} // namespace celform::model
