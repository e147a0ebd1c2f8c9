// The viewport host: the QOpenGLWidget VTK draws into (STACK.md pitfall 5), its events, and the
// bookkeeping that keeps the scene in step with the document at the playhead. Document changes
// only mark things stale; a paint (or a pick) brings them up to date, so a hidden viewport does no
// work and a brush step costs its listeners almost nothing.
#include "celform/views/viewport/viewport.h"

#include "celform/model/document/document.h"
#include "celform/model/data/shading_layers.h"
#include "celform/model/render/render_output.h"
#include "celform/views/viewport/look_shading.h"
#include "celform/views/tools/align_tool.h"
#include "celform/views/tools/brush_tool.h"
#include "celform/views/tools/highlight_tool.h"
#include "celform/views/tools/light_tool.h"
#include "celform/views/tools/offset_brush_tool.h"
#include "celform/views/tools/patch_tool.h"
#include "celform/views/viewport/axis_gizmo.h"
#include "celform/views/overlays/drawing_outline.h"
#include "celform/views/viewport/viewport_camera.h"
#include "celform/views/viewport/viewport_compositor.h"
#include "celform/views/viewport/viewport_scene.h"
#include "celform/views/viewport/displayed_shape.h"

#include <QElapsedTimer>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QWheelEvent>

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkNew.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace celform::views {
Viewport::Viewport(model::Document* document, QWidget* parent)
    : QOpenGLWidget(parent)
    , m_document(document)
    , m_scene(std::make_unique<ViewportScene>())
    , m_camera(std::make_unique<ViewportCamera>(m_scene->renderer()))
    , m_compositor(std::make_unique<ViewportCompositor>(this, *m_scene, *m_camera))
    , m_shape(std::make_unique<DisplayedShape>())
{
    setFocusPolicy(Qt::StrongFocus);
    setMinimumSize(64, 64);
    m_axisGizmo = new AxisGizmo(this);
    setMouseTracking(true); // hover feedback: the brush circle
    setAccessibleName(tr("3D viewport"));
    setWhatsThis(tr("<p>The 3D view of the model.</p>"
                    "<p>Alt+left drag or middle drag: orbit. Alt+middle drag or Shift+middle drag: pan. "
                    "Alt+right drag, Ctrl+middle drag or the mouse wheel: dolly. "
                    "F: frame the model. Home: front view.</p>"
                    "<p>Ctrl+left drag on the light gizmo (the yellow arrow or sphere): move the key light "
                    "around the model.</p>"));

    // VTK asks for the context when it releases resources outside paintGL. An unconditional
    // makeCurrent() would re-bind Qt's framebuffer behind VTK's cached state (black viewport).
    vtkNew<vtkCallbackCommand> makeCurrent;
    makeCurrent->SetClientData(this);
    makeCurrent->SetCallback([](vtkObject*, unsigned long, void* clientData, void*) {
        auto* self = static_cast<Viewport*>(clientData);
        if (self->context() && QOpenGLContext::currentContext() != self->context())
            self->makeCurrent();
    });
    m_scene->window()->AddObserver(vtkCommand::WindowMakeCurrentEvent, makeCurrent);

    // The tools, one file each: adding one is a file and a line here (and its Tool value).
    m_tools[Tool::Align] = std::make_unique<AlignTool>(this);
    m_tools[Tool::Brush] = std::make_unique<BrushTool>(this);
    m_tools[Tool::Patch] = std::make_unique<PatchTool>(this);
    m_tools[Tool::Highlight] = std::make_unique<HighlightTool>(this);
    m_tools[Tool::OffsetBrush] = std::make_unique<OffsetBrushTool>(this);
    m_lightTool = std::make_unique<LightTool>(this);

    if (m_document)
        connect(m_document, &model::Document::changed, this, &Viewport::documentChanged);
    m_wheelBurst.setSingleShot(true);
    m_wheelBurst.setInterval(400);
    connect(&m_wheelBurst, &QTimer::timeout, this, [this] {
        if (ViewportTool* tool = activeTool())
            tool->navigationEnded();
    });
    rebuildMesh();
    resetView();
}

Viewport::~Viewport()
{
    // The base class destroys the context after our members are gone: drop the connection first.
    if (context())
        disconnect(context(), &QOpenGLContext::aboutToBeDestroyed, this, nullptr);
    releaseGraphics();
    m_scene->window()->RemoveObservers(vtkCommand::WindowMakeCurrentEvent);
}

QSurfaceFormat Viewport::defaultFormat()
{
    QSurfaceFormat format;
    format.setRenderableType(QSurfaceFormat::OpenGL);
    format.setVersion(3, 2);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    format.setStencilBufferSize(8);
    format.setAlphaBufferSize(8);
    // Single-sampled on purpose: VTK blits its frame into Qt's framebuffer, and a blit into a
    // multisampled framebuffer is invalid in OpenGL. VTK multisamples its own buffer instead.
    // (Under Xvfb's llvmpipe GLX offers no multisampled configs anyway: a request for 4 gave 0.)
    format.setSamples(0);
    return format;
}

// --- document ---------------------------------------------------------------------------------

void Viewport::documentChanged(const model::ChangeSet& change)
{
    using model::Part;
    if (change.onlyPlayhead() && !m_document->hasMesh())
        return;
    if (change.reset) {
        if (m_drag != Drag::None)
            endDrag(true);
        m_displayedKey = 0;
        m_overlayDrawing = 0;
        setTool(Tool::Navigate);
        m_shape->setSource(m_preview ? DisplayedShape::Source::Blend : DisplayedShape::Source::Base);
        rebuildMesh();
        updateOverlay();
        resetView();
        // A project with a render camera opens looking through it, as a shot would.
        if (const auto& shot = m_document->data().look.renderCamera)
            setCamera(*shot);
        update();
        return;
    }
    if (change.has(Part::Mesh))
        rebuildMesh();
    if (change.has(Part::Keys) && m_displayedKey && !m_document->data().key(m_displayedKey)) {
        m_displayedKey = 0;
        showBrushSelection(nullptr, nullptr);
        m_shape->setSource(m_preview || m_observed ? DisplayedShape::Source::Blend : DisplayedShape::Source::Base);
    }
    bool repaint = m_shape->noteChange(change);
    if (change.has(Part::Drawings) && (change.structure || change.touches(m_overlayDrawing))) {
        updateOverlay();
        repaint = true;
    }
    if (change.has(Part::Look)) {
        updateLightGizmo();
        applyShadingState();
    }
    if (change.has(Part::Look) || change.has(Part::Highlights) || change.has(Part::FaceSets)
        || change.has(Part::ShadingOffsets) || change.has(Part::Playhead)) {
        m_lookStale = true;
        repaint = true;
    }
    if (change.has(Part::FaceSets)) {
        m_patchStale = true;
        repaint = true;
    }
    if (repaint)
        update();
}

void Viewport::rebuildMesh()
{
    const auto mesh = (m_document && m_document->hasMesh()) ? m_document->data().baseMesh : nullptr;
    m_scene->setMesh(mesh.get());
    m_compositor->clearLines();
    m_shape->invalidate();
    m_uploadedGeneration = 0;
    m_lookStale = true;
    m_patchStale = true;
    showBrushSelection(nullptr, nullptr);
    Eigen::AlignedBox3d bounds(Eigen::Vector3d::Constant(-1.0), Eigen::Vector3d::Constant(1.0));
    if (mesh && mesh->vertexCount() > 0)
        bounds = algo::boundingBox(mesh->vertices);
    m_camera->setBounds(bounds);
    m_scene->rebuildGrid(m_camera->bounds());
    updateLightGizmo();
    applyShadingState();
}

void Viewport::syncScene()
{
    if (!m_document || !m_document->hasMesh() || !m_scene->hasMesh())
        return;
    const model::ProjectData& data = m_document->data();
    const Eigen::Vector3d direction = m_observed ? m_observed->viewDirection() : viewDirection();
    if (m_shape->refresh(*m_document, direction))
        ++m_shapeUpdates;
    const algo::Shape& shape = m_shape->shape();
    if (shape.positions.rows() != data.baseMesh->vertexCount())
        return; // a mesh change is on its way
    if (shape.generation != m_uploadedGeneration) {
        m_scene->uploadShape(shape.positions, m_shape->normals());
        m_uploadedGeneration = shape.generation;
        m_lookStale = true;
        m_patchStale = true;
    }
    // The look's per-vertex data only when the look is drawn (the brush's clay look skips it).
    if (m_lookStale && m_shadingEnabled && !m_scene->selectionShown()) {
        updateShadingOffsets(direction);
        m_scene->look().update(data, shape.positions, m_shape->normals().data(), m_document->currentFrame(),
            shape.generation, &m_shadingOffsets);
        m_lookStale = false;
    }
    if (m_patchStale) {
        const algo::FaceSet* set = m_tool == Tool::Patch ? data.faceSet(m_patchTarget) : nullptr;
        // Lifted by a thousandth of the model's size along the normals: no depth fighting with
        // the model under it, and too little to see.
        m_scene->setPatchOverlay(shape.positions, m_shape->normals(), data.baseMesh->faces, set,
            float(1e-3 * m_camera->bounds().diagonal().norm()));
        m_patchStale = false;
    }
}

const algo::Positions& Viewport::displayedShape()
{
    syncScene();
    return m_shape->positions();
}

void Viewport::updateShadingOffsets(const Eigen::Vector3d& direction)
{
    // The layers that belong to the shape shown: a key's shape carries its own layer whole, the
    // blend the key layers with the blend's weights (paper 3, eq. 4.3 per layer).
    const model::ProjectData& data = m_document->data();
    const int frame = m_document->currentFrame();
    switch (m_shape->source()) {
    case DisplayedShape::Source::Base:
        model::effectiveShadingOffsets(data, {}, frame, m_shadingOffsets);
        break;
    case DisplayedShape::Source::Key:
        model::effectiveShadingOffsets(data, {{m_shape->key(), 1.0}}, frame, m_shadingOffsets);
        break;
    case DisplayedShape::Source::Blend:
        model::effectiveShadingOffsets(data, m_document->blender(), direction, frame, m_shadingOffsets);
        break;
    }
}

const std::vector<float>& Viewport::displayedShadingOffsets()
{
    syncScene();
    if (m_document && m_document->hasMesh())
        updateShadingOffsets(m_observed ? m_observed->viewDirection() : viewDirection());
    return m_shadingOffsets;
}

std::uint64_t Viewport::displayedShapeGeneration()
{
    syncScene();
    return m_shape->shape().generation;
}

// --- camera -----------------------------------------------------------------------------------

model::Camera Viewport::camera() const
{
    return m_camera->camera();
}

void Viewport::setCamera(const model::Camera& camera)
{
    if (!m_camera->setCamera(camera))
        return;
    m_scene->cameraPlaced = true;
    cameraEdited();
}

void Viewport::setProjection(model::Projection projection)
{
    if (projection == m_camera->projection())
        return;
    m_camera->setProjection(projection);
    cameraEdited();
}

model::Projection Viewport::projection() const
{
    return m_camera->projection();
}

Eigen::Vector3d Viewport::pivot() const
{
    return m_camera->pivot();
}

void Viewport::frameAll()
{
    m_camera->frameAll();
    m_scene->cameraPlaced = true;
    cameraEdited();
}

void Viewport::resetView()
{
    m_camera->resetView();
    m_scene->cameraPlaced = true;
    cameraEdited();
}

void Viewport::setViewPreset(ViewPreset preset)
{
    // The eye's side of the model and the up vector of each view (Y up; top looks down with -Z up).
    Eigen::Vector3d side = Eigen::Vector3d::UnitZ(), up = Eigen::Vector3d::UnitY();
    switch (preset) {
    case ViewPreset::Front:
        break;
    case ViewPreset::Back:
        side = -Eigen::Vector3d::UnitZ();
        break;
    case ViewPreset::Right:
        side = Eigen::Vector3d::UnitX();
        break;
    case ViewPreset::Left:
        side = -Eigen::Vector3d::UnitX();
        break;
    case ViewPreset::Top:
        side = Eigen::Vector3d::UnitY();
        up = -Eigen::Vector3d::UnitZ();
        break;
    case ViewPreset::Bottom:
        side = -Eigen::Vector3d::UnitY();
        up = Eigen::Vector3d::UnitZ();
        break;
    }
    m_camera->viewFrom(side, up);
    m_scene->cameraPlaced = true;
    cameraEdited();
}

void Viewport::setOrbitMode(OrbitMode mode)
{
    m_camera->setTrackball(mode == OrbitMode::Trackball);
}

OrbitMode Viewport::orbitMode() const
{
    return m_camera->isTrackball() ? OrbitMode::Trackball : OrbitMode::Turntable;
}

void Viewport::setOrbitSpeed(double factor)
{
    if (std::isfinite(factor) && factor > 0.0)
        m_orbitSpeed = factor;
}

void Viewport::cameraEdited()
{
    if (m_preview)
        m_shape->viewChanged();
    if (ViewportTool* tool = activeTool())
        tool->cameraChanged();
    update();
    emit cameraChanged();
}

double Viewport::worldUnitsPerPixel(const Eigen::Vector3d& point) const
{
    return m_camera->worldUnitsPerPixel(point);
}

QPointF Viewport::projectToWidget(const Eigen::Vector3d& point) const
{
    return m_camera->projectToWidget(point);
}

std::pair<Eigen::Vector3d, Eigen::Vector3d> Viewport::rayThrough(const QPointF& position) const
{
    return m_camera->rayThrough(position);
}

Eigen::Vector3d Viewport::viewDirection() const
{
    if (!m_document || !m_document->hasMesh())
        return Eigen::Vector3d::Zero();
    return model::viewDirectionFromEye(m_document->data(), camera().eye, m_document->currentFrame());
}

// --- what is shown ----------------------------------------------------------------------------

void Viewport::setDisplayedKey(model::ObjectId key)
{
    if (key == m_displayedKey && !m_preview)
        return;
    m_displayedKey = key;
    m_preview = false;
    showBrushSelection(nullptr, nullptr);
    m_shape->setSource(m_observed ? DisplayedShape::Source::Blend
            : key                 ? DisplayedShape::Source::Key
                                  : DisplayedShape::Source::Base,
        key);
    update();
}

void Viewport::setPreview(bool on)
{
    if (on == m_preview)
        return;
    m_preview = on;
    if (on)
        m_displayedKey = 0;
    showBrushSelection(nullptr, nullptr);
    m_shape->setSource(on || m_observed ? DisplayedShape::Source::Blend : DisplayedShape::Source::Base);
    update();
}

void Viewport::setObserved(Viewport* driver)
{
    if (m_observed)
        disconnect(m_observed, nullptr, this, nullptr);
    m_observed = driver;
    if (driver)
        connect(driver, &Viewport::cameraChanged, this, [this] {
            // Only marks the blend stale: a hidden observer (a closed dock) costs nothing.
            m_shape->viewChanged();
            update();
        });
    m_shape->setSource(driver || m_preview ? DisplayedShape::Source::Blend
            : m_displayedKey               ? DisplayedShape::Source::Key
                                           : DisplayedShape::Source::Base,
        m_displayedKey);
    update();
}

vtkRenderer* Viewport::modelRenderer() const
{
    return m_scene->renderer();
}

// --- reference drawing overlay ----------------------------------------------------------------

void Viewport::setOverlayDrawing(model::ObjectId drawing)
{
    if (drawing == m_overlayDrawing)
        return;
    // Aligning is bound to its drawing: showing another ends it (storing what was aligned).
    if (m_tool == Tool::Align)
        setTool(Tool::Navigate);
    m_overlayDrawing = drawing;
    if (!matchedModelPoints().empty() || !matchedDrawingPoints().empty())
        clearMatchedPoints(); // the pairs belong to the drawing they were placed on
    updateOverlay();
}

void Viewport::setOverlayOnTop(bool onTop)
{
    if (onTop == m_overlayOnTop)
        return;
    m_overlayOnTop = onTop;
    updateOverlay();
}

void Viewport::updateOverlay()
{
    const model::Drawing* drawing
        = (m_document && m_overlayDrawing) ? m_document->data().drawing(m_overlayDrawing) : nullptr;
    if (!drawing) {
        m_overlayDrawing = 0;
        if (m_tool == Tool::Align)
            setTool(Tool::Navigate);
    }
    const QImage* image = drawing ? &drawing->image : nullptr;
    if (drawing && m_overlayOutline) {
        if (m_outlineSource != drawing->image.cacheKey() || m_outline.isNull()) {
            m_outline = drawingOutline(drawing->image);
            m_outlineSource = drawing->image.cacheKey();
        }
        image = &m_outline;
    }
    // The outline is drawn over the model at full strength: it is thin.
    m_scene->setDrawing(
        image, m_overlayOnTop || m_overlayOutline, drawing ? (m_overlayOutline ? 1.0 : drawing->opacity) : 1.0);
    refreshFrameScale();
    update();
}

void Viewport::setOverlayOutline(bool on)
{
    if (on == m_overlayOutline)
        return;
    m_overlayOutline = on;
    updateOverlay();
}

double Viewport::wantedFrameScale() const
{
    const model::Drawing* drawing
        = (m_document && m_overlayDrawing) ? m_document->data().drawing(m_overlayDrawing) : nullptr;
    if (!drawing || drawing->image.isNull() || width() <= 0 || height() <= 0)
        return 1.0;
    // The drawing fits inside the viewport; the camera's frame is the drawing's frame.
    const double fit = std::min(double(width()) / drawing->image.width(), double(height()) / drawing->image.height());
    return std::max(1.0, double(height()) / (fit * drawing->image.height()));
}

void Viewport::refreshFrameScale()
{
    const double wanted = wantedFrameScale();
    if (wanted != m_camera->frameScale()) {
        m_camera->setFrameScale(wanted);
        cameraEdited();
    }
    m_scene->fitDrawing(width(), height());
}

std::optional<Eigen::Vector2d> Viewport::widgetToDrawing(const QPointF& position) const
{
    const model::Drawing* drawing
        = (m_document && m_overlayDrawing) ? m_document->data().drawing(m_overlayDrawing) : nullptr;
    if (!drawing || drawing->image.isNull())
        return std::nullopt;
    const double w = drawing->image.width(), h = drawing->image.height();
    const double fit = std::min(double(width()) / w, double(height()) / h);
    const double x = (position.x() - 0.5 * (width() - fit * w)) / fit;
    const double y = (position.y() - 0.5 * (height() - fit * h)) / fit;
    if (x < 0 || y < 0 || x > w || y > h)
        return std::nullopt;
    return Eigen::Vector2d(x, y);
}

QPointF Viewport::drawingToWidget(const Eigen::Vector2d& pixel) const
{
    const model::Drawing* drawing
        = (m_document && m_overlayDrawing) ? m_document->data().drawing(m_overlayDrawing) : nullptr;
    if (!drawing || drawing->image.isNull())
        return {};
    const double w = drawing->image.width(), h = drawing->image.height();
    const double fit = std::min(double(width()) / w, double(height()) / h);
    return {0.5 * (width() - fit * w) + fit * pixel.x(), 0.5 * (height() - fit * h) + fit * pixel.y()};
}

// --- the look and its key light ---------------------------------------------------------------

void Viewport::setBackgroundColors(const QColor& top, const QColor& bottom)
{
    m_scene->setClayBackground(top, bottom);
    applyShadingState(); // the look's background replaces these while it is shown
    update();
}

void Viewport::setShadingEnabled(bool on)
{
    if (on == m_shadingEnabled)
        return;
    m_shadingEnabled = on;
    applyShadingState();
    update();
}

void Viewport::setLightGizmoVisible(bool on)
{
    if (on == m_lightGizmoVisible)
        return;
    m_lightGizmoVisible = on;
    applyShadingState();
    update();
}

void Viewport::applyShadingState()
{
    const bool hasMesh = m_document && m_document->hasMesh() && m_scene->hasMesh();
    // Brush selection colours are VTK scalars, shown by the clay material: the look steps aside
    // while they are displayed rather than tinting its tones (which would read as a tone change).
    const bool active = m_shadingEnabled && hasMesh && !m_scene->selectionShown();
    const Eigen::Vector3f background
        = m_document ? m_document->data().look.backgroundColor : model::Look{}.backgroundColor;
    m_scene->applyShading(
        active, m_shadingEnabled && hasMesh, background, m_lightGizmoVisible && m_shadingEnabled && hasMesh);
    if (active)
        m_lookStale = true;
}

Eigen::Vector3d Viewport::modelCentre() const
{
    return m_camera->bounds().center();
}

double Viewport::lightGizmoRadius() const
{
    return std::max(0.5 * m_camera->bounds().diagonal().norm(), 1e-6);
}

bool Viewport::lightGizmoShown() const
{
    return m_scene->lightGizmoVisible();
}

Eigen::Vector3d Viewport::lightGizmoHandle() const
{
    const model::Light light = m_document ? m_document->data().look.light : model::Light{};
    if (light.type == model::LightType::Point)
        return light.vector;
    Eigen::Vector3d direction = light.vector.normalized();
    if (!direction.allFinite())
        direction = Eigen::Vector3d::UnitZ();
    return modelCentre() + 1.3 * lightGizmoRadius() * direction;
}

void Viewport::updateLightGizmo()
{
    m_scene->setLightGizmo(
        m_document ? m_document->data().look.light : model::Light{}, modelCentre(), lightGizmoRadius());
}

const model::Look& Viewport::currentLook() const
{
    static const model::Look defaultLook;
    return m_document ? m_document->data().look : defaultLook;
}

// --- stereo and lines -------------------------------------------------------------------------------

void Viewport::setStereo(algo::StereoOutput output)
{
    if (output == m_stereo)
        return;
    m_stereo = output;
    update();
}

void Viewport::setStereoLook(const std::optional<model::StereoLook>& look)
{
    m_stereoLook = look;
    update();
}

model::StereoLook Viewport::stereoLook() const
{
    if (m_stereoLook)
        return *m_stereoLook;
    return m_document ? m_document->data().look.stereo : model::StereoLook{};
}

algo::StereoSettings Viewport::resolvedStereoSettings() const
{
    // The centroid of the base model, as the offline path (model::renderShape) uses.
    const bool mesh = m_document && m_document->hasMesh() && m_document->data().baseMesh->vertices.rows() > 0;
    const Eigen::Vector3d centroid = mesh ? m_document->data().baseMesh->centre() : modelCentre();
    return model::resolvedStereo(stereoLook(), camera(), centroid);
}

void Viewport::setLinesOverride(std::optional<bool> show)
{
    m_linesOverride = show;
    update();
}

bool Viewport::linesShown() const
{
    if (!m_document || !m_document->hasMesh())
        return false;
    return m_linesOverride.value_or(m_document->data().look.showLines);
}

void Viewport::setEyeOnly(Eye eye)
{
    m_eyeOnly = eye;
    update();
}

double Viewport::lastLineMilliseconds() const
{
    return m_compositor->lastLineMilliseconds();
}

QImage Viewport::renderedImage()
{
    return grabFramebuffer();
}

// --- OpenGL ---------------------------------------------------------------------------------

void Viewport::showEvent(QShowEvent* event)
{
    QOpenGLWidget::showEvent(event);
    update(); // catch up with what changed while hidden
}

void Viewport::initializeGL()
{
    vtkGenericOpenGLRenderWindow* window = m_scene->window();
    // On a software rasteriser (Mesa llvmpipe under Xvfb, remote desktops) 4x multisampling
    // halves the frame rate: interaction matters more there. CELFORM_MSAA overrides.
    const auto* renderer = reinterpret_cast<const char*>(context()->functions()->glGetString(GL_RENDERER));
    const bool software = renderer
        && (std::strstr(renderer, "llvmpipe") || std::strstr(renderer, "softpipe")
            || std::strstr(renderer, "Software"));
    bool overridden = false;
    const int samples = qEnvironmentVariableIntValue("CELFORM_MSAA", &overridden);
    window->SetMultiSamples(overridden ? std::clamp(samples, 0, 16) : (software ? 0 : 4));
    window->SetReadyForRendering(false);
    window->InitializeFromCurrentContext();
    window->SetFrameBlitModeToBlitToCurrent();
    window->SetReadyForRendering(true);
    m_initialized = true;
    // Reparenting to another window replaces the context: VTK's objects die with the old one.
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &Viewport::releaseGraphics, Qt::UniqueConnection);
}

