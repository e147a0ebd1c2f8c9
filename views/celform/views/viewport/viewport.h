// The 3D viewport: VTK 9.1 hosted in a Qt 6 QOpenGLWidget (STACK.md pitfall 5). This class is the
// host: GL lifetime and keeping the scene in step with the document at the playhead
// (viewport.cpp), pointer and key events (viewport_events.cpp). The VTK scene, the camera, the
// frame composition, the displayed shape and each editing tool have files of their own
// (viewport_*.h, tools/).
#pragma once

#include "celform/algorithms/brush.h"
#include "celform/model/data/camera.h"
#include "celform/model/document/change_set.h"
#include "celform/model/data/project_data.h"

#include <QColor>
#include <QImage>
#include <QOpenGLWidget>
#include <QPoint>
#include <QPointer>
#include <QSurfaceFormat>
#include <QTimer>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <map>
#include <memory>
#include <optional>
#include <vector>

class vtkRenderer;

namespace celform::model {
class Document;
}

namespace celform::views {

class AlignTool;
class AxisGizmo;
class BrushTool;
class OffsetBrushTool;
class DisplayedShape;
class ViewportCamera;
class ViewportCompositor;
class ViewportScene;
class ViewportTool;

enum class NavigationStyle { Maya, Blender };
enum class OrbitMode { Turntable, Trackball };

class Viewport : public QOpenGLWidget {
    Q_OBJECT
public:
    explicit Viewport(model::Document* document, QWidget* parent = nullptr);
    ~Viewport() override;

    /// The surface format VTK needs (OpenGL 3.2 core, depth, stencil). Must be installed with
    /// QSurfaceFormat::setDefaultFormat() before the QApplication is created.
    static QSurfaceFormat defaultFormat();

    [[nodiscard]] model::Document* document() const { return m_document; }
    [[nodiscard]] model::Camera camera() const;
    /// Shows the view of camera. An invalid camera (see model::Camera::isValid) is ignored.
    void setCamera(const model::Camera& camera);
    void setProjection(model::Projection projection);
    [[nodiscard]] model::Projection projection() const;

    /// What the widget shows now, in device pixels (size() * devicePixelRatio()).
    QImage renderedImage();
    /// Number of frames drawn so far; tests wait on it.
    [[nodiscard]] int renderCount() const { return m_renderCount; }
    /// Number of times the displayed shape was recomputed (in full or in part): a hidden
    /// viewport's stays put while the document changes.
    [[nodiscard]] int shapeUpdates() const { return m_shapeUpdates; }
    /// Wall time of the last paintGL (VTK render, readbacks, lines, stereo composition), ms.
    [[nodiscard]] double lastFrameMilliseconds() const { return m_frameMilliseconds; }
    /// Wall time of the last frame's line extraction and drawing alone, ms.
    [[nodiscard]] double lastLineMilliseconds() const;

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
    /// renderer shades it (at the playhead), on the look's background. Off: the neutral clay look
    /// for modelling. The clay look also shows while brush selection colours are displayed.
    void setShadingEnabled(bool on);
    [[nodiscard]] bool isShadingEnabled() const { return m_shadingEnabled; }
    /// The key-light gizmo (an arrow towards a directional light, a sphere at a point light);
    /// Ctrl+left drag on it moves the light around the model.
    void setLightGizmoVisible(bool on);
    [[nodiscard]] bool isLightGizmoVisible() const { return m_lightGizmoVisible; }
    /// Where the gizmo's handle is drawn (model space): the arrow tip or the point light.
    [[nodiscard]] Eigen::Vector3d lightGizmoHandle() const;
    /// Whether the gizmo is on screen now (shading on, a model).
    [[nodiscard]] bool lightGizmoShown() const;
    /// Radius of the sphere the light handle moves on, and its centre (the model's).
    [[nodiscard]] double lightGizmoRadius() const;
    [[nodiscard]] Eigen::Vector3d modelCentre() const;

    /// Centre of the frame-all bounds, moved by panning: the point orbit turns around.
    [[nodiscard]] Eigen::Vector3d pivot() const;

