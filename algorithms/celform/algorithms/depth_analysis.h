// Where toon shading hides depth, and by how much (paper 3, chapter 4): the analysis G-buffer
// rendered from the centre eye (4.5.2), its segments of salient shape with their bright/dark
// ratios (4.1.3, 4.5.3), and the depth error of the picture (4.4, 4.4.1).
#pragma once

#include "celform/algorithms/distance_transform.h"
#include "celform/algorithms/image.h"
#include "celform/algorithms/raster.h"
#include "celform/algorithms/segments.h"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace celform::algo {

/// The thesis's ratio window presets (5.0.3): lenient 0.2-0.8, medium 0.35-0.65 (the default,
/// DESIGN.md), strict 0.5.
struct RatioWindow {
    float low = 0.35f;
    float high = 0.65f;
    [[nodiscard]] bool contains(float ratio) const { return ratio >= low && ratio <= high; }
};

struct DepthAnalysisSettings {
    /// Neighbouring pixels whose depths differ by this much or more are in different segments
    /// (model units; the thesis gives no value, the caller derives it from the model's size).
    float depthThreshold = 0.01f;
    int minSegmentPixels = kMinSegmentPixels;
    RatioWindow window;
    /// The toon threshold the bright/dark ratio is taken at: N.L + offset at or above it is bright.
    float toonThreshold = 0.5f;
    bool pointLight = false;
    Eigen::Vector3f light{0.4f, 0.6f, 0.7f}; ///< towards the light (directional) or its position (point)
    const std::vector<float>* shadingOffsets = nullptr; ///< per vertex (paper 3, eq. 4.3), may be null
    /// The artist's say (paper 3, 6.2; issue 26), per face of the faces given, null or empty for
    /// none: each face's importance in [0, 1] (SegmentStats::importance), and a segment override
    /// label per face (>= 0; negative: none) that applySegmentOverrides regroups the segments by.
    const std::vector<float>* faceImportance = nullptr;
    const std::vector<std::int32_t>* segmentOverrides = nullptr;
};

/// One segment of salient shape.
struct SegmentStats {
    std::int32_t pixels = 0;
    std::int32_t bright = 0; ///< pixels with N.L + offset at or above the toon threshold
    float ratio = 0.f; ///< bright / pixels
    bool inWindow = false;
    float meanCurvature = 0.f; ///< mean Gaussian curvature of its pixels (its sign is the segment's)
    /// Sum over the segment of the shading's derivative with respect to the light position
    /// (eq. 4.2): the direction moving the light brightens the segment fastest (the gradient method
    /// of light optimisation follows it).
    Eigen::Vector3d lightGradient = Eigen::Vector3d::Zero();
    Eigen::Vector2f centroid = Eigen::Vector2f::Zero(); ///< mean pixel position
    /// The mean importance of its faces (the faces faceSegmentVote gives it; without any, of its
    /// pixels' faces): the factor its weight in the light optimisation is multiplied by. 1 when
    /// no importance is painted.
    float importance = 1.f;
};

/// The analysis of one picture. Per-pixel vectors are width * height, row-major from the top-left.
struct DepthAnalysis {
    int width = 0;
    int height = 0;
    // The analysis G-buffer (4.5.2).
    std::vector<float> curvature; ///< Gaussian curvature interpolated from the vertices, 0 off the model
    std::vector<float> depth; ///< distance along the view axis, +infinity off the model
    std::vector<float> lambert; ///< N.L + shading offset (N facing the viewer), 0 off the model
    std::vector<Eigen::Vector3f> lightGradient; ///< eq. 4.2 per pixel, zero off the model
    /// A scale for curvature pictures that belongs to the shape, not to the view, so colours keep
    /// their meaning while orbiting; 0: none (pictures take one from their own pixels). Set by the
    /// caller (model::DepthAnalyser: the |K| below which 98% of the surface's area lies).
    float curvatureScale = 0.f;
    // Segments (4.1.3).
    SegmentLabels segments;
    std::vector<SegmentStats> stats; ///< per segment
    // Depth error (4.4).
    std::vector<std::uint8_t> feature; ///< 1 on model pixels whose colour differs from the left or right pixel
    std::vector<std::int32_t> nearestFeature; ///< index of the nearest feature pixel, -1 off the model or none
    std::vector<float> depthError; ///< perceived - actual depth; 0 on features and off the model
    std::int64_t modelPixels = 0;
    std::int64_t featurePixels = 0;
    double meanSquaredError = 0.0; ///< over model pixels, model units squared
    double maxAbsError = 0.0;
    DistanceTransformScratch scratch;
};