void Viewport::releaseGraphics()
{
    if (!m_initialized || !context())
        return;
    makeCurrent();
    m_scene->window()->ReleaseGraphicsResources(m_scene->window());
    m_initialized = false;
    doneCurrent();
}

void Viewport::resizeGL(int w, int h)
{
    const qreal dpr = devicePixelRatioF();
    m_scene->window()->SetSize(qRound(w * dpr), qRound(h * dpr));
    m_camera->setWidgetSize(w, h, dpr);
    m_axisGizmo->move(width() - m_axisGizmo->width() - 6, 6);
    if (AlignTool* align = alignTool())
        align->resized();
    refreshFrameScale();
    // A view framed by the program (load, F, Home) stays framed while the window is resized:
    // the widget's first size is only known here, after the constructor framed the model.
    if (m_camera->isFramed())
        frameAll();
}

void Viewport::paintGL()
{
    if (!m_initialized)
        return;
    if (!m_scene->cameraPlaced)
        frameAll();
    QElapsedTimer timer;
    timer.start();
    syncScene();
    ViewportCompositor::Frame frame;
    frame.shape = &m_shape->shape();
    frame.mesh = m_document && m_document->hasMesh() ? m_document->data().baseMesh.get() : nullptr;
    frame.look = &currentLook();
    frame.lines = linesShown();
    frame.stereo = m_stereo;
    if (m_stereo != algo::StereoOutput::Off) {
        frame.stereoSettings = resolvedStereoSettings();
        frame.dubois = stereoLook().dubois;
    }
    frame.eyeOnly = m_eyeOnly == Eye::Left ? ViewportCompositor::Eye::Left
        : m_eyeOnly == Eye::Right          ? ViewportCompositor::Eye::Right
                                           : ViewportCompositor::Eye::Both;
    m_compositor->paint(frame);
    m_frameMilliseconds = double(timer.nsecsElapsed()) / 1e6;
    ++m_renderCount;
}

} // namespace celform::views
