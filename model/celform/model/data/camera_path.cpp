// Camera path interpolation and the turntable generator.
#include "celform/model/data/camera_path.h"

#include "celform/algorithms/blend.h"
#include "celform/model/data/project_data.h"

#include <Eigen/Geometry>

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace celform::model {
namespace {

struct PathText {
    Q_DECLARE_TR_FUNCTIONS(CameraPath)
};

} // namespace

Camera CameraPath::at(double frame) const
{
    if (keys.empty())
        return {};
    if (keys.size() == 1 || frame <= keys.front().frame)
        return keys.front().camera;
    if (frame >= keys.back().frame)
        return keys.back().camera;
    // On a key: that key exactly (a turntable is keyed at every frame).
    const auto hit = std::lower_bound(
        keys.begin(), keys.end(), frame, [](const CameraKey& k, double f) { return double(k.frame) < f; });
    if (hit != keys.end() && double(hit->frame) == frame)
        return hit->camera;
    std::vector<double> knots;
    knots.reserve(keys.size());
    for (const CameraKey& k : keys)
        knots.push_back(double(k.frame));
    const std::vector<double> w = algo::splineWeights(knots, frame, false);
    Camera out = std::prev(hit)->camera;
    out.eye.setZero();
    out.target.setZero();
    out.up.setZero();
    out.fovYDegrees = 0.0;
    out.orthoHeight = 0.0;
    for (std::size_t i = 0; i < keys.size(); ++i) {
        if (w[i] == 0.0)
            continue;
        const Camera& c = keys[i].camera;
        out.eye += w[i] * c.eye;
        out.target += w[i] * c.target;
        out.up += w[i] * c.up;
        out.fovYDegrees += w[i] * c.fovYDegrees;
        out.orthoHeight += w[i] * c.orthoHeight;
    }
    // A spline may overshoot: keep the lens usable and the up vector a unit vector.
    out.fovYDegrees = std::clamp(out.fovYDegrees, 1.0, 170.0);
    out.orthoHeight = std::max(out.orthoHeight, 1e-6);
    if (out.up.norm() > 1e-12)
        out.up.normalize();
    if (!out.isValid())
        return std::prev(hit)->camera;
    return out;
}

void CameraPath::setKey(int frame, const Camera& camera)
{
    const auto it
        = std::lower_bound(keys.begin(), keys.end(), frame, [](const CameraKey& k, int f) { return k.frame < f; });
    if (it != keys.end() && it->frame == frame)
        it->camera = camera;
    else
        keys.insert(it, CameraKey{frame, camera});
}

bool CameraPath::hasKey(int frame) const
{
    return std::binary_search(keys.begin(), keys.end(), CameraKey{frame, {}},
        [](const CameraKey& a, const CameraKey& b) { return a.frame < b.frame; });
}

QString cameraPathProblem(const CameraPath& path)
{
    for (std::size_t i = 0; i < path.keys.size(); ++i) {
        const CameraKey& k = path.keys[i];
        if (std::abs(k.frame) > kMaxFrame)
            return PathText::tr("camera key %1 is at frame %2, beyond ±%3").arg(i).arg(k.frame).arg(kMaxFrame);
        if (i > 0 && k.frame <= path.keys[i - 1].frame)
            return PathText::tr("camera keys are not in increasing frame order at frame %1").arg(k.frame);
        if (!k.camera.isValid())
            return PathText::tr("the camera key at frame %1 is not a usable camera").arg(k.frame);
    }
    return {};
}

QString turntableProblem(const Turntable& t)
{
    if (t.frames < 2 || t.frames > kMaxFrame)
        return PathText::tr("a turntable needs 2 to %1 frames, not %2").arg(kMaxFrame).arg(t.frames);
    if (std::abs(t.startFrame) > kMaxFrame || std::abs(qint64(t.startFrame) + t.frames) > kMaxFrame)
        return PathText::tr("the turntable's frames leave the range ±%1").arg(kMaxFrame);
    if (!t.axis.allFinite() || t.axis.norm() < 1e-12)
        return PathText::tr("the turntable axis must be a finite, non-zero vector");
    if (!std::isfinite(t.elevationDegrees) || std::abs(t.elevationDegrees) >= 90.0)
        return PathText::tr("the elevation must lie strictly between -90 and 90 degrees");
    // Any angle is some turn of the circle, but past a few turns a typed value is a mistake, and
    // 1e308 degrees becomes NaN once converted to radians and added to the steps.
    if (!std::isfinite(t.startDegrees) || std::abs(t.startDegrees) > kMaxTurntableStartDegrees)
        return PathText::tr("the start angle must lie between -%1 and %1 degrees").arg(kMaxTurntableStartDegrees);
    return {};
}

CameraPath turntablePath(const Turntable& t, const Eigen::Vector3d& target, double distance, const Camera& lens)
{
    const Eigen::Vector3d axis = t.axis.normalized();
    // Angle 0 looks from the default view's side: the +Z direction made normal to the axis, or +X
    // when the axis is along Z.
    Eigen::Vector3d side = Eigen::Vector3d::UnitZ() - axis * axis.z();
    if (side.norm() < 1e-6)
        side = Eigen::Vector3d::UnitX() - axis * axis.x();
    side.normalize();
    const double elevation = t.elevationDegrees * M_PI / 180.0;
    CameraPath path;
    path.keys.reserve(std::size_t(t.frames));
    for (int i = 0; i < t.frames; ++i) {
        const double angle = (t.startDegrees + 360.0 * double(i) / double(t.frames)) * M_PI / 180.0;
        const Eigen::Vector3d around = Eigen::AngleAxisd(angle, axis) * side;
        const Eigen::Vector3d direction = std::cos(elevation) * around + std::sin(elevation) * axis;
        Camera c = lens;
        c.target = target;
        c.eye = target + distance * direction;
        c.up = axis;
        path.keys.push_back({t.startFrame + i, c});
    }
    return path;
}

} // namespace celform::model