    // --- what is shown (paper 1, section 3), always at the document's playhead ---------------
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
    /// The model layer's renderer, for props drawn in this view's 3D scene (the Observer's camera
    /// path overlay); the viewport owns it. Call update() after changing such props.
    [[nodiscard]] vtkRenderer* modelRenderer() const;
    /// The shading-offset brush (its mode, strength and target live in the tool).
    [[nodiscard]] OffsetBrushTool* offsetBrushTool() const;
    /// The view direction of this camera, from the base centroid towards the eye (DESIGN.md).
    [[nodiscard]] Eigen::Vector3d viewDirection() const;
    /// The vertex positions on screen (#V by 3): base, key or blend, brought up to date first.
    [[nodiscard]] const algo::Positions& displayedShape();
    /// The generation of the shape displayedShape() returns (algo::Shape): caches compare it.
    [[nodiscard]] std::uint64_t displayedShapeGeneration();
    /// The shading offsets in effect for the shape shown (model::effectiveShadingOffsets: the base
    /// layer, plus the key's layer for a key's shape, plus the blended key layers for the blend);
    /// empty for none. Brought up to date first.
    [[nodiscard]] const std::vector<float>& displayedShadingOffsets();

    /// A reference drawing fixed in the viewport (0: none), its height filling the view, so a
    /// camera aligned here matches the drawing (paper 1, section 3.1.1).
    void setOverlayDrawing(model::ObjectId drawing);
    [[nodiscard]] model::ObjectId overlayDrawing() const { return m_overlayDrawing; }
    /// Over the model (with the drawing's opacity) or under it, as a backdrop.
    void setOverlayOnTop(bool onTop);
    [[nodiscard]] bool overlayOnTop() const { return m_overlayOnTop; }
    /// Only the drawing's lines and silhouette edge, in magenta, for checking contours meet.
    void setOverlayOutline(bool on);
    [[nodiscard]] bool overlayOutline() const { return m_overlayOutline; }

    // --- tools (views/tools/, one file each) ---------------------------------------------------
    enum class Tool {
        Navigate, ///< mouse only navigates
        Align, ///< navigation edits the overlay drawing's camera (one undo step per gesture)
        Brush, ///< left drag deforms the displayed key at the playhead (paper 1, section 3.1.2)
        Highlight, ///< left drag moves, rotates or scales the highlight target (one undo step)
        Patch, ///< left drag paints faces into the patch target (Ctrl+drag removes them)
        OffsetBrush, ///< left drag paints shading offsets into the tool's target (paper 3, 4.3)
    };
    enum class BrushMode { Move, Smooth, Relax };
    void setTool(Tool tool);
    [[nodiscard]] Tool tool() const { return m_tool; }
    void setBrushRadius(double radius);
    [[nodiscard]] double brushRadius() const { return m_brushRadius; }
    void setBrushMode(BrushMode mode) { m_brushMode = mode; }
    [[nodiscard]] BrushMode brushMode() const { return m_brushMode; }
    /// The radius in world units (setBrushRadius) or in widget pixels, as Blender's "View"
    /// radius: the same size on screen whatever the zoom.
    enum class BrushRadiusUnit { World, Pixels };
    void setBrushRadiusUnit(BrushRadiusUnit unit) { m_brushRadiusUnit = unit; }
    [[nodiscard]] BrushRadiusUnit brushRadiusUnit() const { return m_brushRadiusUnit; }
    void setBrushPixelRadius(double pixels);
    [[nodiscard]] double brushPixelRadius() const { return m_brushPixelRadius; }
    /// The falloff curve and strength of the next strokes.
    void setBrushProfile(const algo::BrushProfile& profile) { m_brushProfile = profile; }
    [[nodiscard]] const algo::BrushProfile& brushProfile() const { return m_brushProfile; }
    /// The brush tool (its circle under the cursor, F-resize state), for tests.
    [[nodiscard]] BrushTool* brushTool() const;
    void setBrushMirrorX(bool on) { m_brushMirror = on; }
    [[nodiscard]] bool brushMirrorX() const { return m_brushMirror; }
    /// The face set (highlight patch) Tool::Patch paints into; created by the first stroke when
    /// missing. Its faces are tinted while the tool is on.
    void setPatchTarget(const QString& name);
    [[nodiscard]] QString patchTarget() const { return m_patchTarget; }
    /// The highlight layer Tool::Highlight edits (0: none).
    void setHighlightTarget(model::ObjectId layer) { m_highlightTarget = layer; }
    [[nodiscard]] model::ObjectId highlightTarget() const { return m_highlightTarget; }
    /// The brush selection shown in red (brush tool), or none.
    void showBrushSelection(const algo::BrushSelection* selection, const algo::BrushSelection* mirror);

