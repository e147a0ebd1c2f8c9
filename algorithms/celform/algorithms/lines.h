// Feature lines of the cartoon look (comic paper, "Outlining"; paper 3, section 4.2.2): edge
// adjacency built once per topology, silhouettes, creases, borders and material boundaries per
// frame, chained into strokes, then styled with the comic paper's hand-drawn look.
#pragma once

#include "celform/algorithms/mesh_topology.h"
#include "celform/algorithms/tri_mesh.h"

#include <cstdint>
#include <vector>

namespace celform::algo {

enum LineKind : std::uint8_t {
    kSilhouette = 1, ///< between a front- and a back-facing triangle
    kCrease = 2, ///< dihedral angle above the threshold
    kBorder = 4, ///< open edge
    kMaterialBoundary = 8, ///< between two materials
    kRidge = 16, ///< apparent ridge (paper 3, section 4.2; apparent_ridges.h), drawn as an inner line
};

struct LineSettings {
    bool silhouettes = true;
    bool creases = true;
    bool borders = true;
    bool materialBoundaries = true;
    float creaseAngleDegrees = 45.0f; ///< angle between the two face normals
    /// Hysteresis (as Canny's edge linking): an edge whose angle lies between this and
    /// creaseAngleDegrees is a crease when it is connected, through such edges, to a crease above
    /// creaseAngleDegrees, so a chain on a coarse surface does not break into dashes. At or above
    /// creaseAngleDegrees: no hysteresis.
    float creaseLowAngleDegrees = 35.0f;
    /// Apparent ridges (paper 3, section 4.2), off by default: they cost a curvature pass per shape.
    bool ridges = false;
    /// Scale-free ridge threshold: view-dependent curvature times the median edge length
    /// (ApparentRidgeOptions::threshold).
    float ridgeThreshold = 0.3f;
    /// Ridges joined into snakes, smoothed and short ones dropped (paper 3, figure 4.11: the
    /// default), or raw (figure 4.8: each face's segment as apparent_ridges gives it, only
    /// segments meeting at a shared mesh edge joined, nothing smoothed or dropped).
    bool ridgeSnakes = true;
    /// Paper 3, section 4.4: lower the ridge threshold where a first picture's depth error is high
    /// (ridge_depth_scale.h); 0 keeps one threshold everywhere. A strength of 1 halves the
    /// threshold where the error is the picture's root mean square.
    float ridgeDepthStrength = 0.f;
    bool operator==(const LineSettings& o) const
    {
        return silhouettes == o.silhouettes && creases == o.creases && borders == o.borders
            && materialBoundaries == o.materialBoundaries && creaseAngleDegrees == o.creaseAngleDegrees
            && creaseLowAngleDegrees == o.creaseLowAngleDegrees && ridges == o.ridges
            && ridgeThreshold == o.ridgeThreshold && ridgeSnakes == o.ridgeSnakes
            && ridgeDepthStrength == o.ridgeDepthStrength;
    }
};

/// A camera as the line extraction needs it: an eye point for perspective cameras (per-triangle
/// view vectors, paper 3, section 4.2.2) or a view direction for orthographic ones.
struct LineView {
    Eigen::Vector3f eye = Eigen::Vector3f::Zero();
    Eigen::Vector3f direction{0.f, 0.f, -1.f}; ///< orthographic: from the camera into the scene
    bool orthographic = false;
};

struct FeatureEdges {
    std::vector<std::int32_t> edges; ///< indices into EdgeTopology::edges
    std::vector<std::uint8_t> kinds; ///< LineKind bits per edge
};

/// Per frame: the feature edges of a shape seen from view. faceMaterials may be empty.
/// Hidden parts are not removed here: the renderer tests each line against its depth buffer.
/// Each face is classified once as front-facing (dot(normal, p - eye) < 0, or dot(normal,
/// direction) < 0 when orthographic), back-facing (>= 0: edge-on counts as back) or degenerate
/// (zero normal: no silhouette, no crease); a silhouette separates a front and a back face.
/// Non-manifold edges are reported as creases when settings.creases is set. out is cleared and
/// reused; per-face scratch is kept per thread, so steady-state frames do not allocate.
void extractFeatureEdges(const Positions& shape, const Faces& faces, const EdgeTopology& topology,
    const std::vector<std::int32_t>& faceMaterials, const LineView& view, const LineSettings& settings,
    FeatureEdges& out);

/// Feature edges joined into polylines through vertices where exactly two edges of the same
/// kind class (outline: silhouette or border; inner: crease or material) meet.
struct Stroke {
    std::vector<std::int32_t> vertices;
    std::uint8_t kinds = 0;
    bool closed = false;
};
std::vector<Stroke> chainStrokes(const EdgeTopology& topology, const FeatureEdges& features);

/// Line look (comic paper): colour, widths in pixels (outlines wider than inner lines) and the
/// hand-drawn look. Deterministic: the same inputs give the same lines, and jitter is anchored to
/// vertex indices so it stays coherent from frame to frame.
struct LineStyle {
    Eigen::Vector3f color{0.06f, 0.05f, 0.05f};
    float outlineWidth = 3.0f; ///< silhouettes and borders, pixels
    float innerWidth = 1.5f; ///< creases and material boundaries, pixels
    float jitter = 0.0f; ///< jagged offset amplitude, pixels
    float widthVariation = 0.0f; ///< relative, 0 = constant width
    float overshoot = 0.0f; ///< extension at stroke ends, pixels
    std::uint32_t seed = 1;
    // Image-space clean-up (stroke_refine.h), after projection. Defaults look hand-drawn.
    float joinGap = 2.0f; ///< open stroke ends at most this far apart (pixels) are joined
    int smoothing = 2; ///< Chaikin corner-cutting rounds (0 = the projected polyline)
    float minLength = 0.01f; ///< shorter strokes are dropped; a fraction of the image height
    float taper = 6.0f; ///< length (pixels) over which open strokes thin towards their ends, 0 = off
    /// Pencil+'s "reduction": the farthest line is this much thinner (fraction of its width)
    /// than the nearest, linearly in camera depth between them. 0 = off.
    float reduction = 0.4f;
    bool operator==(const LineStyle& o) const
    {
        return color == o.color && outlineWidth == o.outlineWidth && innerWidth == o.innerWidth && jitter == o.jitter
            && widthVariation == o.widthVariation && overshoot == o.overshoot && seed == o.seed && joinGap == o.joinGap
            && smoothing == o.smoothing && minLength == o.minLength && taper == o.taper && reduction == o.reduction;
    }
};

/// A styled stroke in image space: points in pixels (x right, y down), depth (the camera-space
/// distance along the view axis, for hidden-line tests) and width per point.
struct StyledStroke {
    std::vector<Eigen::Vector2f> points;
    std::vector<float> depths;
    std::vector<float> widths;
    std::uint8_t kinds = 0;
    bool closed = false; ///< the last point repeats the first
};

/// Extends both ends of an open stroke by overshoot pixels along its end tangents (comic paper).
void overshootEnds(StyledStroke& stroke, float overshoot);

/// Projects strokes with project(vertex position) -> (x, y, depth) and applies the style.
/// Points behind the camera (depth <= 0) split a stroke.
template <typename Project>
std::vector<StyledStroke> styleStrokes(
    const std::vector<Stroke>& strokes, const Positions& shape, const LineStyle& style, Project project);

/// Non-template core of styleStrokes: strokes already projected (xyz = pixel x, pixel y, depth).
/// noiseKeys, when given (one per projected point), anchors the hand-drawn noise of each point
/// instead of its index (ridge points lie on edges and are renumbered every frame).
std::vector<StyledStroke> styleProjectedStrokes(const std::vector<Stroke>& strokes,
    const std::vector<Eigen::Vector3f>& projected, const LineStyle& style,
    const std::vector<std::uint32_t>* noiseKeys = nullptr);

template <typename Project>
std::vector<StyledStroke> styleStrokes(
    const std::vector<Stroke>& strokes, const Positions& shape, const LineStyle& style, Project project)
{
    std::vector<Eigen::Vector3f> projected(std::size_t(shape.rows()));
    for (Eigen::Index v = 0; v < shape.rows(); ++v)
        projected[std::size_t(v)] = project(Eigen::Vector3f(shape.row(v)));
    return styleProjectedStrokes(strokes, projected, style);
}

} // namespace celform::algo
