// Synthetic model sheets with a known answer, for the tests and benchmarks of fitting a model to a
// drawing: a mesh pulled in the image plane by a known smooth displacement, its silhouette drawn
// from a known camera as black ink on white paper, and the outline extracted from that drawing.
#pragma once

#include "celform/algorithms/fit_camera.h"
#include "celform/algorithms/fit_metrics.h"
#include "celform/algorithms/outline.h"
#include "celform/algorithms/raster.h"
#include "celform/algorithms/tri_mesh.h"

#include <cmath>

namespace celform::test {

struct ModelSheet {
    algo::RasterCamera camera; ///< the known camera the drawing was made from
    algo::Positions pulled; ///< the mesh as drawn
    Eigen::Vector3d pullCentre = Eigen::Vector3d::Zero();
    double pullSigma = 0.0; ///< model units
    double modelSize = 0.0; ///< bounding-box diagonal
    algo::Outline outline;
};

/// A camera looking at the mesh's centroid from direction (unit, from the centroid to the eye), with
/// the model's bounding sphere filling about 70 % of the image height.
inline algo::RasterCamera sheetCamera(
    const algo::TriMesh& mesh, const Eigen::Vector3d& direction, int size, bool orthographic = false)
{
    const Eigen::Vector3d centre = algo::centroid(mesh.vertices);
    const double radius = 0.5 * algo::boundingBox(mesh.vertices).diagonal().norm();
    algo::RasterCamera c;
    c.width = c.height = size;
    c.fovYDegrees = 30.0;
    const double distance = radius / 0.7 / std::tan(15.0 * 3.14159265358979323846 / 180.0);
    c.eye = centre + distance * direction.normalized();
    c.target = centre;
    c.up = Eigen::Vector3d::UnitY();
    c.orthographic = orthographic;
    c.orthoHeight = 2.0 * radius / 0.7;
    return c;
}

/// The silhouette of shape through camera as a black-on-white grey drawing.
inline algo::DrawingImage silhouetteDrawing(
    const algo::Positions& shape, const algo::Faces& faces, const algo::RasterCamera& camera)
{
    std::vector<std::uint8_t> mask;
    algo::silhouetteMask(shape, faces, camera, mask);
    algo::DrawingImage image;
    image.width = camera.width;
    image.height = camera.height;
    image.channels = 1;
    image.pixels.resize(mask.size());
    for (std::size_t i = 0; i < mask.size(); ++i)
        image.pixels[i] = mask[i] ? 0 : 255;
    return image;
}

/// The sheet: the mesh pulled by amplitude * exp(-|p - c|^2 / (2 sigma^2)) along an image-plane
/// direction (right * 0.8 + up * 0.6), c the vertex farthest to the right of the image, sigma and
/// amplitude as fractions of the model size; amplitude 0 draws the mesh as it is.
inline ModelSheet makeModelSheet(const algo::TriMesh& mesh, const Eigen::Vector3d& direction, int size,
    double amplitude, double sigma = 0.12, bool orthographic = false)
{
    ModelSheet sheet;
    sheet.camera = sheetCamera(mesh, direction, size, orthographic);
    sheet.modelSize = algo::boundingBox(mesh.vertices).diagonal().norm();
    const Eigen::Vector3d right = sheet.camera.right(), up = sheet.camera.trueUp();
    Eigen::Index farthest = 0;
    for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v)
        if (mesh.vertices.row(v).cast<double>().dot(right) > mesh.vertices.row(farthest).cast<double>().dot(right))
            farthest = v;
    sheet.pullCentre = mesh.vertices.row(farthest).transpose().cast<double>();
    sheet.pullSigma = sigma * sheet.modelSize;
    const Eigen::Vector3d pull = amplitude * sheet.modelSize * (0.8 * right + 0.6 * up);
    sheet.pulled = mesh.vertices;
    for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
        const double d2 = (mesh.vertices.row(v).transpose().cast<double>() - sheet.pullCentre).squaredNorm();
        const double w = std::exp(-d2 / (2.0 * sheet.pullSigma * sheet.pullSigma));
        sheet.pulled.row(v) += (w * pull).transpose().cast<float>();
    }
    algo::OutlineSettings settings;
    settings.closingRadius = 0.0;
    sheet.outline = algo::extractOutline(silhouetteDrawing(sheet.pulled, mesh.faces, sheet.camera), settings);
    return sheet;
}

} // namespace celform::test
