// The viewport's VTK scene: the renderers and actors (model, ground grid, axes triad, reference
// drawing, painted patch, key-light gizmo), the model as zero-conversion vtkPolyData, picking,
// and the model layer's depth for hidden lines. Knows VTK, not the document.
#pragma once

#include "celform/algorithms/brush.h"
#include "celform/algorithms/tri_mesh.h"
#include "celform/model/data/project_data.h"

#include <QColor>
#include <QImage>

#include <Eigen/Geometry>

#include <memory>
#include <optional>
#include <vector>

class vtkCamera;
class vtkGenericOpenGLRenderWindow;
class vtkRenderer;

namespace celform::views {

class LookShading;

class ViewportScene {
public:
    ViewportScene();
    ~ViewportScene();
    ViewportScene(const ViewportScene&) = delete;
    ViewportScene& operator=(const ViewportScene&) = delete;

    [[nodiscard]] vtkGenericOpenGLRenderWindow* window() const;
    /// The model layer's renderer (its active camera is the viewport's camera).
    [[nodiscard]] vtkRenderer* renderer() const;
    [[nodiscard]] vtkCamera* camera() const;
    [[nodiscard]] LookShading& look() const;

    // --- the model ---------------------------------------------------------------------------
    /// New topology (or none): positions and normals arrays sized for it, cells copied.
    void setMesh(const algo::TriMesh* mesh);
    [[nodiscard]] bool hasMesh() const;
    /// Copies positions and normals (#V by 3 each, the mesh's vertex count) into the arrays:
    /// every row, or only the given rows (ascending) when the arrays hold the rest already, so a
    /// brush step costs what the brush touched.
    void uploadShape(const algo::Positions& shape, const algo::Positions& normals);
    void uploadRows(
        const algo::Positions& shape, const algo::Positions& normals, const std::vector<std::uint32_t>& rows);
    /// The uploaded normals, row-major #V by 3 floats (null without a mesh).
    [[nodiscard]] const float* normals() const;
    /// Paper 1, section 3.1.2: the brush's selected vertices in red, shaded by their falloff
    /// (null selections: no colours). Colours show the clay look, so the look steps aside.
    void setSelectionColors(
        const algo::BrushSelection* selection, const algo::BrushSelection* mirror, Eigen::Index vertexCount);
    [[nodiscard]] bool selectionShown() const;

    // --- surroundings ------------------------------------------------------------------------
    void rebuildGrid(const Eigen::AlignedBox3d& bounds);
    void setClayBackground(const QColor& top, const QColor& bottom);
    /// The look's shader and flat background (as the render writes them) or the neutral clay,
    /// gradient and grid; the light gizmo shown or not.
    void applyShading(bool lookActive, bool lookBackground, const Eigen::Vector3f& background, bool showLight);
    /// An arrow towards a directional light or a sphere at a point light.
    void setLightGizmo(const model::Light& light, const Eigen::Vector3d& centre, double radius);
    [[nodiscard]] bool lightGizmoVisible() const;
    /// The painted patch tinted over the model (lifted along the normals); null hides it.
    void setPatchOverlay(const algo::Positions& shape, const algo::Positions& normals, const algo::Faces& faces,
        const algo::FaceSet* set, float lift);
    /// The axes triad in the lower-left corner, following the main camera's orientation.
    void placeTriad(int width, int height, int cornerPixels);

    // --- the reference drawing ---------------------------------------------------------------
    /// The drawing fixed in the view, its height filling the view (null: none). Over the model
    /// with opacity, or under it as an opaque backdrop.
    void setDrawing(const QImage* image, bool onTop, double opacity);
    /// Keeps the drawing's height fitting the view after a resize.
    void fitDrawing(int width, int height);

    // --- picking and depth -------------------------------------------------------------------
    struct Pick {
        std::int64_t face = -1;
        Eigen::Vector3d position = Eigen::Vector3d::Zero();
    };
    /// The model surface under a framebuffer pixel (x right, y up), or nothing. Needs a current
    /// GL context.
    [[nodiscard]] std::optional<Pick> pick(double x, double y) const;
    /// Reads the model layer's window depth (rows bottom-up) during the next Render().
    void captureDepthOnNextRender(bool on);
    [[nodiscard]] const std::vector<float>& capturedDepth() const;

    /// Whether the main camera has been placed: VTK does not reset a camera that was touched
    /// before the first render (docs/pitfalls.md, "VTK in a Qt 6 widget"), so the first frame depends on our framing.
    bool cameraPlaced = false;

private:
    struct Vtk;
    std::unique_ptr<Vtk> m;
};

} // namespace celform::views
