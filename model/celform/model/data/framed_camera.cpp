// A camera framing the base model (framed_camera.h).
#include "celform/model/data/framed_camera.h"

#include "celform/algorithms/tri_mesh.h"

#include <algorithm>
#include <cmath>

namespace celform::model {

Camera cameraFromView(const ProjectData& data, const Eigen::Vector3d& view, double aspect)
{
    Camera camera;
    const Eigen::Vector3d centre = algo::centroid(data.baseMesh->vertices);
    // The sphere around the centroid holding every vertex fits the narrower field of view.
    const double radius = std::max(
        std::sqrt(
            (data.baseMesh->vertices.cast<double>().rowwise() - centre.transpose()).rowwise().squaredNorm().maxCoeff()),
        1e-6);
    const double halfY = camera.fovYDegrees * M_PI / 360.0;
    const double halfMin = std::min(halfY, std::atan(std::tan(halfY) * aspect));
    const Eigen::Vector3d direction = view.normalized();
    camera.target = centre;
    camera.eye = centre + direction * (1.05 * radius / std::sin(halfMin));
    camera.up = std::abs(direction.y()) > 0.99 ? Eigen::Vector3d(0, 0, -1) : Eigen::Vector3d(0, 1, 0);
    return camera;
}

} // namespace celform::model