    // --- semi-automatic alignment: model points matched to drawing points (AlignTool) --------
    /// While aligning, a click on the model adds a model point and Shift+click adds a drawing
    /// point; the i-th of each form a pair.
    void setPointMatching(bool on);
    [[nodiscard]] bool isPointMatching() const;
    [[nodiscard]] const std::vector<Eigen::Vector3d>& matchedModelPoints() const;
    /// Drawing pixels (x right, y down from the top-left corner).
    [[nodiscard]] const std::vector<Eigen::Vector2d>& matchedDrawingPoints() const;
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
    /// The surface point under a widget position and its face, or nothing.
    [[nodiscard]] std::optional<std::pair<std::int64_t, Eigen::Vector3d>> pickSurface(const QPointF& position);
    /// World units per logical pixel at a point's depth (for brush drags and tests).
    [[nodiscard]] double worldUnitsPerPixel(const Eigen::Vector3d& point) const;
    /// Projects a model point to widget coordinates (logical pixels, y down).
    [[nodiscard]] QPointF projectToWidget(const Eigen::Vector3d& point) const;
    /// The ray through a widget position: origin and unit direction (model space).
    [[nodiscard]] std::pair<Eigen::Vector3d, Eigen::Vector3d> rayThrough(const QPointF& position) const;

    /// The six axis views, framed (Blender's numeric keypad 1, 3, 7 and their opposites).
    enum class ViewPreset { Front, Back, Right, Left, Top, Bottom };
    void setViewPreset(ViewPreset preset);

    // --- navigation preferences (Edit > Preferences) --------------------------------------------
    /// Maya: Alt + left orbit, Alt + middle pan, Alt + right dolly (and the middle-button
    /// equivalents). Blender: middle orbit, Shift + middle pan, Ctrl + middle dolly; Alt + left
    /// drag goes to the tool.
    void setNavigationStyle(NavigationStyle style) { m_navigationStyle = style; }
    [[nodiscard]] NavigationStyle navigationStyle() const { return m_navigationStyle; }
    void setOrbitMode(OrbitMode mode);
    [[nodiscard]] OrbitMode orbitMode() const;
    /// Multiplies the orbit's degrees per pixel (1: 0.4 degrees per pixel).
    void setOrbitSpeed(double factor);
    [[nodiscard]] double orbitSpeed() const { return m_orbitSpeed; }
    /// Orbit turns around the surface point under the cursor where the drag starts (Maya's
    /// tumble pivot); elsewhere, and when off, around the framed centre moved by panning.
    void setOrbitAroundCursor(bool on) { m_orbitAroundCursor = on; }
    [[nodiscard]] bool orbitAroundCursor() const { return m_orbitAroundCursor; }

public slots:
    /// Keeps the view direction and fits the whole model in the view.
    void frameAll();
    /// Front view (looking down -Z, Y up), framed.
    void resetView();

signals:
    /// Emitted after every navigation step and every programmatic camera change.
    void cameraChanged();
    void brushRadiusChanged(double radius);
    void brushPixelRadiusChanged(double pixels);
    void toolChanged(celform::views::Viewport::Tool tool);
    /// A message for the status bar (brush refused, nothing picked, ...).
    void message(const QString& text);
    void matchedPointsChanged();

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
    void leaveEvent(QEvent* event) override;
    bool event(QEvent* event) override;

private:
    friend class AlignTool;
    enum class Drag { None, Orbit, Pan, Dolly, Roll, Tool };

