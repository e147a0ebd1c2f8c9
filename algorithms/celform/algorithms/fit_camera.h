// Fit Camera to Drawing: the camera's rotation, position and field of view (orthographic: height)
// optimised so that the model's silhouette meets the drawing's outline. Paper 1, section 3.1.1
// aligns the base model with each drawing by hand and names non-linear alignment as future work;
// here the objective is the robust symmetric chamfer distance of DESIGN.md ("Drawings and
// cameras"), solved with Levenberg-Marquardt coarse to fine over an image pyramid from a few starts
// around the artist's rough alignment.
#pragma once

#include "celform/algorithms/fit_metrics.h"
#include "celform/algorithms/mesh_topology.h"
#include "celform/algorithms/outline.h"
#include "celform/algorithms/progress.h"
#include "celform/algorithms/raster.h"

#include <string>

namespace celform::algo {

struct FitCameraOptions {
    /// Fit the vertical field of view (orthographic: the height) as well as the pose.
    bool fitFieldOfView = true;
    /// Starts around the given camera: the camera itself, then orbits of +/- this many degrees in
    /// yaw and in pitch about the model (5 starts); 0 starts from the camera only.
    double startSpreadDegrees = 20.0;
    /// Long side in pixels of the coarsest pyramid level (every start is solved there).
    int coarsestSize = 128;
    /// Long side in pixels of the finest level the solve uses (the figures use the full drawing);
    /// the drawing's own size when it is smaller.
    int finestSize = 512;
    /// Levenberg-Marquardt iterations per level and start, at most.
    int iterationsPerLevel = 25;
    /// Residual samples per side (silhouette, outline) at most.
    int maxSamples = 1000;
    /// Starts kept after the coarsest level (the rest are dropped by their chamfer cost there).
    int keptStarts = 2;
    /// How far the fit may zoom: the field of view's tan(fov / 2) (orthographic: the height)
    /// stays within this factor of the start's either way. A dolly and a zoom nearly undo each
    /// other on a model much shallower than its distance, and a drawing the model cannot meet
    /// (another pose) would otherwise trade the artist's lens for a telephoto one.
    double maxZoomFactor = 1.5;
    /// The field of view stays within these bounds (degrees).
    static constexpr double kMinFieldOfViewDegrees = 2.0;
    static constexpr double kMaxFieldOfViewDegrees = 120.0;
    /// Robust loss of the residuals on the coarse and middle levels (and of the reported robust
    /// cost); its scale is in full-resolution pixels (at least 1.5 pixels of a coarse level).
    RobustKernel kernel{RobustLoss::Huber, 3.0};
    /// Loss of the refinement on the finest level: redescending, so outline parts the model does
    /// not have (a drawing's exaggeration) stop pulling the camera once it is close.
    RobustKernel refineKernel{RobustLoss::Tukey, 4.0};
};

struct FitCameraResult {
    bool ok = false;
    bool cancelled = false;
    std::string error; ///< English, when not ok and not cancelled
    RasterCamera camera; ///< the fitted camera (the start camera when not ok); target at the start's distance
    FitMetrics before; ///< the start camera against the outline, full resolution
    FitMetrics after;
    int iterations = 0; ///< Levenberg-Marquardt iterations over every start and level
};

/// Fits start (its width and height are replaced by the outline's) so that shape's silhouette meets
/// outline. topology: the edge adjacency of faces (TriMesh::edgeTopology()). The result keeps the
/// start camera when the fit does not lower the robust chamfer cost at full resolution.
/// Progress is reported per iteration; a cancel returns the start camera with cancelled set.
FitCameraResult fitCamera(const Positions& shape, const Faces& faces, const EdgeTopology& topology,
    const RasterCamera& start, const Outline& outline, const FitCameraOptions& options = {},
    Progress* progress = nullptr);

/// The camera orbited about pivot by yaw (about its true up) then pitch (about its right), in
/// degrees; target and up follow. Exposed for the starts and for tests.
RasterCamera orbitCamera(
    const RasterCamera& camera, const Eigen::Vector3d& pivot, double yawDegrees, double pitchDegrees);

/// The view direction of DESIGN.md: the unit vector from the model's centroid towards the eye.
Eigen::Vector3d viewDirection(const RasterCamera& camera, const Eigen::Vector3d& centroid);

} // namespace celform::algo
