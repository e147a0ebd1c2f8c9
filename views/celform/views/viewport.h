// The 3D viewport: VTK 9.1 hosted in a Qt 6 QOpenGLWidget (STACK.md pitfall 5), showing the
// document's base model, with Maya-style navigation handled here rather than by a VTK interactor.
#pragma once

#include "celform/algorithms/brush.h"
#include "celform/model/camera.h"
#include "celform/model/project_data.h"

#include <QColor>
#include <QImage>
#include <QOpenGLWidget>
#include <QPoint>
#include <QPointer>
#include <QSurfaceFormat>
#include <QTimer>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <memory>
#include <optional>
#include <vector>

namespace celform::model {
class Document;
}

namespace celform::views {

class LineOverlay;
struct GlFrame;

class Viewport : public QOpenGLWidget {
    Q_OBJECT
public:
    explicit Viewport(model::Document* document, QWidget* parent = nullptr);
    ~Viewport() override;

    /// The surface format VTK needs (OpenGL 3.2 core, depth, stencil). Must be installed with
    /// QSurfaceFormat::setDefaultFormat() before the QApplication is created.
    static QSurfaceFormat defaultFormat();

    [[nodiscard]] model::Camera camera() const;
    /// Shows the view of camera. An invalid camera (see model::Camera::isValid) is ignored.
    void setCamera(const model::Camera& camera);
    void setProjection(model::Projection projection);
    [[nodiscard]] model::Projection projection() const;

    /// What the widget shows now, in device pixels (size() * devicePixelRatio()).
    QImage renderedImage();
    /// Number of frames drawn so far; tests wait on it.
    [[nodiscard]] int renderCount() const { return m_renderCount; }
    /// Wall time of the last paintGL (VTK render, readbacks, lines, stereo composition), ms.
    [[nodiscard]] double lastFrameMilliseconds() const { return m_frameMilliseconds; }
    /// Wall time of the last frame's line extraction and drawing alone, ms.
    [[nodiscard]] double lastLineMilliseconds() const { return m_lineMilliseconds; }

    // --- stereo and lines (paper 3, sections 3.1 and 4.2.2) ---------------------------------
    /// Renders left and right eyes and shows their composition (Off: mono, the default).
    void setStereo(algo::StereoOutput output);
    [[nodiscard]] algo::StereoOutput stereo() const { return m_stereo; }
    /// Stereo settings used instead of the document look's (a review session's own interocular);
    /// nothing follows the look again.
    void setStereoLook(const std::optional<model::StereoLook>& look);
    [[nodiscard]] model::StereoLook stereoLook() const;
    /// The eye pair's settings for the current camera, "auto" distances resolved.
    [[nodiscard]] algo::StereoSettings resolvedStereoSettings() const;
    /// Lines shown or hidden whatever the look says; nothing follows Look::showLines.
    void setLinesOverride(std::optional<bool> show);
    [[nodiscard]] bool linesShown() const;
    /// Test hook: with stereo on, show one eye's full-colour image instead of the composition.
    enum class Eye { Both, Left, Right };
    void setEyeOnly(Eye eye);

    void setBackgroundColors(const QColor& top, const QColor& bottom);

    // --- the cartoon look (DESIGN.md, "Look") ---------------------------------------------------
    /// On (the default): the model is shaded with the document's look exactly as the offline
    /// renderer shades it, on the look's background. Off: the neutral clay look for modelling.
    /// The clay look also shows while brush selection colours are displayed.
    void setShadingEnabled(bool on);
    [[nodiscard]] bool isShadingEnabled() const { return m_shadingEnabled; }
    /// The key-light gizmo (an arrow towards a directional light, a sphere at a point light);
    /// Ctrl+left drag on it moves the light around the model.
    void setLightGizmoVisible(bool on);
    [[nodiscard]] bool isLightGizmoVisible() const { return m_lightGizmoVisible; }
    /// The frame the highlight tracks are drawn at (their keys interpolated there); 0 by default.
    void setFrame(int frame);
    [[nodiscard]] int frame() const { return m_frame; }
    /// Where the gizmo's handle is drawn (model space): the arrow tip or the point light.
    [[nodiscard]] Eigen::Vector3d lightGizmoHandle() const;

