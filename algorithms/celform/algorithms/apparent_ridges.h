// Apparent ridges (Judd, Durand and Adelson, "Apparent Ridges for Line Drawing", SIGGRAPH 2007;
// paper 3, sections 3.4 and 4.2): per view, the maximum view-dependent curvature q1 and its
// derivative along its own screen direction at every vertex, then per face the line through the
// zero crossings of that derivative where q1 is a maximum above a threshold.
#pragma once

#include "celform/algorithms/curvature.h"
#include "celform/algorithms/lines.h"
#include "celform/algorithms/mesh_topology.h"
#include "celform/algorithms/mesh_types.h"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace celform::algo {

/// The length the ridge threshold is measured against: the median edge length of the mesh (each
/// face's three edges, so interior edges count twice, which does not move a median). 0 for a mesh
/// without edges. Per shape, next to the curvature.
float ridgeFeatureSize(const Positions& shape, const Faces& faces);

struct ApparentRidgeOptions {
    /// Scale-free threshold: a ridge point is kept where q1 * featureSize > threshold, i.e. where the
    /// surface, as seen, bends by more than `threshold` radians over one typical edge. Measuring q1
    /// against the mesh's own sampling (rtsc does the same, dividing its threshold by the squared
    /// feature size because its q1 is squared) makes the value independent of the model's units,
    /// and it is the scale at which discrete curvature noise lives: noise of a finely tessellated
    /// mesh is high in 1/length, and so is its threshold. 0.3 is close to rtsc's default (0.1 on
    /// q1 squared) and drew the clear folds of the armadillo without the scales of its skin.
    float threshold = 0.3f;
    float featureSize = 1.f; ///< ridgeFeatureSize of the shape
    /// Optional, #V: multiplies the threshold per vertex (paper 3, section 4.4: lower it where the
    /// depth error is high so that more lines give stereo correspondence). Null: 1 everywhere.
    const std::vector<float>* thresholdScale = nullptr;
    int threads = 2; ///< worker threads for the per-vertex and per-face passes (1 = caller only)
};

/// Ridge line segments in model space: segment i runs from points[2i] to points[2i+1]. keys[j]
/// names where point j lies (a mesh edge or a face centre), stable while the ridge stays there:
/// the hand-drawn jitter is anchored to it, so a line keeps its wiggle from frame to frame.
struct RidgeSegments {
    std::vector<Eigen::Vector3f> points;
    std::vector<std::uint32_t> keys;
    void clear()
    {
        points.clear();
        keys.clear();
    }
};

/// Per-view scratch kept by the caller: one call on a mesh of unchanged size allocates nothing
/// (the worker threads are started per call). After a call, q1 and t1 hold the view-dependent
/// curvature of every vertex (tests and overlays read them).
struct ApparentRidgeWorkspace {
    /// Per vertex: g = Dt1q1 * T1 (T1 the unit surface direction of t1, so g points where q1 grows
    /// and does not depend on t1's arbitrary sign), the excess q1 - threshold, |Dt1q1| and n.v.
    struct VertexRecord {
        float gx, gy, gz;
        float excess;
        float slope;
        float ndotv;
    };
    std::vector<VertexRecord> records;
    std::vector<float> q1;
    std::vector<Eigen::Vector3f> t1; ///< unit surface direction of q1 where dt1q1 is taken, else 0
    /// Derivative of q1 along t1 per unit of screen-plane distance; computed only at the corners
    /// of faces that can hold a ridge (see computeApparentRidges), 0 elsewhere.
    std::vector<float> dt1q1;
    std::vector<std::vector<std::uint8_t>> marks; ///< per face block: vertices needing dt1q1; last: flags
    std::vector<std::vector<std::int32_t>> candidates; ///< per face block: faces that may hold a ridge
    std::vector<RidgeSegments> perThread;
};

/// Fills out with the apparent ridges of shape (#V by 3) seen from view (an eye point, or an
/// orthographic direction: the centre eye for stereo pairs, paper 3, section 4.2). curvatures
/// are the shape's (computeCurvatures, cached by the caller: only this view-dependent part runs
/// per view); around is the mesh's vertex-face table. Faces whose three vertices face away are
/// skipped. Deterministic whatever the thread count: faces are split into ordered blocks.
void computeApparentRidges(const Positions& shape, const Faces& faces, const VertexFaces& around,
    const Curvatures& curvatures, const LineView& view, const ApparentRidgeOptions& options,
    ApparentRidgeWorkspace& workspace, RidgeSegments& out);

} // namespace celform::algo
