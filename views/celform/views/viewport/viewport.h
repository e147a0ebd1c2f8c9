// The 3D viewport: VTK 9.1 hosted in a Qt 6 QOpenGLWidget (docs/pitfalls.md, "VTK in a Qt 6 widget"). This class is the
// host: GL lifetime, keeping the scene in step with the document at the playhead (viewport.cpp),
// the camera, and pointer and key events (viewport_events.cpp), handed to the active tool. The VTK
// scene, the camera's maths, the frame composition and the displayed shape have files of their
// own (viewport_*.h); the drawing options are display(), the reference drawing drawingOverlay(),
// and each editing tool owns its settings (tools/, reached with tool<T>()).
#pragma once

#include "celform/algorithms/brush.h"
#include "celform/model/data/camera.h"
#include "celform/model/document/change_set.h"
#include "celform/model/data/project_data.h"
#include "celform/views/tools/viewport_tool.h"

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

class AxisGizmo;
class BrushSize;
class ControlCage;
class DisplayedShape;
class DrawingOverlay;
class ViewportCamera;
class ViewportCompositor;
class ViewportDisplay;
class ViewportScene;
class SubdividedDisplay;

enum class NavigationStyle { Maya, Blender };
enum class OrbitMode { Turntable, Trackball };

/// Edit > Preferences: how the mouse navigates.
struct Navigation {
    /// Maya: Alt + left orbit, Alt + middle pan, Alt + right dolly (and the middle-button
    /// equivalents). Blender: middle orbit, Shift + middle pan, Ctrl + middle dolly; Alt + left
    /// drag goes to the tool.
    NavigationStyle style = NavigationStyle::Maya;
    OrbitMode orbitMode = OrbitMode::Turntable;
    /// Multiplies the orbit's degrees per pixel (1: 0.4 degrees per pixel).
    double orbitSpeed = 1.0;
    /// Orbit turns around the surface point under the cursor where the drag starts (Maya's
    /// tumble pivot); elsewhere, and when off, around the framed centre moved by panning.
    bool orbitAroundCursor = false;
};

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
    /// Wall times of the last paintGL, ms: the whole frame (VTK render, readbacks, lines, stereo
    /// composition) and the line extraction and drawing alone.
    struct FrameTimes {
        double frame = 0.0;
        double lines = 0.0;
    };
    [[nodiscard]] FrameTimes lastFrameTimes() const;

    /// How the model is drawn: look or clay, the light gizmo, lines, stereo.
    [[nodiscard]] ViewportDisplay& display() const { return *m_display; }
    /// The centre of the model's bounds (the light gizmo turns about it).
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
    /// The view direction of this camera, from the base centroid towards the eye (DESIGN.md).
    [[nodiscard]] Eigen::Vector3d viewDirection() const;
    /// The control shape shown (#V by 3): base, key or blend, brought up to date first. The
    /// surface on screen is its subdivision at the displayed level (issue 25); tools edit this.
    [[nodiscard]] const algo::Positions& displayedShape();
    /// The generation of the shape displayedShape() returns (algo::Shape): caches compare it.
    [[nodiscard]] std::uint64_t displayedShapeGeneration();
    /// The shading offsets in effect for the shape shown (model::effectiveShadingOffsets: the base
    /// layer, plus the key's layer for a key's shape, plus the blended key layers for the blend);
    /// empty for none. Brought up to date first.
    [[nodiscard]] const std::vector<float>& displayedShadingOffsets();

    /// The reference drawing fixed in the viewport, its height filling the view.
    [[nodiscard]] DrawingOverlay& drawingOverlay() const { return *m_overlay; }

    // --- tools (views/tools/, one file each) ---------------------------------------------------
    enum class Tool {
        Navigate, ///< mouse only navigates
        Align, ///< navigation edits the overlay drawing's camera (one undo step per gesture)
        Brush, ///< left drag deforms the displayed key at the playhead (paper 1, section 3.1.2)
        Highlight, ///< left drag moves, rotates or scales the highlight target (one undo step)
        Patch, ///< left drag paints faces into the patch target (Ctrl+drag removes them)
        OffsetBrush, ///< left drag paints shading offsets into the tool's target (paper 3, 4.3)
    };
    void setTool(Tool tool);
    [[nodiscard]] Tool tool() const { return m_tool; }
    /// The tool of type T (BrushTool, AlignTool, ...): its settings and state live there.
    template <class T> [[nodiscard]] T& tool() const;

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

    /// Edit > Preferences: how the mouse navigates.
    void setNavigation(const Navigation& navigation);

    /// Whether the active tool takes this key press before the window's shortcuts (the brush's F,
    /// [ and ], Esc or Enter while resizing). The window sends such presses here wherever the
    /// focus is, so a tool's keys win inside it.
    [[nodiscard]] bool toolTakesKey(const QKeyEvent& event) const;
    [[nodiscard]] const Navigation& navigation() const { return m_navigation; }