    /// Centre of the frame-all bounds, moved by panning: the point orbit turns around.
    [[nodiscard]] Eigen::Vector3d pivot() const { return m_pivot; }

    // --- what is shown (paper 1, section 3) ------------------------------------------------
    /// Shows a key's deformed shape (0: the base model). Leaves preview mode.
    void setDisplayedKey(model::ObjectId key);
    [[nodiscard]] model::ObjectId displayedKey() const { return m_displayedKey; }
    /// Preview mode: the shape is the view-dependent blend for this viewport's camera, updated
    /// live while orbiting (paper 1, section 3.2).
    void setPreview(bool on);
    [[nodiscard]] bool isPreview() const { return m_preview; }
    /// Observer mode: shows the blend for another viewport's camera from this one's (paper 1,
    /// figure 6, bottom row). Null ends it.
    void setObserved(Viewport* driver);
    /// The view direction of this camera, from the base centroid towards the eye (DESIGN.md).
    [[nodiscard]] Eigen::Vector3d viewDirection() const;
    /// The vertex positions on screen now (#V by 3): base, key or blend.
    [[nodiscard]] const algo::Positions& displayedShape() const { return m_shape; }

    /// A reference drawing fixed in the viewport (0: none), its height filling the view, so a
    /// camera aligned here matches the drawing (paper 1, section 3.1.1).
    void setOverlayDrawing(model::ObjectId drawing);
    [[nodiscard]] model::ObjectId overlayDrawing() const { return m_overlayDrawing; }
    /// Over the model (with the drawing's opacity) or under it, as a backdrop.
    void setOverlayOnTop(bool onTop);
    [[nodiscard]] bool overlayOnTop() const { return m_overlayOnTop; }

    // --- tools ------------------------------------------------------------------------------
    enum class Tool {
        Navigate, ///< mouse only navigates
        Align, ///< navigation edits the overlay drawing's camera (one undo step per gesture)
        Brush, ///< left drag deforms the displayed key (paper 1, section 3.1.2)
        Highlight, ///< left drag is forwarded as highlightDrag* signals (the Highlights dock edits)
        Patch, ///< left drag paints faces into the patch target (Ctrl+drag removes them)
    };
    enum class BrushMode { Move, Smooth };
    void setTool(Tool tool);
    [[nodiscard]] Tool tool() const { return m_tool; }
    void setBrushRadius(double radius);
    [[nodiscard]] double brushRadius() const { return m_brushRadius; }
    void setBrushMode(BrushMode mode) { m_brushMode = mode; }
    [[nodiscard]] BrushMode brushMode() const { return m_brushMode; }
    void setBrushMirrorX(bool on) { m_brushMirror = on; }
    [[nodiscard]] bool brushMirrorX() const { return m_brushMirror; }
    /// The face set (highlight patch) Tool::Patch paints into; created by the first stroke when
    /// missing. Its faces are tinted while the tool is on.
    void setPatchTarget(const QString& name);
    [[nodiscard]] QString patchTarget() const { return m_patchTarget; }
    /// Faces a paint dab at a widget position would touch: the face under it and every face
    /// turned towards the camera with a corner within the brush radius of the picked point.
    /// Empty when nothing is picked.
    [[nodiscard]] std::vector<std::int32_t> facesUnderBrush(const QPointF& position);
    // --- semi-automatic alignment: model points matched to drawing points --------------------
    /// While aligning, a click on the model adds a model point and Shift+click adds a drawing
    /// point; the i-th of each form a pair.
    void setPointMatching(bool on);
    [[nodiscard]] bool isPointMatching() const { return m_matching; }
    [[nodiscard]] const std::vector<Eigen::Vector3d>& matchedModelPoints() const { return m_modelPoints; }
    /// Drawing pixels (x right, y down from the top-left corner).
    [[nodiscard]] const std::vector<Eigen::Vector2d>& matchedDrawingPoints() const { return m_drawingPoints; }
    void clearMatchedPoints();
    void removeLastMatchedPoint();
    /// Solves the camera from at least six pairs (DLT, then Levenberg-Marquardt) and stores it
    /// with the drawing as one undo step. Returns the RMS reprojection error in drawing pixels,
    /// or nothing with a message.
    std::optional<double> solveFromMatchedPoints(QString* error);
    /// Widget position (logical pixels) to drawing pixels and back, for the drawing shown.
    [[nodiscard]] std::optional<Eigen::Vector2d> widgetToDrawing(const QPointF& position) const;
    [[nodiscard]] QPointF drawingToWidget(const Eigen::Vector2d& pixel) const;

