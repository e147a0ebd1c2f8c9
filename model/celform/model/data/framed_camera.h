// A camera that frames the whole base model from a view direction: the default render camera,
// the turntable's distance and `--view` on the command line all start from it.
#pragma once

#include "celform/model/data/camera.h"
#include "celform/model/data/project_data.h"

#include <Eigen/Core>

namespace celform::model {

/// The default camera's view direction when the project has no render camera.
inline Eigen::Vector3d defaultRenderView()
{
    return {0.35, 0.25, 1.0};
}

/// A perspective camera looking at the base model's centroid from view (any length), at the
/// distance where the sphere around the centroid holding every vertex fits the narrower of the
/// vertical and horizontal fields of view for an image of the given aspect ratio (width / height).
/// The project must have a base model.
Camera cameraFromView(const ProjectData& data, const Eigen::Vector3d& view, double aspect = 1.0);

} // namespace celform::model