    /// What the document change means for this view: only marks things stale and schedules a
    /// paint; the work happens in syncScene().
    void documentChanged(const model::ChangeSet& change);
    void releaseGraphics();
    void rebuildMesh();
    /// Brings the scene up to date with the document before a paint or a pick: the shape at the
    /// playhead, its upload, the look's per-vertex data, the patch overlay.
    void syncScene();
    void updateOverlay();
    [[nodiscard]] double wantedFrameScale() const;
    /// Keeps the stored camera when the drawing frame's share of the viewport changes.
    void refreshFrameScale();
    /// Look shader on or off (enabled, a mesh, no selection colours), background and grid to match.
    void applyShadingState();
    void updateLightGizmo();
    /// After every camera change: keeps the view up, the preview's blend, the tool and listeners
    /// in step.
    void cameraEdited();
    void endDrag(bool cancelled);
    [[nodiscard]] ViewportTool* activeTool() const;
    [[nodiscard]] AlignTool* alignTool() const;
    /// Recomputes m_shadingOffsets for the displayed shape's source at the playhead.
    void updateShadingOffsets(const Eigen::Vector3d& direction);
    /// The document's look, or the default one without a document.
    [[nodiscard]] const model::Look& currentLook() const;

    model::Document* m_document;
    std::unique_ptr<ViewportScene> m_scene;
    std::unique_ptr<ViewportCamera> m_camera;
    std::unique_ptr<ViewportCompositor> m_compositor;
    std::unique_ptr<DisplayedShape> m_shape;
    std::vector<float> m_shadingOffsets; ///< in effect for m_shape (displayedShadingOffsets)
    std::map<Tool, std::unique_ptr<ViewportTool>> m_tools;
    std::unique_ptr<ViewportTool> m_lightTool; ///< Ctrl+drag on the gizmo, whatever the tool
    AxisGizmo* m_axisGizmo = nullptr; ///< child widget, top right

    Drag m_drag = Drag::None;
    QTimer m_wheelBurst; ///< a pause in wheel ticks ends their navigation gesture
    ViewportTool* m_dragTool = nullptr;
    Qt::MouseButton m_dragButton = Qt::NoButton;
    QPointF m_lastPos;
    double m_rollDragged = 0.0, m_rollApplied = 0.0; ///< degrees, this roll drag (Ctrl snaps)
    int m_renderCount = 0;
    int m_shapeUpdates = 0;
    bool m_initialized = false;

    model::ObjectId m_displayedKey = 0;
    bool m_preview = false;
    QPointer<Viewport> m_observed;
    model::ObjectId m_overlayDrawing = 0;
    bool m_overlayOnTop = true;
    bool m_overlayOutline = false;
    QImage m_outline; ///< the overlay drawing's outline, made when first shown
    qint64 m_outlineSource = 0; ///< cacheKey of the image m_outline was made from
    bool m_lookStale = true; ///< the look's per-vertex data needs refreshing before a paint
    bool m_patchStale = true;
    std::uint64_t m_uploadedGeneration = 0; ///< of the shape in the VTK arrays

    Tool m_tool = Tool::Navigate;
    double m_brushRadius = 0.1;
    double m_brushPixelRadius = 50.0;
    BrushRadiusUnit m_brushRadiusUnit = BrushRadiusUnit::World;
    algo::BrushProfile m_brushProfile;
    BrushMode m_brushMode = BrushMode::Move;
    bool m_brushMirror = false;
    QString m_patchTarget;
    model::ObjectId m_highlightTarget = 0;
    bool m_shadingEnabled = true;
    bool m_lightGizmoVisible = true;

    NavigationStyle m_navigationStyle = NavigationStyle::Maya;
    double m_orbitSpeed = 1.0;
    bool m_orbitAroundCursor = false;

    algo::StereoOutput m_stereo = algo::StereoOutput::Off;
    std::optional<model::StereoLook> m_stereoLook;
    std::optional<bool> m_linesOverride;
    Eye m_eyeOnly = Eye::Both;
    double m_frameMilliseconds = 0.0;
};

} // namespace celform::views
