// The document's cartoon look on the viewport's mesh: VTK shader replacements that shade each
// fragment as algo::renderFrame shades each pixel (same GLSL mirror of shading.cpp, light and
// normals in model space), so the viewport shows what `celform render` writes.
#pragma once

#include "celform/algorithms/tri_mesh.h"
#include "celform/model/data/project_data.h"

#include <memory>
#include <vector>

class vtkActor;
class vtkPolyData;
class vtkRenderer;

namespace celform::algo {
struct RenderHighlight;
}

namespace celform::views {

/// What the viewport's shader draws of the highlight tracks: the first visible layers, and of each
/// the first operations and combinations (uniform arrays of fixed size). `celform render` draws
/// them all; the Highlights dock says when a look goes beyond these.
inline constexpr int kViewportHighlightLayers = 4;
inline constexpr int kViewportHighlightOperations = 8;
inline constexpr int kViewportHighlightCombinations = 2;

/// Configures one actor (its mapper must be a vtkOpenGLPolyDataMapper) for a model::Look.
///
/// Spaces: everything is shaded in model space, as the offline renderer does. The vertex shader
/// passes the model-space position (vertexMC; the mapper's coordinate shift/scale is disabled so
/// it is the document's coordinates) and the model-space vertex normal (the mesh's "Normals"
/// array mapped as a custom attribute, not VTK's view-space normal); the light vector, the eye
/// and the view axis are uniforms in model space (the actor has no transform).
///
/// Per-face data (LookFaceTable: a float texture the fragment shader reads by gl_PrimitiveID, as
/// render.cpp reads its G-buffer's face id): the face's material (colour, style and Gooch
/// coefficients, which the "auto" preset sets per material), so nothing of a material is
/// interpolated across faces, and for the PerFace toon evaluation the face's tone as render.cpp
/// computes it (face normal, light at the face's centre, mean of the corners' offsets), from
/// either side of the face.
///
/// Per-vertex attributes (point arrays added to the polydata): the shading offset O_v (paper 3,
/// equation 4.3), the PerVertexLut intensity (lookupIntensity of N.L + O_v, computed here on the
/// CPU exactly as render.cpp does), and for up to 4 highlight layers (model::renderHighlightsFor at
/// the frame) the vertex's du with the handedness of its frame (dv = w N x du) and the layer's
/// smoothed normal (zero: the surface's, which is then N). Whether a fragment is in a layer's
/// patch is decided per face, as render.cpp decides it: a bit per layer in the face table.
/// Look uniforms are set from a cached copy each time VTK binds the program (UpdateShaderEvent),
/// so a Look change costs no shader rebuild; only setActive() rebuilds the shaders.
class LookShading {
public:
    LookShading(vtkActor* actor, vtkPolyData* mesh, vtkRenderer* renderer);
    ~LookShading();
    LookShading(const LookShading&) = delete;
    LookShading& operator=(const LookShading&) = delete;

    /// Refreshes the per-vertex arrays and the uniforms for the displayed project (the document's,
    /// or its subdivided stand-in: model::SubdividedSurface) with the document's look and the
    /// displayed shape (#V by 3, with its vertex normals, row-major #V by 3 floats).
    /// frame selects the highlight tracks' keys (model::renderHighlightsFor at that frame).
    /// shapeGeneration (algo::Shape) lets the highlight geometry be reused while the shape is still.
    /// shadingOffsets: the offsets in effect for the shape shown (model::effectiveShadingOffsets;
    /// empty for none); null means the base layer alone.
    void update(const model::ProjectData& data, const model::Look& documentLook, const algo::Positions& shape,
        const float* normals, int frame = 0, std::uint64_t shapeGeneration = 0,
        const std::vector<float>* shadingOffsets = nullptr);
    /// On: the look's shader; off: VTK's own lighting (the viewport's clay look) as configured
    /// before. Rebuilds the shaders only when the state changes.
    void setActive(bool active);
    [[nodiscard]] bool isActive() const;

private:
    /// Highlight uniforms and per-vertex frames and normals, as renderFrame resolves them; returns
    /// the layers the shaders draw (for their patches' face masks).
    std::vector<algo::RenderHighlight> updateHighlights(const model::ProjectData& data, const model::Look& documentLook,
        const algo::Positions& shape, const float* normals, int frame, Eigen::Index count,
        std::uint64_t shapeGeneration);

    struct Impl;
    std::unique_ptr<Impl> m;
};

} // namespace celform::views