    /// The vertex under a widget position (logical pixels) on the displayed shape, or -1.
    [[nodiscard]] std::int64_t pickVertex(const QPointF& position);
    /// World units per logical pixel at a point's depth (for brush drags and tests).
    [[nodiscard]] double worldUnitsPerPixel(const Eigen::Vector3d& point) const;
    /// Projects a model point to widget coordinates (logical pixels, y down).
    [[nodiscard]] QPointF projectToWidget(const Eigen::Vector3d& point) const;

public slots:
    /// Keeps the view direction and fits the whole model in the view.
    void frameAll();
    /// Front view (looking down -Z, Y up), framed.
    void resetView();

signals:
    /// Emitted after every navigation step and every programmatic camera change.
    void cameraChanged();
    void brushRadiusChanged(double radius);
    void toolChanged(celform::views::Viewport::Tool tool);
    /// A message for the status bar (brush refused, nothing picked, ...).
    void message(const QString& text);
    void matchedPointsChanged();
    /// The highlight frame changed (setFrame).
    void frameChanged(int frame);
    /// Left drag in Tool::Highlight: start (widget position), each move (delta in logical
    /// pixels, modifiers held), end.
    void highlightDragStarted(const QPointF& position);
    void highlightDragged(const QPointF& delta, Qt::KeyboardModifiers modifiers);
    void highlightDragFinished();

protected:
    void showEvent(QShowEvent* event) override;
    void initializeGL() override;
    void resizeGL(int w, int h) override;
    void paintGL() override;

    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;

private:
    enum class Drag { None, Orbit, Pan, Dolly, Roll, Brush, Light, Highlight, Patch };

    void releaseGraphics();
    void rebuildMesh();
    /// Recomputes m_shape for the current source and uploads positions and normals.
    void updateShape();
    void updateOverlay();
    [[nodiscard]] double wantedFrameScale() const;
    /// Keeps the stored camera when the drawing frame's share of the viewport changes.
    void refreshFrameScale();
    void updateSelectionColors();
    void roll(double degrees);
    void beginBrush(const QPointF& position, Qt::KeyboardModifiers modifiers);
    void brushMove(const QPointF& delta, Qt::KeyboardModifiers modifiers);
    void endBrush();
    /// One paint dab of Tool::Patch at a widget position (Ctrl removes); a drag is one undo step.
    void paintPatch(const QPointF& position, Qt::KeyboardModifiers modifiers);
    /// Tints the patch target's faces while Tool::Patch is on (hidden otherwise).
    void updatePatchOverlay();
    void rebuildGrid();
    void updateTriadViewport();
    void syncTriadCamera();
    /// Look shader on or off (enabled, a mesh, no selection colours), background and grid to match.
    void applyShadingState();
    /// Per-vertex look attributes and uniforms for the displayed shape.
    void updateLookShading();
    void updateLightGizmo();
    /// Radius of the sphere the light handle moves on, and its centre (the model's).
    [[nodiscard]] double lightGizmoRadius() const;
    /// Moves the light so the handle lies under a widget position (one undo step per drag).
    void dragLight(const QPointF& position);
    /// One VTK frame into Qt's framebuffer, read back (colour only when wanted, depth when
    /// lines are shown), camera and clipping as they are now.
    void renderVtkFrame(bool readColor, bool readDepth, GlFrame& out);
    /// The projection VTK uses now, as a raster camera of the framebuffer's size.
    [[nodiscard]] algo::RasterCamera vtkRasterCamera() const;
    /// Line coverage of the displayed shape for camera, strokes extracted from lineEye (the
    /// centre eye in stereo), hidden by depth; returns the rect the lines may touch.
    QRect lineCoverage(const algo::RasterCamera& camera, const algo::RasterCamera& lineEye,
        const std::vector<float>& depth, std::vector<float>& coverage);
    void paintStereo();
    /// The document's look, or the default one without a document.
    [[nodiscard]] const model::Look& currentLook() const;

