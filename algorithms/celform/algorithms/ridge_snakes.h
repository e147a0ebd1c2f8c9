// Line clustering of apparent ridges into "snakes" (paper 3, section 4.2.1, listing 4.4): the
// per-face segments joined head to tail in screen space, smoothed once, short ones dropped as
// noise; then styled like every other line.
#pragma once

#include "celform/algorithms/apparent_ridges.h"
#include "celform/algorithms/curvature.h"
#include "celform/algorithms/lines.h"
#include "celform/algorithms/raster.h"

#include <cstdint>
#include <vector>

namespace celform::algo {

struct SnakeOptions {
    /// Free segment ends (snake heads and tails) closer than this on screen (pixels, in the camera the snakes are built
    /// for) are one snake vertex. Ends on a shared mesh edge coincide exactly; the tolerance bridges the small breaks
    /// where one face failed the maximum test. 2 px is about the width of an inner line with its anti-aliased rim (1.5
    /// px + 0.5 px): a gap narrower than that does not show in the picture, so bridging it changes which snakes are
    /// long enough to stay, not their look.
    float joinPixels = 2.f;
    /// Paper 3, section 4.2.1: "snakes with a length smaller than 10 vertices are removed".
    int minVertices = 10;
    bool smooth = true; ///< one Laplacian pass: interior vertices to the mean of their two neighbours

    /// Raw ridges (paper 3, figure 4.8): no joining across gaps, no smoothing, no length filter.
    static SnakeOptions raw()
    {
        SnakeOptions o;
        o.joinPixels = 0.f;
        o.minVertices = 2;
        o.smooth = false;
        return o;
    }
};

/// Snakes as 3D polylines: each stroke's vertices index points (kinds = kRidge); keys[i] anchors
/// the hand-drawn noise of point i to the mesh edge it came from.
struct RidgeSnakes {
    std::vector<Eigen::Vector3f> points;
    std::vector<std::uint32_t> keys;
    std::vector<Stroke> strokes;
    void clear()
    {
        points.clear();
        keys.clear();
        strokes.clear();
    }
};

/// Scratch of clusterSnakes, kept by the caller (no allocation once sizes have settled).
struct SnakeWorkspace {
    std::vector<std::int32_t> endpointNode, nodeNext, nodeStart, adjacency, chain;
    std::vector<Eigen::Vector3f> nodePoint;
    std::vector<std::uint32_t> nodeKey;
    std::vector<std::int32_t> edgeA, edgeB, parent, degree, componentSize;
    std::vector<Eigen::Vector2f> screen;
    std::vector<std::uint64_t> cellKeys;
    std::vector<std::int32_t> cellFirst, alias;
    std::vector<char> edgeUsed, joined;
};

/// Listing 4.4 in expected linear time. Segment ends on the same mesh edge are one snake vertex
/// (they are the same point); then every snake head or tail joins the nearest other free end
/// within options.joinPixels on screen (camera's pixels), found through a spatial hash of screen
/// cells instead of the listing's scan of every snake, which makes the pass linear. Chains of
/// vertices with two connections are the snakes; a chain that comes back to its start is closed
/// (and, as in the listing, takes nothing more); a vertex where three or more meet ends the snakes
/// there. Then one Laplacian pass and the length filter. Ends behind the camera are never joined.
/// Deterministic.
void clusterSnakes(const RidgeSegments& segments, const RasterCamera& camera, const SnakeOptions& options,
    SnakeWorkspace& workspace, RidgeSnakes& out);

/// What the ridges of one shape need whatever the view: its curvature and feature size
/// (computed once per shape and kept by the caller, trimesh2's need_curvatures()).
struct RidgeShapeData {
    Curvatures curvatures;
    float featureSize = 0.f;
};
void computeRidgeShapeData(const Positions& shape, const Faces& faces, RidgeShapeData& out);

/// Per-view scratch of extractRidgeSnakes.
struct RidgeScratch {
    ApparentRidgeWorkspace ridges;
    RidgeSegments segments;
    SnakeWorkspace snakes;
};

/// The whole per-view pipeline the renderer and the viewport share: apparent ridges from the line
/// camera's eye (the centre eye for stereo pairs), clustered into snakes in its pixels.
/// thresholdScale: optional per-vertex factor (paper 3, section 4.4), may be null.
/// snakeOptions: SnakeOptions::raw() keeps the ridges as extracted (figure 4.8).
void extractRidgeSnakes(const Positions& shape, const Faces& faces, const VertexFaces& around,
    const RidgeShapeData& data, const RasterCamera& lineCamera, float threshold, RidgeScratch& scratch,
    RidgeSnakes& out, const std::vector<float>* thresholdScale = nullptr,
    const SnakeOptions& snakeOptions = SnakeOptions());

/// The snakes projected with project(point) -> (x, y, depth) and given the line style (inner
/// width, jitter anchored to the points' keys).
template <typename Project>
std::vector<StyledStroke> styleSnakes(const RidgeSnakes& snakes, const LineStyle& style, Project project)
{
    std::vector<Eigen::Vector3f> projected(snakes.points.size());
    for (std::size_t i = 0; i < snakes.points.size(); ++i)
        projected[i] = project(snakes.points[i]);
    return styleProjectedStrokes(snakes.strokes, projected, style, &snakes.keys);
}

} // namespace celform::algo