/// How many segments have their ratio inside the window.
[[nodiscard]] int segmentsInWindow(const std::vector<SegmentStats>& stats);

/// Equation 4.2 (listing 4.5): d(l.n/|l|)/dl = (-(l.n)/(l.l) l + n) / |l|, with l the vector from
/// the surface point to the light. Zero when l is zero.
Eigen::Vector3f shadingLightDerivative(const Eigen::Vector3f& l, const Eigen::Vector3f& n);

/// Fills out from a rendered picture and its G-buffer:
/// - gbuffer: the centre eye's G-buffer (faceId, depth, barycentric, position);
/// - normals: per pixel the shading normal (turned towards the viewer), as RenderPasses::normal;
/// - beauty: the picture whose colour changes are the depth cues (feature pixels compare its linear
///   float colours, channels differing by more than 1/4096 — a sixteenth of an 8-bit step — as
///   thesis 4.4's "any difference in RGB values"; nothing is quantised);
/// - faces and vertexCurvature: the mesh and its smoothed Gaussian curvature per vertex.
/// Off-model pixels are background: never features, no depth error, transparent to segments.
/// settings.segmentOverrides regroup the segments (applySegmentOverrides), settings.faceImportance
/// gives each segment its importance (segmentFaceMeans over the face vote). With no feature pixel at all, the depth
/// error is zero. Allocates only when sizes change.
void analyseDepth(const GBuffer& gbuffer, const std::vector<Eigen::Vector3f>& normals, const ImageRGBA& beauty,
    const Faces& faces, const std::vector<float>& vertexCurvature, const DepthAnalysisSettings& settings,
    DepthAnalysis& out);

/// The face vote (the one the automatic offsets and the stable segment numbers use, thesis 4.3):
/// per face of faceCount, the segment most of its pixels are in (ties: the lower number), or -1
/// when none of its pixels is in a segment. faceId: per pixel of labels, -1 off the model.
void faceSegmentVote(
    const SegmentLabels& labels, const std::int32_t* faceId, std::int32_t faceCount, std::vector<std::int32_t>& owner);

/// Per segment the mean of perFace over the faces the vote gives it; a segment given no face takes
/// the mean over its pixels' faces. Faces beyond perFace count as 1.
void segmentFaceMeans(const SegmentLabels& labels, const std::int32_t* faceId, const std::vector<std::int32_t>& owner,
    const std::vector<float>& perFace, std::vector<float>& out);

/// The segment brush's overrides (issue 26, "a segment brush"): every covered pixel whose face has
/// an override label (>= 0) leaves the segment the scan gave it for the one segment of all pixels
/// of that label, wherever they are; the other pixels keep theirs, but for the rest of a segment
/// that lost more than half its pixels so: it joins the override beside it (grown over its own
/// pixels, else the one that took most of it), so that a merge or a split leaves no sliver of the
/// segment on faces the vote gave a neighbour. Segments are then numbered again in the order of their first pixel, and
/// those under minPixels dropped as the scan drops them. faceId: per pixel, -1 off the model; overrides: per face
/// (faces beyond it have none).
void applySegmentOverrides(
    const std::int32_t* faceId, const std::vector<std::int32_t>& overrides, int minPixels, SegmentLabels& labels);

/// Only the depth error part of analyseDepth (features, nearest feature, error, MSE), from the
/// depths (+infinity off the model) and the picture; the other fields of out are left alone.
void computeDepthError(const std::vector<float>& depth, const ImageRGBA& beauty, DepthAnalysis& out);

} // namespace celform::algo
