// The display-free renderer (DESIGN.md, "Rendering"): a CPU G-buffer of the shape, the cartoon
// shading functions per pixel, feature lines on top, and the render passes compositors expect.
#pragma once

#include "celform/algorithms/highlights.h"
#include "celform/algorithms/image.h"
#include "celform/algorithms/lines.h"
#include "celform/algorithms/raster.h"
#include "celform/algorithms/ridge_snakes.h"
#include "celform/algorithms/shading.h"
#include "celform/algorithms/tri_mesh.h"

#include <functional>
#include <cstdint>
#include <vector>

namespace celform::algo {

enum class Style { Lambert, Toon, Gooch, Comic };

/// One stylized highlight layer resolved for a frame by the caller (model::renderShape): the
/// layer with its combinations' shapes, where it may appear, the tangent frames its operations
/// act along, and optionally the smoothed normals it is evaluated with (smoothPatchNormals).
struct RenderHighlight {
    HighlightLayer layer;
    std::vector<char> faceMask; ///< per face, non-zero where the layer may appear; empty: all faces
    Positions du; ///< #V by 3 per-vertex tangent frames (zero rows outside the patch)
    Positions dv; ///< #V by 3
    /// #V by 3 smoothed unit normals of the layer, zero rows outside its patch; empty: the surface's
    Positions normals;
};

/// Everything about the look the renderer needs, independent of the document.
/// Anti-aliasing of the per-pixel toon tone's boundaries (issue 25, "Shading without stair
/// steps"); the per-vertex table and per-face evaluations are left as the comic paper has them.
enum class ToneAntialiasing {
    Off, ///< hard boundaries, one intensity per tone
    Coverage, ///< toneCoverage from the screen-space derivative of N.L (as the viewport's fwidth)
    Supersample4, ///< the tone alone at 4 sub-pixel points (normal and position from pixel differences)
};

struct RenderLook {
    Style style = Style::Toon;
    std::vector<Style> materialStyles; ///< per material index; empty or short: style
    std::vector<Color> materialColors; ///< base colour per material; empty: defaultColor
    Color defaultColor{0.85f, 0.82f, 0.78f};
    Color background{0.93f, 0.93f, 0.91f};
    bool pointLight = false;
    Eigen::Vector3f light{0.4f, 0.6f, 0.7f}; ///< towards the light (directional) or its position (point)
    ToonRamp toon;
    ToonEvaluation toonEvaluation = ToonEvaluation::PerPixel;
    /// Coverage: as good as Supersample4 to the eye at a fraction of its cost (bench_render).
    ToneAntialiasing toneAntialiasing = ToneAntialiasing::Coverage;
    /// Whether renderFrame fills the data passes (tone, highlights, depth, normal, id). A file of
    /// the beauty alone needs none of them: false leaves them empty and spares a sequence about
    /// 57 bytes a pixel of filling and copying per frame (issue 29). The beauty, the lines and the
    /// strokes are the same either way.
    bool dataPasses = true;
    GoochParams gooch;
    std::vector<GoochParams> materialGooch; ///< per material index (the "auto" preset); empty: gooch
    HatchParams hatch;
    bool lines = true;
    LineSettings lineSettings;
    LineStyle lineStyle;
    const std::vector<float>* shadingOffsets = nullptr; ///< per vertex (paper 3, eq. 4.3), may be null
    /// Per vertex, a factor on the apparent-ridge threshold (paper 3, section 4.4; see
    /// ridge_depth_scale.h), may be null (1 everywhere).
    const std::vector<float>* ridgeThresholdScale = nullptr;
    /// Per vertex of the rendered shape, unit normals to shade with (a subdivided surface's limit
    /// normals, issue 25); null, or of another size: area-weighted normals of the shape's faces.
    const Positions* vertexNormals = nullptr;
    /// Stylized highlights (Anjyo & Hiramitsu 2003), later layers painted over earlier ones with the
    /// light above and the camera's eye, after shading and before lines.
    std::vector<RenderHighlight> highlights;
};

/// One frame's passes (Pencil+ render elements, Blender view layers), all width x height.
struct RenderPasses {
    ImageRGBA beauty; ///< the look: shading with lines, background, alpha = coverage of the model
    std::vector<float> lines; ///< line coverage in [0, 1]
    /// The strokes the lines pass draws, in pixels, hidden parts included (visibleStrokeParts
    /// with depth and id gives what the pass shows).
    std::vector<StyledStroke> strokes;
    std::vector<float> tone; ///< shading intensity before colour (toon tone, Lambert or Gooch luminance)
    std::vector<float> highlights; ///< stylized highlights coverage in [0, 1], zero off the model
    std::vector<float> depth; ///< distance along the view axis, +infinity off the model
    std::vector<Eigen::Vector3f> normal; ///< model-space unit normal, zero off the model
    std::vector<std::int32_t> id; ///< face id, -1 off the model
};

/// Topology data derived once per mesh and reused frame after frame (trimesh2-style caching).
/// A highlight layer's per-vertex geometry (smoothed normals, tangent frames), which depends on
/// the shape, the patch, the guide and the smoothing but not on the layer's keyed parameters:
/// kept across parameter edits and frames of a still shape (model::renderHighlightsFor).
struct HighlightGeometry {
    std::uint64_t key = 0; ///< hash of the shape's generation, the patch, the guide and the smoothing
    Positions normals, du, dv;
};

/// What every highlight track of a shape starts from: its vertex normals and, for a mesh with UVs,
/// their tangent frames; kept while the shape keeps its generation (0: none kept).
struct HighlightShapeFrames {
    std::uint64_t generation = 0;
    Positions normals, du, dv;
    bool haveUvFrames = false;
};

/// Apparent ridges between renderFrame calls: the curvature of the last shape (recomputed only when
/// the positions differ, compared byte for byte) and the snakes of the last line camera and
/// threshold (a stereo pair's two eyes share the centre eye's snakes, paper 3, section 4.2).
struct RidgeRenderCache {
    Positions shape; ///< the positions data was computed for
    Faces faces;
    RidgeShapeData data;
    RidgeScratch scratch;
    bool snakesValid = false;
    RasterCamera snakeCamera;
    float snakeThreshold = 0.f;
    bool snakeJoined = true; ///< the snakes were joined (false: raw ridges)
    std::vector<float> snakeScale; ///< the per-vertex threshold factor they were made with (empty: none)
    RidgeSnakes snakes;
};

/// A frame's working buffers, kept between frames so that a sequence allocates them once: after
/// the first frame of a size, a frame touches no fresh page for them (issue 29). Their contents
/// are overwritten by every frame; nothing is carried from one frame to the next.
struct RenderScratch {
    GBuffer gbuffer;
    Positions normals;
    FeatureEdges features;
    std::vector<float> lambert; ///< N.L + offset per pixel
    std::vector<float> vertexIntensity; ///< the comic paper's per-vertex table lookup
};

/// What renderFrame keeps between frames (the edge topology is the mesh's own, TriMesh::
/// edgeTopology()).
struct RenderCache {
    std::vector<HighlightGeometry> highlights; ///< most recently used last, a few entries
    HighlightShapeFrames highlightFrames;
    RidgeRenderCache ridges;
    RenderScratch scratch;
};

/// The ridge snakes of shape seen from lineCamera, through cache (curvature once per shape);
/// raw ridges (figure 4.8) when snakes is false; thresholdScale: per vertex, may be null.
const RidgeSnakes& cachedRidgeSnakes(const Positions& shape, const TriMesh& mesh, const RasterCamera& lineCamera,
    float threshold, RidgeRenderCache& cache, bool snakes = true, const std::vector<float>* thresholdScale = nullptr);

/// Renders shape (the view-dependent blend for this camera, #V by 3) with mesh's faces and
/// materials. lineView lets stereo pairs take their lines from the centre eye (paper 3, section
/// 4.2.2); null uses camera itself. gbuffer, when not null, receives the frame's G-buffer (the
/// depth analysis reads it; its earlier storage goes to the cache's scratch in exchange). out's
/// buffers are reused when they have the size already. Deterministic.
void renderFrame(const Positions& shape, const TriMesh& mesh, const RasterCamera& camera, const RenderLook& look,
    RenderCache& cache, RenderPasses& out, const RasterCamera* lineView = nullptr, GBuffer* gbuffer = nullptr);

} // namespace celform::algo
