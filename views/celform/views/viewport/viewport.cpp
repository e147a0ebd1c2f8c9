// The viewport host: the QOpenGLWidget VTK draws into (docs/pitfalls.md, "VTK in a Qt 6 widget"), its events, and the
// bookkeeping that keeps the scene in step with the document at the playhead. Document changes
// only mark things stale; a paint (or a pick) brings them up to date, so a hidden viewport does no
// work and a brush step costs its listeners almost nothing.
#include "celform/views/viewport/viewport.h"

#include "celform/model/document/document.h"
#include "celform/model/data/shading_layers.h"
#include "celform/model/render/render_output.h"
#include "celform/views/viewport/look_shading.h"
#include "celform/views/tools/align_tool.h"
#include "celform/views/tools/brush_size.h"
#include "celform/views/tools/brush_tool.h"
#include "celform/views/tools/highlight_tool.h"
#include "celform/views/tools/light_tool.h"
#include "celform/views/tools/offset_brush_tool.h"
#include "celform/views/tools/patch_tool.h"
#include "celform/views/viewport/axis_gizmo.h"
#include "celform/views/overlays/drawing_overlay.h"
#include "celform/views/viewport/viewport_camera.h"
#include "celform/views/viewport/viewport_compositor.h"
#include "celform/views/viewport/viewport_display.h"
#include "celform/views/viewport/viewport_scene.h"
#include "celform/views/viewport/control_cage.h"
#include "celform/views/viewport/displayed_shape.h"
#include "celform/views/viewport/subdivided_display.h"

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
    , m_surface(std::make_unique<SubdividedDisplay>())
    , m_cage(std::make_unique<ControlCage>(m_scene->renderer()))
    , m_display(
          std::make_unique<ViewportDisplay>(document, *m_camera, [this](bool shading) { displayChanged(shading); }))
    , m_overlay(new DrawingOverlay(document, this))
    , m_brushSize(new BrushSize(this))
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

    // The tools, one file each: adding one is a file and a line here (and its Tool value). The
    // brushes share one radius; each tool's messages go to the status bar through this widget.
    m_tools[Tool::Align] = std::make_unique<AlignTool>(this);
    auto brush = std::make_unique<BrushTool>(this, *m_brushSize);
    connect(brush.get(), &BrushTool::selectionChanged, this, &Viewport::showBrushSelection);
    m_tools[Tool::Brush] = std::move(brush);
    auto patch = std::make_unique<PatchTool>(this, *m_brushSize);
    connect(patch.get(), &PatchTool::targetChanged, this, [this] {
        m_patchStale = true;
        update();
    });
    m_tools[Tool::Patch] = std::move(patch);
    m_tools[Tool::Highlight] = std::make_unique<HighlightTool>(this);
    m_tools[Tool::OffsetBrush] = std::make_unique<OffsetBrushTool>(this, *m_brushSize);
    m_lightTool = std::make_unique<LightTool>(this);
    for (ViewportTool* tool : allTools())
        connect(tool, &ViewportTool::message, this, &Viewport::message);

    // Showing another drawing ends aligning to the old one first (storing what was aligned).
    connect(m_overlay, &DrawingOverlay::drawingAboutToChange, this, [this] {
        if (m_tool == Tool::Align)
            setTool(Tool::Navigate);
    });
    connect(m_overlay, &DrawingOverlay::changed, this, &Viewport::updateOverlay);
    // Why the outline mode has no outline to show goes to the status bar as well as the banner.
    connect(m_overlay, &DrawingOverlay::outlineProblemChanged, this, [this](const QString& problem) {
        if (!problem.isEmpty())
            emit message(problem);
    });

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
        m_overlay->forget(); // before the align tool ends: nothing of the old document is stored
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
    if (change.has(Part::Drawings) && (change.structure || change.touches(m_overlay->drawing()))) {
        updateOverlay();
        repaint = true;
    }
    // With a light track the light follows the playhead too.
    if (change.has(Part::Look) || (change.has(Part::Playhead) && !m_document->data().look.lightTrack.empty())) {
        updateLightGizmo();
        applyShadingState();
        repaint = true; // the subdivision levels are in the look
    }
    // The subdivided stand-in project carries the face sets and base offsets through the stencil.
    if (change.has(Part::FaceSets) || change.has(Part::ShadingOffsets) || change.has(Part::FaceValues))
        m_surface->invalidate();
    if (change.has(Part::Look) || change.has(Part::Highlights) || change.has(Part::FaceSets)
        || change.has(Part::ShadingOffsets) || change.has(Part::Playhead)) {
        m_lookStale = true;
        repaint = true;
    }
    if (change.has(Part::FaceSets) || change.has(Part::FaceValues)) {
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
    m_surface->invalidate();
    m_cage->show(nullptr, nullptr);
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

void Viewport::syncSubdivision()
{
    const model::ProjectData& data = m_document->data();
    if (!m_surface->setLevel(data, m_display->subdivision().level))
        return;
    // A new topology on screen: the scene's arrays, the lines' edges and the per-vertex look are
    // made again; brush colours of the old vertices are dropped (the next brush hover shows them).
    m_scene->setMesh(m_surface->view(data, *m_shape).mesh);
    m_compositor->clearLines();
    m_uploadedGeneration = 0;
    m_lookStale = true;
    m_patchStale = true;
    if (m_scene->selectionShown()) {
        m_scene->setSelectionColors(nullptr, nullptr, 0);
        applyShadingState();
    }
}

void Viewport::syncScene()
{
    if (!m_document || !m_document->hasMesh() || !m_scene->hasMesh())
        return;
    const model::ProjectData& data = m_document->data();
    const Eigen::Vector3d direction = m_observed ? m_observed->viewDirection() : viewDirection();
    syncSubdivision();
    // The VTK arrays hold the displayed shape as it is before this refresh: a partial refresh
    // needs only its rows uploaded.
    const std::uint64_t controlBefore = m_shape->shape().generation;
    const bool uploadedBefore
        = m_uploadedGeneration != 0 && m_uploadedGeneration == m_surface->view(data, *m_shape).shape->generation;
    if (m_shape->refresh(*m_document, direction))
        ++m_shapeUpdates;
    if (m_shape->shape().positions.rows() != data.baseMesh->vertexCount())
        return; // a mesh change is on its way
    // Issue 25: the smooth surface comes after the blend, the animation and the key deformations.
    m_surface->refresh(*m_shape, controlBefore);
    const SubdividedDisplay::View shown = m_surface->view(data, *m_shape);
    const algo::Shape& shape = *shown.shape;
    if (shape.generation != m_uploadedGeneration) {
        if (uploadedBefore && !shown.changed->empty())
            m_scene->uploadRows(shape.positions, *shown.normals, *shown.changed);
        else
            m_scene->uploadShape(shape.positions, *shown.normals);
        m_uploadedGeneration = shape.generation;
        m_lookStale = true;
        m_patchStale = true;
    }
    m_cage->show(m_display->cageShown() && m_surface->level() > 0 ? data.baseMesh.get() : nullptr, &m_shape->shape());
    // The look's per-vertex data only when the look is drawn (the brush's clay look skips it).
    if (m_lookStale && m_display->isShadingEnabled() && !m_scene->selectionShown()) {
        updateShadingOffsets(direction);
        m_scene->look().update(*shown.data, data.look, shape.positions, shown.normals->data(),
            m_document->currentFrame(), shape.generation, &m_surface->perVertex(m_shadingOffsets, m_surfaceOffsets));
        m_lookStale = false;
    }
    if (m_patchStale) {
        // The patch painted shows on the displayed surface: its children faces there.
        const algo::FaceSet* set = nullptr;
        algo::FaceSet focal; // the importance mode: the faces painted below 1 (issue 26)
        if (m_tool == Tool::Patch && tool<PatchTool>().mode() == PatchTool::Mode::Importance) {
            const std::vector<float>& importance = shown.data->faceImportance;
            for (std::size_t f = 0; f < importance.size(); ++f)
                if (importance[f] < 1.f)
                    focal.faces.push_back(std::int32_t(f));
            set = &focal;
        } else if (m_tool == Tool::Patch) {
            if (const algo::FaceSet* painted = data.faceSet(tool<PatchTool>().target()))
                set = m_surface->level() > 0 ? shown.data->faceSet(QString::fromStdString(painted->name)) : painted;
        }
        // Lifted by a thousandth of the model's size along the normals: no depth fighting with
        // the model under it, and too little to see.
        m_scene->setPatchOverlay(shape.positions, *shown.normals, shown.mesh->faces, set,
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

bool Viewport::refusedWhileHeld(const QString& action)
{
    ViewportTool* tool = activeTool();
    if (!tool || !tool->holdsCamera())
        return false;
    emit message(tr("%1 would take the view off the camera being edited; leave the tool first (Esc).").arg(action));
    return true;
}

void Viewport::frameAll()
{
    if (refusedWhileHeld(tr("Frame All")))
        return;
    placeFramed();
}

void Viewport::placeFramed()
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
    // While brushing a key, a preset view (numpad, Home, the axis gizmo) would swing the key's
    // camera away from its drawing just as Frame All would (issue 24, item 4). Aligning takes them:
    // the axis views are where a rough alignment starts (the align banner says so).
    if (m_tool != Tool::Align && refusedWhileHeld(tr("A preset view")))
        return;
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

void Viewport::setNavigation(const Navigation& navigation)
{
    const double speed = m_navigation.orbitSpeed;
    m_navigation = navigation;
    if (!(std::isfinite(navigation.orbitSpeed) && navigation.orbitSpeed > 0.0))
        m_navigation.orbitSpeed = speed;
    m_camera->setTrackball(navigation.orbitMode == OrbitMode::Trackball);
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

void Viewport::updateOverlay()
{
    // A drawing the document no longer has is forgotten; aligning to it ends.
    if (!m_overlay->resolve() && m_tool == Tool::Align)
        setTool(Tool::Navigate);
    m_scene->setDrawing(m_overlay->image(), m_overlay->drawnOnTop(), m_overlay->opacity());
    refreshFrameScale();
    update();
}

void Viewport::refreshFrameScale()
{
    const double wanted = m_overlay->frameScale();
    if (wanted != m_camera->frameScale()) {
        m_camera->setFrameScale(wanted);
        cameraEdited();
    }
    m_scene->fitDrawing(width(), height());
}

// --- the look and its key light ---------------------------------------------------------------

void Viewport::displayChanged(bool shading)
{
    if (shading)
        applyShadingState();
    update();
}

void Viewport::applyShadingState()
{
    const bool hasMesh = m_document && m_document->hasMesh() && m_scene->hasMesh();
    // Brush selection colours are VTK scalars, shown by the clay material: the look steps aside
    // while they are displayed rather than tinting its tones (which would read as a tone change).
    const bool shadingEnabled = m_display->isShadingEnabled();
    const bool active = shadingEnabled && hasMesh && !m_scene->selectionShown();
    const Eigen::Vector3f background
        = m_document ? m_document->data().look.backgroundColor : model::Look{}.backgroundColor;
    m_scene->applyShading(
        active, shadingEnabled && hasMesh, background, m_display->isLightGizmoVisible() && shadingEnabled && hasMesh);
    if (active)
        m_lookStale = true;
}

Eigen::Vector3d Viewport::modelCentre() const
{
    return m_camera->bounds().center();
}

void Viewport::updateLightGizmo()
{
    m_scene->setLightGizmo(m_document ? m_document->data().look.lightAt(m_document->currentFrame()) : model::Light{},
        modelCentre(), m_display->lightGizmoRadius());
}

const model::Look& Viewport::currentLook() const
{
    static const model::Look defaultLook;
    return m_document ? m_document->data().look : defaultLook;
}

Viewport::FrameTimes Viewport::lastFrameTimes() const
{
    return {m_frameMilliseconds, m_compositor->lastLineMilliseconds()};
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
    tool<AlignTool>().resized();
    refreshFrameScale();
    // A view framed by the program (load, F, Home) stays framed while the window is resized:
    // the widget's first size is only known here, after the constructor framed the model.
    if (m_camera->isFramed())
        placeFramed();
}

void Viewport::paintGL()
{
    if (!m_initialized)
        return;
    if (!m_scene->cameraPlaced)
        placeFramed();
    QElapsedTimer timer;
    timer.start();
    syncScene();
    ViewportCompositor::Frame frame;
    // Lines and highlights are those of the displayed surface, as `celform render` draws them.
    if (m_document && m_document->hasMesh()) {
        const SubdividedDisplay::View shown = m_surface->view(m_document->data(), *m_shape);
        frame.shape = shown.shape;
        frame.mesh = shown.mesh;
    }
    frame.look = &currentLook();
    const ViewportDisplay& display = *m_display;
    frame.lines = display.linesShown();
    frame.stereo = display.stereo();
    if (display.stereo() != algo::StereoOutput::Off) {
        frame.stereoSettings = display.resolvedStereoSettings();
        frame.dubois = display.stereoLook().dubois;
    }
    frame.eyeOnly = display.eyeOnly() == ViewportDisplay::Eye::Left ? ViewportCompositor::Eye::Left
        : display.eyeOnly() == ViewportDisplay::Eye::Right          ? ViewportCompositor::Eye::Right
                                                                    : ViewportCompositor::Eye::Both;
    m_compositor->paint(frame);
    m_frameMilliseconds = double(timer.nsecsElapsed()) / 1e6;
    ++m_renderCount;
}

} // namespace celform::views
