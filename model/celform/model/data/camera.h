// A camera as the document stores it: eye, target and up in model space, plus the projection.
#pragma once

#include <Eigen/Core>

namespace celform::model {

enum class Projection { Perspective, Orthographic };

struct Camera {
    Eigen::Vector3d eye{0.0, 0.0, 5.0};
    Eigen::Vector3d target{0.0, 0.0, 0.0};
    Eigen::Vector3d up{0.0, 1.0, 0.0};
    Projection projection = Projection::Perspective;
    double fovYDegrees = 30.0; ///< vertical field of view, perspective only
    double orthoHeight = 2.0; ///< height of the view in world units, orthographic only

    bool operator==(const Camera& o) const
    {
        return eye == o.eye && target == o.target && up == o.up && projection == o.projection
            && fovYDegrees == o.fovYDegrees && orthoHeight == o.orthoHeight;
    }
    bool operator!=(const Camera& o) const { return !(*this == o); }

    /// Unit vector from the eye towards the target.
    [[nodiscard]] Eigen::Vector3d forward() const { return (target - eye).normalized(); }
    /// Unit vector to the right of the image, orthogonal to forward.
    [[nodiscard]] Eigen::Vector3d right() const { return forward().cross(up).normalized(); }
    /// Unit up vector of the image, orthogonal to forward and right.
    [[nodiscard]] Eigen::Vector3d trueUp() const { return right().cross(forward()).normalized(); }
    /// Whether eye, target and up make a usable frame (finite, distinct, up not along forward).
    [[nodiscard]] bool isValid() const
    {
        if (!eye.allFinite() || !target.allFinite() || !up.allFinite())
            return false;
        const Eigen::Vector3d f = target - eye;
        return f.norm() > 1e-12 && f.normalized().cross(up).norm() > 1e-9
            && (projection == Projection::Perspective ? fovYDegrees > 0.0 && fovYDegrees < 180.0 : orthoHeight > 0.0);
    }
};

} // namespace celform::model
