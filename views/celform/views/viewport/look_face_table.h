// The per-face data of the viewport's look (LookShading): each face's material, PerFace tones and
// highlight patches, resolved as render.cpp does, uploaded as a texture in VTK's drawing order.
#pragma once

#include "celform/algorithms/render.h"
#include "celform/algorithms/tri_mesh.h"

#include <vtkSmartPointer.h>
#include <vtkType.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

class vtkCallbackCommand;
class vtkCellArray;
class vtkPoints;
class vtkPolyData;
class vtkRenderer;
class vtkShaderProgram;
class vtkTextureObject;

namespace celform::views {

/// render.cpp's lightDirection: unit vector towards the light (a direction, or a point light's
/// position), +Z for a degenerate one.
[[nodiscard]] Eigen::Vector3f lookLightDirection(
    const Eigen::Vector3f& light, bool point, const Eigen::Vector3f& position);

/// The face table of one viewport mesh: what the look's fragment shader reads per face (by
/// gl_PrimitiveID, as render.cpp reads its G-buffer's face id), so that nothing of a face is
/// interpolated across faces.
///
/// When every face has the same data and nothing per face is needed (the usual case: one
/// material, no PerFace tones, no highlight patch), needed() is false and the shaders are built without the table:
/// setUniforms() then passes the shared data as uniforms and no texture is made.
class LookFaceTable {
public:
    /// mesh: the polydata VTK draws (its polys in face order); renderer: the one drawing it (the
    /// texture is made in its window's context and released at the end of its frames).
    LookFaceTable(vtkPolyData* mesh, vtkRenderer* renderer);
    ~LookFaceTable();
    LookFaceTable(const LookFaceTable&) = delete;
    LookFaceTable& operator=(const LookFaceTable&) = delete;

    /// The fragment shader's declarations for the table (before the look's own; the layout is
    /// described there): the texture's uniforms and fetch functions with CF_FACE_TABLE defined,
    /// the uniforms of the shared face data without.
    [[nodiscard]] static std::string glslDeclarations();

    /// Resolves each face's data for the look on the displayed shape (#V by 3): its material's
    /// colour, style and Gooch entry, whether it is in the patch of each of the highlight layers
    /// the shaders draw (the first kViewportHighlightLayers of `highlights`, by their faceMask),
    /// and for the PerFace toon evaluation its normal and tones (offsets: per-vertex shading
    /// offsets, empty for none). The upload waits for the next draw.
    void update(const algo::RenderLook& look, const algo::TriMesh& mesh, const algo::Positions& shape,
        const std::vector<float>& offsets, const std::vector<algo::RenderHighlight>& highlights);
    /// Whether the faces differ, so the shaders must read the table (CF_FACE_TABLE).
    [[nodiscard]] bool needed() const { return m_needed; }

    /// For one draw with a program built with (texture) or without the table: binds the table
    /// (uploaded in drawing order when it or the polydata changed) until the renderer's frame
    /// ends, or sets the uniforms of the data all faces share.
    void setUniforms(vtkShaderProgram* program, bool texture);

private:
    /// Brings m_drawnFaces up to date with the polydata as VTK's index buffer sees it; true when
    /// it changed.
    bool findDrawnFaces();
    /// Uploads the table in drawing order when it changed (or GL lost it) and binds it.
    bool bind(vtkShaderProgram* program);

    vtkPolyData* m_mesh = nullptr;
    vtkRenderer* m_renderer = nullptr;
    vtkSmartPointer<vtkCallbackCommand> m_renderEndObserver;

    // The look's material entries (Gooch coefficients) and, per face of the document in face
    // order, its row, as update() resolves them.
    std::vector<float> m_materialTable; ///< kMaterialFloats per entry
    std::vector<float> m_faceTable; ///< kFaceFloats per face
    bool m_needed = false;
    std::array<float, 4> m_sameFace{}; ///< the first texel every face has, when !m_needed
    std::array<float, 12> m_sameGooch{}; ///< and its material's entry
    bool m_tableChanged = true;

    // The triangles VTK draws, in order: it builds its index buffer from the polys at every
    // change of the polydata and leaves out triangles with two equal corners (as the CPU
    // rasteriser covers no pixel of them), numbering the others consecutively (gl_PrimitiveID).
    std::vector<std::int32_t> m_drawnFaces; ///< face of each triangle; empty when all are drawn
    std::int32_t m_drawnCount = 0;
    int m_primitiveBase = 0; ///< vertex and line primitives VTK numbers before the triangles
    vtkPoints* m_drawnPoints = nullptr; ///< what m_drawnFaces was found for, and when
    vtkCellArray* m_drawnPolys = nullptr;
    vtkMTimeType m_drawnTime = 0;

    vtkSmartPointer<vtkTextureObject> m_texture;
    std::vector<float> m_packed; ///< the texture's texels, reused between uploads
    int m_faceBase = 0; ///< first face texel in the texture
    int m_shift = 0; ///< log2 of its width
    bool m_tooLarge = false;
    bool m_tooManyMaterials = false;
};

} // namespace celform::views