    void orbit(double yawDegrees, double pitchDegrees);
    void pan(const QPointF& deltaPixels);
    void dolly(double factor);
    void cameraEdited();

    struct Vtk; // VTK objects, kept out of this header so that users do not pull VTK in
    model::Document* m_document;
    std::unique_ptr<Vtk> m_vtk;

    Eigen::AlignedBox3d m_bounds; ///< of the base model, or a unit box when there is none
    Eigen::Vector3d m_pivot{0.0, 0.0, 0.0};
    Drag m_drag = Drag::None;
    Qt::MouseButton m_dragButton = Qt::NoButton;
    QPointF m_lastPos;
    int m_renderCount = 0;
    bool m_framed = false; ///< the camera is as frameAll() left it, not moved since
    bool m_initialized = false;

    algo::Positions m_shape; ///< the displayed positions
    model::ObjectId m_displayedKey = 0;
    bool m_preview = false;
    QPointer<Viewport> m_observed;
    model::ObjectId m_overlayDrawing = 0;
    bool m_overlayOnTop = true;
    double m_frameScale = 1.0; ///< widget height / drawing height on screen (>= 1)

    Tool m_tool = Tool::Navigate;
    QTimer m_alignCommit; ///< stores the aligned camera once navigation settles
    double m_brushRadius = 0.1;
    BrushMode m_brushMode = BrushMode::Move;
    bool m_brushMirror = false;
    algo::BrushSelection m_selection;
    std::vector<std::int32_t> m_mirror; ///< mirror map of the base, built on demand
    algo::BrushSelection m_mirrorSelection;
    int m_strokeId = 0;
    QString m_patchTarget;
    /// Faces around each vertex (CSR over the base model), built on the first paint dab.
    std::vector<std::int32_t> m_vertexFaceStart, m_vertexFaces;
    std::weak_ptr<const algo::TriMesh> m_vertexFacesMesh; ///< the base model m_vertexFaces was built for
    algo::VertexGrid m_patchGrid; ///< over the displayed shape, for one paint stroke
    bool m_matching = false;
    std::vector<Eigen::Vector3d> m_modelPoints;
    std::vector<Eigen::Vector2d> m_drawingPoints;
    QWidget* m_markers = nullptr; ///< transparent child painting the matched points
    double m_strokeUnitsPerPixel = 0.0;
    bool m_shadingEnabled = true;
    bool m_lightGizmoVisible = true;
    int m_frame = 0;
    QColor m_clayTop{200, 201, 204};
    QColor m_clayBottom{150, 151, 155};

    algo::StereoOutput m_stereo = algo::StereoOutput::Off;
    std::optional<model::StereoLook> m_stereoLook;
    std::optional<bool> m_linesOverride;
    Eye m_eyeOnly = Eye::Both;
    std::unique_ptr<LineOverlay> m_lines;
    double m_frameMilliseconds = 0.0;
    double m_lineMilliseconds = 0.0;
};

} // namespace celform::views