public slots:
    /// Keeps the view direction and fits the whole model in the view; refused with a message while
    /// the tool holds a document camera (ViewportTool::holdsCamera: aligning, brushing a key), as
    /// are the preset views and the reset view.
    void frameAll();
    /// Front view (looking down -Z, Y up), framed.
    void resetView();

signals:
    /// Emitted after every navigation step and every programmatic camera change.
    void cameraChanged();
    void toolChanged(celform::views::Viewport::Tool tool);
    /// A message for the status bar (brush refused, nothing picked, ...): the tools' relayed.
    void message(const QString& text);

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
    /// Keeps the stored camera when the drawing frame's share of the viewport changes.
    void refreshFrameScale();
    /// Look shader on or off (enabled, a mesh, no selection colours), background and grid to match.
    void applyShadingState();
    void updateLightGizmo();
    /// After every camera change: keeps the view up, the preview's blend, the tool and listeners
    /// in step.
    void cameraEdited();
    void endDrag(bool cancelled);
    /// frameAll without the tool's refusal: the program's own framing (first paint, a resize).
    void placeFramed();
    /// True, with a status-bar message naming the action, while the active tool holds a document
    /// camera (aligning, brushing a key): framing must not move that camera.
    bool refusedWhileHeld(const QString& action);
    [[nodiscard]] ViewportTool* activeTool() const;
    /// Every tool: the ones setTool() picks and the light gizmo's drag.
    [[nodiscard]] std::vector<ViewportTool*> allTools() const;
    /// The displayed level follows the display settings: a new topology goes to the scene.
    void syncSubdivision();
    /// The brush selection shown in red (brush tool), or none.
    void showBrushSelection(const algo::BrushSelection* selection, const algo::BrushSelection* mirror);
    /// The look's state (shader, background, gizmo) again after a display setting changed.
    void displayChanged(bool shading);
    /// Recomputes m_shadingOffsets for the displayed shape's source at the playhead.
    void updateShadingOffsets(const Eigen::Vector3d& direction);
    /// The document's look, or the default one without a document.
    [[nodiscard]] const model::Look& currentLook() const;

    model::Document* m_document;
    std::unique_ptr<ViewportScene> m_scene;
    std::unique_ptr<ViewportCamera> m_camera;
    std::unique_ptr<ViewportCompositor> m_compositor;
    std::unique_ptr<DisplayedShape> m_shape; ///< the control shape at the playhead
    std::unique_ptr<SubdividedDisplay> m_surface; ///< what is displayed of it (issue 25)
    std::unique_ptr<ControlCage> m_cage;
    std::unique_ptr<ViewportDisplay> m_display;
    DrawingOverlay* m_overlay; ///< child QObject
    BrushSize* m_brushSize; ///< child QObject, the radius the brushes share
    std::vector<float> m_shadingOffsets; ///< in effect for m_shape (displayedShadingOffsets)
    std::vector<float> m_surfaceOffsets; ///< m_shadingOffsets on the displayed surface
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
    bool m_lookStale = true; ///< the look's per-vertex data needs refreshing before a paint
    bool m_patchStale = true;
    std::uint64_t m_uploadedGeneration = 0; ///< of the shape in the VTK arrays

    Tool m_tool = Tool::Navigate;
    Navigation m_navigation;
    double m_frameMilliseconds = 0.0;
};

template <class T> T& Viewport::tool() const
{
    for (ViewportTool* t : allTools())
        if (auto* found = dynamic_cast<T*>(t))
            return *found;
    Q_UNREACHABLE(); // every tool type is made in the constructor
}

} // namespace celform::views
