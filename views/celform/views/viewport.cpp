// The 3D viewport: a vtkGenericOpenGLRenderWindow drawing into the QOpenGLWidget's framebuffer
// (STACK.md pitfall 5), the base model as zero-conversion vtkPolyData, and the widget's own camera.
#include "celform/views/viewport.h"

#include "celform/algorithms/camera_solve.h"
#include "celform/model/document.h"
#include "celform/model/io_error.h"
#include "celform/model/render_output.h"
#include "celform/views/line_overlay.h"
#include "celform/views/look_shading.h"

#include <QPainter>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QElapsedTimer>
#include <QOpenGLFunctions>
#include <QWheelEvent>

#include <vtkActor.h>
#include <vtkAppendPolyData.h>
#include <vtkArrowSource.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellPicker.h>
#include <vtkCoordinate.h>
#include <vtkImageActor.h>
#include <vtkImageData.h>
#include <vtkImageProperty.h>
#include <vtkCommand.h>
#include <vtkFloatArray.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkLightKit.h>
#include <vtkNew.h>
#include <vtkOpenGLState.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkSphereSource.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>
#include <vtkTypeInt32Array.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <iterator>
#include <cmath>
#include <cstring>
#include <limits>

namespace celform::views {

namespace {

/// The layers leave the framebuffer's alpha below one (see paintGL): the widget is opaque.
void makeOpaque(QImage& rgba)
{
    for (int y = 0; y < rgba.height(); ++y) {
        uchar* row = rgba.scanLine(y);
        for (int x = 0; x < rgba.width(); ++x)
            row[4 * x + 3] = 255;
    }
}

constexpr double kPi = 3.14159265358979323846;
constexpr double kOrbitDegreesPerPixel = 0.4;
constexpr double kDollyPerPixel = 0.005; // exp(-kDollyPerPixel * pixels)
constexpr double kDollyPerWheelNotch = 0.85; // factor per 120 units of wheel angle
constexpr double kMaxElevationDegrees = 89.0; // turntable never passes over the pole
constexpr int kTriadSizePixels = 90; // logical pixels

Eigen::Vector3d toEigen(const double v[3])
{
    return {v[0], v[1], v[2]};
}

double radians(double degrees)
{
    return degrees * kPi / 180.0;
}

/// One arrow of the axes triad, along +X rotated onto axis.
vtkSmartPointer<vtkPolyData> triadArrow(int axis)
{
    vtkNew<vtkArrowSource> arrow;
    arrow->SetTipResolution(16);
    arrow->SetShaftResolution(16);
    arrow->SetShaftRadius(0.04);
    arrow->SetTipRadius(0.11);
    arrow->SetTipLength(0.3);
    vtkNew<vtkTransform> transform;
    if (axis == 1)
        transform->RotateZ(90.0);
    else if (axis == 2)
        transform->RotateY(-90.0);
    vtkNew<vtkTransformPolyDataFilter> filter;
    filter->SetInputConnection(arrow->GetOutputPort());
    filter->SetTransform(transform);
    filter->Update();
    vtkSmartPointer<vtkPolyData> out = filter->GetOutput();
    return out;
}

/// Paints the matched points of the semi-automatic alignment over the viewport: model points
/// as red numbered dots, drawing points as blue numbered rings, a line between each pair.
class MatchMarkers : public QWidget {
public:
    explicit MatchMarkers(Viewport* viewport)
        : QWidget(viewport)
        , m_viewport(viewport)
    {
        setAttribute(Qt::WA_TransparentForMouseEvents);
        setAttribute(Qt::WA_NoSystemBackground);
    }

protected:
    void paintEvent(QPaintEvent*) override
    {
        QPainter p(this);
        p.setRenderHint(QPainter::Antialiasing);
        QFont font = p.font();
        font.setBold(true);
        p.setFont(font);
        const auto& model = m_viewport->matchedModelPoints();
        const auto& drawing = m_viewport->matchedDrawingPoints();
        for (size_t i = 0; i < std::max(model.size(), drawing.size()); ++i) {
            const QString label = QString::number(i + 1);
            QPointF a, b;
            if (i < model.size())
                a = m_viewport->projectToWidget(model[i]);
            if (i < drawing.size())
                b = m_viewport->drawingToWidget(drawing[i]);
            if (i < model.size() && i < drawing.size()) {
                p.setPen(QPen(QColor(40, 40, 40, 160), 1, Qt::DashLine));
                p.drawLine(a, b);
            }
            if (i < model.size()) {
                p.setPen(QPen(Qt::white, 1.5));
                p.setBrush(QColor(220, 50, 40));
                p.drawEllipse(a, 5, 5);
                p.setPen(QColor(150, 20, 10));
                p.drawText(a + QPointF(7, -6), label);
            }
            if (i < drawing.size()) {
                p.setPen(QPen(QColor(30, 90, 220), 2.5));
                p.setBrush(Qt::NoBrush);
                p.drawEllipse(b, 6, 6);
                p.setPen(QColor(20, 60, 170));
                p.drawText(b + QPointF(8, 14), label);
            }
        }
    }

private:
    Viewport* m_viewport;
};

} // namespace

struct Viewport::Vtk {
    vtkNew<vtkGenericOpenGLRenderWindow> window;
    vtkNew<vtkRenderer> renderer;
    vtkNew<vtkRenderer> triadRenderer;
    vtkNew<vtkPolyData> mesh;
    vtkNew<vtkPolyDataMapper> meshMapper;
    vtkNew<vtkActor> meshActor;
    vtkNew<vtkPolyData> grid;
    vtkNew<vtkPolyDataMapper> gridMapper;
    vtkNew<vtkActor> gridActor;
    // The patch being painted: its faces over the model, lifted a little along the normals.
    vtkNew<vtkPolyData> patch;
    vtkNew<vtkPolyDataMapper> patchMapper;
    vtkNew<vtkActor> patchActor;
    vtkNew<vtkCallbackCommand> makeCurrent;
    // The reference drawing, in a renderer of its own with a parallel camera fitted to the
    // image height: under the model (layer 0) or over it (layer 2).
    vtkNew<vtkRenderer> drawingRenderer;
    vtkNew<vtkImageData> drawingImage;
    vtkNew<vtkImageActor> drawingActor;
    qint64 drawingImageKey = 0;
    vtkNew<vtkCellPicker> picker;
    vtkSmartPointer<vtkFloatArray> positions;
    vtkSmartPointer<vtkFloatArray> normals;
    vtkNew<vtkUnsignedCharArray> colors;
    // Whether the main camera has been placed: VTK does not reset a camera that was touched
    // before the first render (STACK.md pitfall 5), so the first frame depends on our framing.
    bool cameraPlaced = false;
    // The document's look on the mesh actor, and the key-light gizmo (not pickable by the mesh
    // picker; hit-tested in widget space).
    std::unique_ptr<LookShading> look;
    vtkNew<vtkPolyDataMapper> lightMapper;
    vtkNew<vtkActor> lightActor;
    // Depth of the model layer, read when its renderer ends: later layers (a drawing on top, the
    // triad) clear the depth buffer, so the end of the frame is too late for hidden lines.
    vtkNew<vtkCallbackCommand> depthCapture;
    bool captureDepth = false;
    std::vector<float> windowDepth;
};

Viewport::Viewport(model::Document* document, QWidget* parent)
    : QOpenGLWidget(parent)
    , m_document(document)
    , m_vtk(std::make_unique<Vtk>())
{
    setFocusPolicy(Qt::StrongFocus);
    setMinimumSize(64, 64);
    setAccessibleName(tr("3D viewport"));
    setWhatsThis(tr("<p>The 3D view of the model.</p>"
                    "<p>Alt+left drag or middle drag: orbit. Alt+middle drag or Shift+middle drag: pan. "
                    "Alt+right drag, Ctrl+middle drag or the mouse wheel: dolly. "
                    "F: frame the model. Home: front view.</p>"
                    "<p>Ctrl+left drag on the light gizmo (the yellow arrow or sphere): move the key light "
                    "around the model.</p>"));

    Vtk& v = *m_vtk;
    // The context belongs to Qt; VTK only draws into the framebuffer Qt has bound in paintGL.
    v.window->SetOwnContext(false);
    v.window->SetIsCurrent(true);
    // Antialiasing is VTK's: it resolves its own multisampled buffer before blitting into Qt's,
    // which must stay single-sampled (see defaultFormat()). FXAA is not an option: its pass
    // re-binds framebuffers behind Qt and the frame comes out black.
    v.window->SetMultiSamples(4); // see initializeGL() for software GL
    // Layers: 0 background (the drawing when it is under the model, else the model), 1 the
    // model over a drawing, 2 a drawing over the model, 3 the axes triad.
    v.window->SetNumberOfLayers(4);
    v.window->AddRenderer(v.renderer);
    v.window->AddRenderer(v.drawingRenderer);
    v.window->AddRenderer(v.triadRenderer);

    // VTK asks for the context when it releases resources outside paintGL. An unconditional
    // makeCurrent() would re-bind Qt's framebuffer behind VTK's cached state (black viewport).
    v.makeCurrent->SetClientData(this);
    v.makeCurrent->SetCallback([](vtkObject*, unsigned long, void* clientData, void*) {
        auto* self = static_cast<Viewport*>(clientData);
        if (self->context() && QOpenGLContext::currentContext() != self->context())
            self->makeCurrent();
    });
    v.window->AddObserver(vtkCommand::WindowMakeCurrentEvent, v.makeCurrent);

    v.renderer->GradientBackgroundOn();
    v.drawingRenderer->GradientBackgroundOn();
    v.drawingRenderer->InteractiveOff();
    v.drawingRenderer->SetLayer(2);
    v.drawingRenderer->GetActiveCamera()->ParallelProjectionOn();
    v.drawingActor->SetInputData(v.drawingImage);
    v.drawingActor->GetProperty()->SetInterpolationTypeToLinear();
    v.drawingActor->VisibilityOff();
    v.drawingActor->PickableOff();
    v.drawingRenderer->AddActor(v.drawingActor);
    v.picker->SetTolerance(0.0005);
    v.picker->PickFromListOn();
    v.picker->AddPickList(v.meshActor);
    v.colors->SetName("BrushFalloff");
    v.colors->SetNumberOfComponents(3);
    setBackgroundColors(QColor(200, 201, 204), QColor(150, 151, 155));
    // A three-light kit reads shapes far better than the single default headlight.
    vtkNew<vtkLightKit> lights;
    lights->SetKeyLightIntensity(0.85);
    lights->AddLightsToRenderer(v.renderer);

    v.meshMapper->SetInputData(v.mesh);
    v.meshMapper->ScalarVisibilityOff();
    v.meshMapper->SetColorModeToDirectScalars();
    v.meshActor->SetMapper(v.meshMapper);
    vtkProperty* material = v.meshActor->GetProperty();
    material->SetInterpolationToPhong();
    material->SetColor(0.80, 0.77, 0.72); // light warm grey clay
    material->SetAmbient(0.12);
    material->SetDiffuse(0.85);
    material->SetSpecular(0.12);
    material->SetSpecularPower(24.0);
    material->SetSpecularColor(1.0, 0.98, 0.95);
    v.renderer->AddActor(v.meshActor);
    // The look replaces this clay material while shading is enabled (applyShadingState()).
    v.look = std::make_unique<LookShading>(v.meshActor, v.mesh, v.renderer);
    v.lightActor->SetMapper(v.lightMapper);
    v.lightActor->GetProperty()->SetColor(1.0, 0.78, 0.15);
    v.lightActor->GetProperty()->SetAmbient(0.4);
    v.lightActor->GetProperty()->SetDiffuse(0.7);
    v.lightActor->PickableOff();
    v.lightActor->VisibilityOff();
    v.renderer->AddActor(v.lightActor);

    v.patchMapper->SetInputData(v.patch);
    v.patchMapper->ScalarVisibilityOff();
    v.patchActor->SetMapper(v.patchMapper);
    v.patchActor->GetProperty()->SetColor(1.0, 0.45, 0.08);
    v.patchActor->GetProperty()->SetOpacity(0.45);
    v.patchActor->GetProperty()->SetAmbient(0.5);
    v.patchActor->GetProperty()->SetDiffuse(0.5);
    v.patchActor->PickableOff();
    v.patchActor->VisibilityOff();
    v.renderer->AddActor(v.patchActor);

    v.gridMapper->SetInputData(v.grid);
    v.gridActor->SetMapper(v.gridMapper);
    v.gridActor->GetProperty()->LightingOff();
    v.gridActor->PickableOff();
    v.renderer->AddActor(v.gridActor);

    // The triad lives in a second layer with its own camera that only copies the orientation of
    // the main one, so it stays the same size whatever the zoom.
    v.triadRenderer->SetLayer(3);
    v.triadRenderer->InteractiveOff();
    const double axisColors[3][3] = {{0.85, 0.25, 0.22}, {0.35, 0.70, 0.25}, {0.25, 0.45, 0.85}};
    for (int axis = 0; axis < 3; ++axis) {
        vtkNew<vtkPolyDataMapper> mapper;
        mapper->SetInputData(triadArrow(axis));
        vtkNew<vtkActor> actor;
        actor->SetMapper(mapper);
        actor->GetProperty()->SetColor(axisColors[axis][0], axisColors[axis][1], axisColors[axis][2]);
        actor->GetProperty()->SetAmbient(0.35);
        actor->GetProperty()->SetDiffuse(0.7);
        v.triadRenderer->AddActor(actor);
    }

    if (m_document) {
        connect(m_document, &model::Document::meshChanged, this, [this] {
            rebuildMesh();
            update();
        });
        connect(m_document, &model::Document::documentReset, this, [this] {
            m_displayedKey = 0;
            m_overlayDrawing = 0;
            m_selection = {};
            rebuildMesh();
            updateOverlay();
            resetView();
            // A project with a render camera opens looking through it, as a shot would.
            if (const auto& shot = m_document->data().look.renderCamera)
                setCamera(*shot);
        });
        connect(m_document, &model::Document::keysChanged, this, [this] {
            if (m_displayedKey && !m_document->data().key(m_displayedKey)) {
                m_displayedKey = 0;
                m_selection = {};
            }
            if (m_displayedKey || m_preview || m_observed)
                updateShape();
        });
        connect(m_document, &model::Document::blendChanged, this, [this] {
            if (m_preview || m_observed)
                updateShape();
        });
        connect(m_document, &model::Document::drawingsChanged, this, &Viewport::updateOverlay);
        connect(m_document, &model::Document::faceSetsChanged, this, [this] {
            updateLookShading();
            updatePatchOverlay();
            update();
        });
        connect(m_document, &model::Document::lookChanged, this, [this] {
            updateLookShading();
            updateLightGizmo();
            applyShadingState();
            update();
        });
    }
    // Lines and stereo: the model layer's depth for hidden-line tests, and a repaint per look edit.
    m_lines = std::make_unique<LineOverlay>();
    v.depthCapture->SetClientData(this);
    v.depthCapture->SetCallback([](vtkObject*, unsigned long, void* clientData, void*) {
        Vtk& vtk = *static_cast<Viewport*>(clientData)->m_vtk;
        if (!vtk.captureDepth)
            return;
        vtk.captureDepth = false;
        const int* size = vtk.window->GetSize();
        vtk.windowDepth.resize(std::size_t(std::max(size[0], 0)) * std::size_t(std::max(size[1], 0)));
        if (!vtk.windowDepth.empty()
            && vtk.window->GetZbufferData(0, 0, size[0] - 1, size[1] - 1, vtk.windowDepth.data()) != VTK_OK)
            vtk.windowDepth.clear();
    });
    v.renderer->AddObserver(vtkCommand::EndEvent, v.depthCapture);
    if (m_document)
        connect(m_document, &model::Document::lookChanged, this, qOverload<>(&QWidget::update));
    m_markers = new MatchMarkers(this);
    m_markers->hide();
    connect(this, &Viewport::cameraChanged, m_markers, qOverload<>(&QWidget::update));
    m_alignCommit.setSingleShot(true);
    m_alignCommit.setInterval(300);
    connect(&m_alignCommit, &QTimer::timeout, this, [this] {
        if (m_tool == Tool::Align && m_overlayDrawing && m_document)
            m_document->setDrawingCamera(m_overlayDrawing, camera());
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
    m_vtk->window->RemoveObserver(m_vtk->makeCurrent);
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

// --- camera ---------------------------------------------------------------------------------

model::Camera Viewport::camera() const
{
    vtkCamera* cam = m_vtk->renderer->GetActiveCamera();
    model::Camera c;
    c.eye = toEigen(cam->GetPosition());
    c.target = toEigen(cam->GetFocalPoint());
    c.up = toEigen(cam->GetViewUp());
    c.projection = cam->GetParallelProjection() ? model::Projection::Orthographic : model::Projection::Perspective;
    // With a drawing shown, the stored camera's field of view spans the drawing's height, which
    // is letterboxed inside the viewport (m_frameScale >= 1): undo that here.
    c.fovYDegrees = 2.0 * std::atan(std::tan(radians(cam->GetViewAngle() / 2.0)) / m_frameScale) * 180.0 / kPi;
    c.orthoHeight = 2.0 * cam->GetParallelScale() / m_frameScale;
    return c;
}

void Viewport::setCamera(const model::Camera& camera)
{
    if (!camera.isValid())
        return;
    vtkCamera* cam = m_vtk->renderer->GetActiveCamera();
    cam->SetPosition(camera.eye.data());
    cam->SetFocalPoint(camera.target.data());
    cam->SetViewUp(camera.up.data());
    cam->SetParallelProjection(camera.projection == model::Projection::Orthographic);
    cam->SetViewAngle(2.0 * std::atan(m_frameScale * std::tan(radians(camera.fovYDegrees / 2.0))) * 180.0 / kPi);
    cam->SetParallelScale(m_frameScale * camera.orthoHeight / 2.0);
    // Orbit turns around the model: the point of the view axis nearest to its centre, so the
    // pivot stays on screen whatever target the camera was given.
    const Eigen::Vector3d forward = camera.forward();
    double along = (m_bounds.center() - camera.eye).dot(forward);
    if (!(along > 1e-6 * m_bounds.diagonal().norm()))
        along = (camera.target - camera.eye).norm(); // model behind the camera: turn about the target
    m_pivot = camera.eye + along * forward;
    m_vtk->cameraPlaced = true;
    cameraEdited();
}

void Viewport::setProjection(model::Projection projection)
{
    vtkCamera* cam = m_vtk->renderer->GetActiveCamera();
    const bool ortho = projection == model::Projection::Orthographic;
    if (bool(cam->GetParallelProjection()) == ortho)
        return;
    // Keep the size of the model at the pivot's depth, so switching does not jump.
    const double distance = (m_pivot - toEigen(cam->GetPosition())).norm();
    const double halfAngle = radians(cam->GetViewAngle() / 2.0);
    if (ortho)
        cam->SetParallelScale(distance * std::tan(halfAngle));
    cam->SetParallelProjection(ortho);
    cameraEdited();
}

model::Projection Viewport::projection() const
{
    return m_vtk->renderer->GetActiveCamera()->GetParallelProjection() ? model::Projection::Orthographic
                                                                       : model::Projection::Perspective;
}

void Viewport::frameAll()
{
    vtkCamera* cam = m_vtk->renderer->GetActiveCamera();
    const Eigen::Vector3d center = m_bounds.center();
    const double radius = std::max(0.5 * m_bounds.diagonal().norm(), 1e-6);
    Eigen::Vector3d forward = (toEigen(cam->GetFocalPoint()) - toEigen(cam->GetPosition())).normalized();
    if (!forward.allFinite())
        forward = -Eigen::Vector3d::UnitZ();

    // The bounding sphere must fit the narrower of the two fields of view.
    const double aspect = height() > 0 ? double(width()) / double(height()) : 1.0;
    const double halfY = radians(cam->GetViewAngle() / 2.0);
    const double halfX = std::atan(std::tan(halfY) * aspect);
    const double halfMin = std::min(halfX, halfY);
    const double margin = 1.05;
    const double distance = margin * radius / std::sin(halfMin);

    const Eigen::Vector3d eye = center - distance * forward;
    cam->SetFocalPoint(center.data());
    cam->SetPosition(eye.data());
    cam->SetParallelScale(margin * radius * std::max(1.0, 1.0 / aspect));
    m_pivot = center;
    m_vtk->cameraPlaced = true;
    cameraEdited();
    m_framed = true;
}

void Viewport::resetView()
{
    vtkCamera* cam = m_vtk->renderer->GetActiveCamera();
    const Eigen::Vector3d center = m_bounds.center();
    cam->SetFocalPoint(center.data());
    const Eigen::Vector3d eye = center + Eigen::Vector3d::UnitZ();
    cam->SetPosition(eye.data());
    cam->SetViewUp(0.0, 1.0, 0.0);
    frameAll();
}

void Viewport::cameraEdited()
{
    m_framed = false;
    m_vtk->renderer->GetActiveCamera()->OrthogonalizeViewUp();
    if (m_preview)
        updateShape();
    if (m_tool == Tool::Align && m_overlayDrawing)
        m_alignCommit.start();
    update();
    emit cameraChanged();
}

void Viewport::roll(double degrees)
{
    vtkCamera* cam = m_vtk->renderer->GetActiveCamera();
    cam->Roll(degrees);
    cameraEdited();
}

void Viewport::orbit(double yawDegrees, double pitchDegrees)
{
    vtkCamera* cam = m_vtk->renderer->GetActiveCamera();
    const Eigen::Vector3d eye = toEigen(cam->GetPosition());
    const Eigen::Vector3d target = toEigen(cam->GetFocalPoint());
    const Eigen::Vector3d up = toEigen(cam->GetViewUp());
    const Eigen::Vector3d forward = (target - eye).normalized();
    const Eigen::Vector3d worldUp = Eigen::Vector3d::UnitY();

    // Turntable: yaw about the world up axis, then pitch about the camera's horizontal axis,
    // clamped by elevation so the view never rolls over the pole.
    const double elevation = std::asin(std::clamp(-forward.dot(worldUp), -1.0, 1.0)) * 180.0 / kPi;
    const double newElevation = std::clamp(elevation + pitchDegrees, -kMaxElevationDegrees, kMaxElevationDegrees);
    const double pitch = newElevation - elevation;

    const Eigen::AngleAxisd yaw(radians(-yawDegrees), worldUp);
    Eigen::Vector3d right = yaw * forward.cross(worldUp);
    if (right.norm() < 1e-9)
        right = yaw * forward.cross(up);
    const Eigen::AngleAxisd tilt(radians(-pitch), right.normalized());
    const Eigen::Matrix3d rotation = (tilt * yaw).toRotationMatrix();

    const Eigen::Vector3d newEye = m_pivot + rotation * (eye - m_pivot);
    const Eigen::Vector3d newTarget = m_pivot + rotation * (target - m_pivot);
    const Eigen::Vector3d newUp = rotation * up;
    cam->SetPosition(newEye.data());
    cam->SetFocalPoint(newTarget.data());
    cam->SetViewUp(newUp.data());
    cameraEdited();
}

void Viewport::pan(const QPointF& deltaPixels)
{
    if (height() <= 0)
        return;
    vtkCamera* cam = m_vtk->renderer->GetActiveCamera();
    const model::Camera c = camera();
    // World units per logical pixel at the pivot's depth, so the model follows the cursor.
    const double perPixel = worldUnitsPerPixel(m_pivot);
    const Eigen::Vector3d shift = perPixel * (-deltaPixels.x() * c.right() + deltaPixels.y() * c.trueUp());
    const Eigen::Vector3d eye = c.eye + shift;
    const Eigen::Vector3d target = c.target + shift;
    cam->SetPosition(eye.data());
    cam->SetFocalPoint(target.data());
    // Maya's centre of interest moves with a track: orbit then turns about what is on screen.
    m_pivot += shift;
    cameraEdited();
}

void Viewport::dolly(double factor)
{
    if (!(factor > 0.0) || !std::isfinite(factor))
        return;
    vtkCamera* cam = m_vtk->renderer->GetActiveCamera();
    if (cam->GetParallelProjection()) {
        cam->SetParallelScale(std::max(cam->GetParallelScale() * factor, 1e-6));
        cameraEdited();
        return;
    }
    const Eigen::Vector3d eye = toEigen(cam->GetPosition());
    const Eigen::Vector3d target = toEigen(cam->GetFocalPoint());
    const double distance = (m_pivot - eye).norm();
    // Never reach the pivot: a zero distance would lose the view direction.
    const double minDistance = 1e-4 * std::max(m_bounds.diagonal().norm(), 1e-6);
    const double newDistance = std::max(distance * factor, minDistance);
    const Eigen::Vector3d shift = (distance - newDistance) * (m_pivot - eye).normalized();
    const Eigen::Vector3d newEye = eye + shift;
    const Eigen::Vector3d newTarget = target + shift;
    cam->SetPosition(newEye.data());
    cam->SetFocalPoint(newTarget.data());
    cameraEdited();
}

// --- scene ----------------------------------------------------------------------------------

void Viewport::setBackgroundColors(const QColor& top, const QColor& bottom)
{
    m_vtk->renderer->SetBackground2(top.redF(), top.greenF(), top.blueF());
    m_vtk->renderer->SetBackground(bottom.redF(), bottom.greenF(), bottom.blueF());
    m_vtk->drawingRenderer->SetBackground2(top.redF(), top.greenF(), top.blueF());
    m_vtk->drawingRenderer->SetBackground(bottom.redF(), bottom.greenF(), bottom.blueF());
    // The grid is a shade of the background: visible, never louder than the model.
    const double r = 0.5 * (top.redF() + bottom.redF()), g = 0.5 * (top.greenF() + bottom.greenF()),
                 b = 0.5 * (top.blueF() + bottom.blueF());
    m_vtk->gridActor->GetProperty()->SetColor(r * 0.82, g * 0.82, b * 0.82);
    m_clayTop = top;
    m_clayBottom = bottom;
    applyShadingState(); // the look's background replaces these while it is shown
    update();
}

void Viewport::rebuildMesh()
{
    Vtk& v = *m_vtk;
    const auto mesh = (m_document && m_document->hasMesh()) ? m_document->data().baseMesh : nullptr;
    if (!mesh || mesh->vertexCount() == 0) {
        v.mesh->Initialize();
        v.meshActor->VisibilityOff();
        m_bounds = Eigen::AlignedBox3d(Eigen::Vector3d::Constant(-1.0), Eigen::Vector3d::Constant(1.0));
        rebuildGrid();
        updateLightGizmo();
        applyShadingState();
        return;
    }

    const auto vertexCount = static_cast<vtkIdType>(mesh->vertexCount());
    const auto faceCount = static_cast<vtkIdType>(mesh->faceCount());

    // Row-major #V x 3 floats are exactly VTK's AOS layout: one memcpy, no per-point calls.
    vtkNew<vtkFloatArray> positions;
    positions->SetNumberOfComponents(3);
    positions->SetNumberOfTuples(vertexCount);
    std::memcpy(positions->GetPointer(0), mesh->vertices.data(), sizeof(float) * 3 * size_t(vertexCount));
    vtkNew<vtkPoints> points;
    points->SetData(positions);

    // 32-bit cell storage like algo::Faces: the connectivity is one memcpy too, and the offsets
    // of fixed-size triangles are a trivial ramp. Half the memory of VTK's default 64-bit ids.
    vtkNew<vtkTypeInt32Array> connectivity;
    connectivity->SetNumberOfTuples(3 * faceCount);
    std::memcpy(connectivity->GetPointer(0), mesh->faces.data(), sizeof(std::int32_t) * 3 * size_t(faceCount));
    vtkNew<vtkTypeInt32Array> offsets;
    offsets->SetNumberOfTuples(faceCount + 1);
    std::int32_t* offset = offsets->GetPointer(0);
    for (vtkIdType f = 0; f <= faceCount; ++f)
        offset[f] = static_cast<std::int32_t>(3 * f);
    vtkNew<vtkCellArray> triangles;
    triangles->SetData(offsets, connectivity);

    v.normals = vtkSmartPointer<vtkFloatArray>::New();
    v.normals->SetName("Normals");
    v.normals->SetNumberOfComponents(3);
    v.normals->SetNumberOfTuples(vertexCount);
    v.positions = positions;

    v.mesh->Initialize();
    v.mesh->SetPoints(points);
    v.mesh->SetPolys(triangles);
    v.mesh->GetPointData()->SetNormals(v.normals);
    v.meshActor->VisibilityOn();
    m_selection = {};
    m_mirror.clear();
    updateShape();

    m_bounds = algo::boundingBox(mesh->vertices);
    if (m_bounds.isEmpty() || !m_bounds.min().allFinite() || !m_bounds.max().allFinite())
        m_bounds = Eigen::AlignedBox3d(Eigen::Vector3d::Constant(-1.0), Eigen::Vector3d::Constant(1.0));
    rebuildGrid();
    updateLightGizmo();
    applyShadingState();
}

void Viewport::rebuildGrid()
{
    // A ground grid under the model (Y up), with a round spacing a little under a tenth of its
    // size, so the floor reads as scale without competing with the model.
    const Eigen::Vector3d center = m_bounds.center();
    const Eigen::Vector3d size = m_bounds.sizes();
    const double extent = std::max({size.x(), size.z(), 0.5 * size.y(), 1e-6});
    const double spacing = std::pow(10.0, std::floor(std::log10(extent / 4.0)));
    const int halfLines = std::min(int(std::ceil(extent / spacing)), 40);
    const double half = halfLines * spacing;
    const double y = m_bounds.min().y();
    const double cx = std::round(center.x() / spacing) * spacing;
    const double cz = std::round(center.z() / spacing) * spacing;

    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> lines;
    for (int i = -halfLines; i <= halfLines; ++i) {
        const double t = i * spacing;
        const vtkIdType a = points->InsertNextPoint(cx + t, y, cz - half);
        const vtkIdType b = points->InsertNextPoint(cx + t, y, cz + half);
        const vtkIdType c = points->InsertNextPoint(cx - half, y, cz + t);
        const vtkIdType d = points->InsertNextPoint(cx + half, y, cz + t);
        const vtkIdType first[2] = {a, b};
        const vtkIdType second[2] = {c, d};
        lines->InsertNextCell(2, first);
        lines->InsertNextCell(2, second);
    }
    m_vtk->grid->Initialize();
    m_vtk->grid->SetPoints(points);
    m_vtk->grid->SetLines(lines);
    m_vtk->grid->Modified();
}

void Viewport::updateTriadViewport()
{
    const double w = std::max(width(), 1), h = std::max(height(), 1);
    const double side = std::min(double(kTriadSizePixels), 0.3 * std::min(w, h));
    m_vtk->triadRenderer->SetViewport(0.0, 0.0, side / w, side / h);
}

void Viewport::syncTriadCamera()
{
    vtkCamera* main = m_vtk->renderer->GetActiveCamera();
    vtkCamera* triad = m_vtk->triadRenderer->GetActiveCamera();
    const Eigen::Vector3d forward = (toEigen(main->GetFocalPoint()) - toEigen(main->GetPosition())).normalized();
    const Eigen::Vector3d eye = -4.0 * forward;
    triad->SetFocalPoint(0.0, 0.0, 0.0);
    triad->SetPosition(eye.data());
    triad->SetViewUp(main->GetViewUp());
    // Orthographic keeps the arrows undistorted in the corner.
    triad->ParallelProjectionOn();
    triad->SetParallelScale(1.3);
    triad->SetClippingRange(0.1, 10.0);
}

// --- displayed shape ------------------------------------------------------------------------

void Viewport::setDisplayedKey(model::ObjectId key)
{
    if (key == m_displayedKey && !m_preview)
        return;
    m_displayedKey = key;
    m_preview = false;
    m_selection = {};
    updateShape();
}

void Viewport::setPreview(bool on)
{
    if (on == m_preview)
        return;
    m_preview = on;
    if (on)
        m_displayedKey = 0;
    m_selection = {};
    updateShape();
}

void Viewport::setObserved(Viewport* driver)
{
    if (m_observed)
        disconnect(m_observed, nullptr, this, nullptr);
    m_observed = driver;
    if (driver)
        connect(driver, &Viewport::cameraChanged, this, [this] {
            // A hidden observer (a closed dock) costs nothing while the main camera orbits.
            if (isVisible())
                updateShape();
        });
    updateShape();
}

Eigen::Vector3d Viewport::viewDirection() const
{
    if (!m_document || !m_document->hasMesh())
        return Eigen::Vector3d::Zero();
    return m_document->blender().viewDirection(m_document->data(), camera().eye);
}

void Viewport::updateShape()
{
    Vtk& v = *m_vtk;
    if (!m_document || !m_document->hasMesh() || !v.positions)
        return;
    const model::ProjectData& data = m_document->data();
    const model::KeyViewpoint* key = m_displayedKey ? data.key(m_displayedKey) : nullptr;
    if (m_observed)
        m_document->blender().shape(data, m_observed->viewDirection(), 0, m_shape);
    else if (m_preview)
        m_document->blender().shape(data, viewDirection(), 0, m_shape);
    else if (key)
        m_shape = data.keyShape(*key, 0);
    else
        m_shape = data.baseMesh->vertices;

    const auto count = size_t(m_shape.rows());
    if (v.positions->GetNumberOfTuples() != vtkIdType(count))
        return; // a mesh change is on its way: rebuildMesh() calls here again
    std::memcpy(v.positions->GetPointer(0), m_shape.data(), sizeof(float) * 3 * count);
    v.positions->Modified();
    const algo::Positions normals = algo::vertexNormals(m_shape, data.baseMesh->faces);
    std::memcpy(v.normals->GetPointer(0), normals.data(), sizeof(float) * 3 * count);
    v.normals->Modified();
    v.mesh->Modified();
    updateLookShading();
    updateSelectionColors();
    updatePatchOverlay();
    update();
}

void Viewport::updateSelectionColors()
{
    Vtk& v = *m_vtk;
    if (m_selection.indices.empty() || m_shape.rows() == 0) {
        v.meshMapper->ScalarVisibilityOff();
        v.mesh->GetPointData()->SetScalars(nullptr);
        applyShadingState();
        update();
        return;
    }
    // Paper 1, section 3.1.2: the selected vertices are drawn in red, here shaded by their falloff.
    v.colors->SetNumberOfTuples(m_shape.rows());
    unsigned char* c = v.colors->GetPointer(0);
    const unsigned char base[3] = {204, 196, 184};
    for (Eigen::Index i = 0; i < m_shape.rows(); ++i)
        std::memcpy(c + 3 * i, base, 3);
    auto paint = [c, &base](const algo::BrushSelection& selection) {
        for (size_t k = 0; k < selection.indices.size(); ++k) {
            const float w = selection.weights[k];
            unsigned char* p = c + 3 * size_t(selection.indices[k]);
            const float red[3] = {230.f, 40.f, 30.f};
            for (int j = 0; j < 3; ++j)
                p[j] = static_cast<unsigned char>(std::lround(base[j] + (red[j] - base[j]) * (0.25f + 0.75f * w)));
        }
    };
    paint(m_selection);
    paint(m_mirrorSelection);
    v.colors->Modified();
    v.mesh->GetPointData()->SetScalars(v.colors);
    v.meshMapper->ScalarVisibilityOn();
    applyShadingState(); // the clay look shows the selection colours
    update();
}

// --- reference drawing overlay ----------------------------------------------------------------

void Viewport::setOverlayDrawing(model::ObjectId drawing)
{
    if (drawing == m_overlayDrawing)
        return;
    m_overlayDrawing = drawing;
    if (!m_modelPoints.empty() || !m_drawingPoints.empty())
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
    Vtk& v = *m_vtk;
    const model::Drawing* drawing
        = (m_document && m_overlayDrawing) ? m_document->data().drawing(m_overlayDrawing) : nullptr;
    if (!drawing) {
        m_overlayDrawing = 0;
        if (m_tool == Tool::Align)
            setTool(Tool::Navigate);
    }
    if (!drawing || drawing->image.isNull()) {
        v.drawingActor->VisibilityOff();
        v.renderer->SetLayer(0);
        v.drawingRenderer->SetLayer(2);
        refreshFrameScale();
        update();
        return;
    }
    if (drawing->image.cacheKey() != v.drawingImageKey) {
        // VTK images start at the bottom row: copy the rows upside down.
        const QImage rgba = drawing->image.convertToFormat(QImage::Format_RGBA8888);
        v.drawingImage->SetDimensions(rgba.width(), rgba.height(), 1);
        v.drawingImage->AllocateScalars(VTK_UNSIGNED_CHAR, 4);
        auto* dst = static_cast<unsigned char*>(v.drawingImage->GetScalarPointer());
        for (int y = 0; y < rgba.height(); ++y)
            std::memcpy(dst + size_t(y) * size_t(rgba.width()) * 4, rgba.constScanLine(rgba.height() - 1 - y),
                size_t(rgba.width()) * 4);
        v.drawingImage->Modified();
        v.drawingImageKey = drawing->image.cacheKey();
        // The image's height fills the view, as the vertical field of view of an aligned camera.
        vtkCamera* cam = v.drawingRenderer->GetActiveCamera();
        const double cx = 0.5 * (rgba.width() - 1), cy = 0.5 * (rgba.height() - 1);
        cam->SetFocalPoint(cx, cy, 0.0);
        cam->SetPosition(cx, cy, 1000.0);
        cam->SetViewUp(0.0, 1.0, 0.0);
        cam->SetClippingRange(1.0, 2000.0);
    }
    v.drawingActor->VisibilityOn();
    v.drawingActor->SetOpacity(m_overlayOnTop ? std::clamp(drawing->opacity, 0.0, 1.0) : 1.0);
    if (m_overlayOnTop) {
        v.renderer->SetLayer(0);
        v.drawingRenderer->SetLayer(2);
    } else {
        v.drawingRenderer->SetLayer(0);
        v.renderer->SetLayer(1);
    }
    refreshFrameScale();
    update();
}

// --- tools ----------------------------------------------------------------------------------

void Viewport::setTool(Tool tool)
{
    if (tool == m_tool)
        return;
    if (m_tool == Tool::Align && m_alignCommit.isActive()) {
        m_alignCommit.stop();
        if (m_overlayDrawing && m_document)
            m_document->setDrawingCamera(m_overlayDrawing, camera());
    }
    m_tool = tool;
    if (tool != Tool::Align && m_matching)
        setPointMatching(false);
    if (tool == Tool::Align && m_document && m_overlayDrawing) {
        // Start from the stored alignment, so refining it does not jump.
        const model::Drawing* drawing = m_document->data().drawing(m_overlayDrawing);
        if (drawing && drawing->aligned)
            setCamera(drawing->camera);
    }
    if (tool != Tool::Brush) {
        m_selection = {};
        m_mirrorSelection = {};
        updateSelectionColors();
    }
    updatePatchOverlay();
    if (tool == Tool::Patch)
        emit message(tr("Paint the patch “%1”: drag adds faces, Ctrl+drag removes them, [ and ] change the radius.")
                         .arg(m_patchTarget));
    setCursor(
        tool == Tool::Brush || tool == Tool::Highlight || tool == Tool::Patch ? Qt::CrossCursor : Qt::ArrowCursor);
    emit toolChanged(tool);
}

void Viewport::setBrushRadius(double radius)
{
    if (!(radius > 0.0) || !std::isfinite(radius) || radius == m_brushRadius)
        return;
    m_brushRadius = radius;
    emit brushRadiusChanged(radius);
}

std::int64_t Viewport::pickVertex(const QPointF& position)
{
    Vtk& v = *m_vtk;
    if (!m_initialized || m_shape.rows() == 0 || !v.meshActor->GetVisibility())
        return -1;
    const qreal dpr = devicePixelRatioF();
    const double x = position.x() * dpr, y = (height() - position.y()) * dpr;
    makeCurrent();
    v.renderer->ResetCameraClippingRange();
    const int hit = v.picker->Pick(x, y, 0.0, v.renderer);
    doneCurrent();
    const vtkIdType cell = v.picker->GetCellId();
    if (!hit || cell < 0 || cell >= vtkIdType(m_document->data().baseMesh->faceCount()))
        return -1;
    const Eigen::Vector3d p = toEigen(v.picker->GetPickPosition());
    const auto& faces = m_document->data().baseMesh->faces;
    std::int64_t best = -1;
    double bestDistance = std::numeric_limits<double>::max();
    for (int k = 0; k < 3; ++k) {
        const auto vertex = faces(cell, k);
        const double d = (m_shape.row(vertex).cast<double>().transpose() - p).squaredNorm();
        if (d < bestDistance) {
            bestDistance = d;
            best = vertex;
        }
    }
    return best;
}

double Viewport::worldUnitsPerPixel(const Eigen::Vector3d& point) const
{
    // From VTK's own camera: its angle spans the whole widget height, drawing or not.
    vtkCamera* cam = m_vtk->renderer->GetActiveCamera();
    double viewHeight = 2.0 * cam->GetParallelScale();
    if (!cam->GetParallelProjection()) {
        const Eigen::Vector3d eye = toEigen(cam->GetPosition());
        const Eigen::Vector3d forward = (toEigen(cam->GetFocalPoint()) - eye).normalized();
        const double depth = (point - eye).dot(forward);
        viewHeight = 2.0 * std::max(depth, 1e-9) * std::tan(radians(cam->GetViewAngle() / 2.0));
    }
    return viewHeight / double(std::max(height(), 1));
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
    Vtk& v = *m_vtk;
    const double wanted = wantedFrameScale();
    if (wanted != m_frameScale) {
        const model::Camera kept = camera();
        const Eigen::Vector3d pivot = m_pivot;
        m_frameScale = wanted;
        setCamera(kept);
        m_pivot = pivot;
    }
    if (const vtkImageData* image = v.drawingImage; v.drawingActor->GetVisibility() && image) {
        int dims[3];
        v.drawingImage->GetDimensions(dims);
        if (dims[0] > 0 && dims[1] > 0 && width() > 0 && height() > 0) {
            const double fit = std::min(double(width()) / dims[0], double(height()) / dims[1]);
            v.drawingRenderer->GetActiveCamera()->SetParallelScale(0.5 * height() / fit);
        }
    }
}

QPointF Viewport::projectToWidget(const Eigen::Vector3d& point) const
{
    vtkNew<vtkCoordinate> coordinate;
    coordinate->SetCoordinateSystemToWorld();
    coordinate->SetValue(point.x(), point.y(), point.z());
    const double* display = coordinate->GetComputedDoubleDisplayValue(m_vtk->renderer);
    const qreal dpr = devicePixelRatioF();
    return {display[0] / dpr, height() - display[1] / dpr};
}

void Viewport::beginBrush(const QPointF& position, Qt::KeyboardModifiers)
{
    const model::KeyViewpoint* key = m_document ? m_document->data().key(m_displayedKey) : nullptr;
    if (!key) {
        emit message(tr("Choose a key to deform first (Scene panel, then Edit Key)."));
        return;
    }
    const std::int64_t picked = pickVertex(position);
    if (picked < 0) {
        m_selection = {};
        m_mirrorSelection = {};
        updateSelectionColors();
        return;
    }
    const algo::VertexGrid grid(m_shape);
    m_selection = algo::selectForBrush(m_shape, grid, std::uint32_t(picked), m_brushRadius);
    m_mirrorSelection = {};
    if (m_brushMirror) {
        if (m_mirror.size() != size_t(m_shape.rows())) {
            const double diagonal = algo::boundingBox(m_document->data().baseMesh->vertices).diagonal().norm();
            m_mirror = algo::mirrorMap(m_document->data().baseMesh->vertices, 1e-4 * diagonal);
        }
        const std::int32_t twin = m_mirror[size_t(picked)];
        if (twin >= 0 && twin != picked)
            m_mirrorSelection = algo::selectForBrush(m_shape, grid, std::uint32_t(twin), m_brushRadius);
    }
    m_strokeId = m_document->newStrokeId();
    m_strokeUnitsPerPixel = worldUnitsPerPixel(m_shape.row(picked).cast<double>().transpose());
    updateSelectionColors();
}

void Viewport::brushMove(const QPointF& delta, Qt::KeyboardModifiers modifiers)
{
    if (m_strokeId == 0 || m_selection.indices.empty())
        return;
    const model::ProjectData& data = m_document->data();
    const model::Camera c = camera();
    const algo::ImageFrame frame{c.right(), c.trueUp(), c.forward()};
    // The mirror image of the frame: the twin selection moves as the reflection of the first.
    const Eigen::Vector3d flip(-1.0, 1.0, 1.0);
    const algo::ImageFrame mirrored{
        -frame.right.cwiseProduct(flip), frame.up.cwiseProduct(flip), frame.forward.cwiseProduct(flip)};
    const double units = m_strokeUnitsPerPixel;
    auto displace = [&](const algo::BrushSelection& selection, const algo::ImageFrame& f) {
        if (m_brushMode == BrushMode::Smooth)
            return algo::brushSmooth(selection, m_shape, data.baseMesh->faces, 0.25);
        const bool ctrl = modifiers & Qt::ControlModifier, shift = modifiers & Qt::ShiftModifier;
        if (ctrl && shift)
            return algo::brushScale(selection, m_shape, f, std::exp(0.005 * delta.x()));
        if (shift)
            return algo::brushRotate(selection, m_shape, f, radians(-0.5 * delta.x()));
        if (ctrl)
            return algo::brushPush(selection, f, -delta.y() * units);
        return algo::brushDrag(selection, f, delta.x() * units, -delta.y() * units);
    };
    algo::Positions moves = displace(m_selection, frame);
    std::vector<std::uint32_t> indices = m_selection.indices;
    if (!m_mirrorSelection.indices.empty()) {
        const algo::Positions twinMoves = displace(m_mirrorSelection, mirrored);
        // Union of the two ascending lists; where both touch a vertex the first selection wins.
        std::vector<std::uint32_t> merged;
        algo::Positions mergedMoves(Eigen::Index(indices.size() + m_mirrorSelection.indices.size()), 3);
        size_t i = 0, j = 0;
        while (i < indices.size() || j < m_mirrorSelection.indices.size()) {
            const bool takeFirst = j == m_mirrorSelection.indices.size()
                || (i < indices.size() && indices[i] <= m_mirrorSelection.indices[j]);
            if (takeFirst) {
                if (j < m_mirrorSelection.indices.size() && m_mirrorSelection.indices[j] == indices[i])
                    ++j;
                mergedMoves.row(Eigen::Index(merged.size())) = moves.row(Eigen::Index(i));
                merged.push_back(indices[i++]);
            } else {
                mergedMoves.row(Eigen::Index(merged.size())) = twinMoves.row(Eigen::Index(j));
                merged.push_back(m_mirrorSelection.indices[j++]);
            }
        }
        mergedMoves.conservativeResize(Eigen::Index(merged.size()), 3);
        indices = std::move(merged);
        moves = std::move(mergedMoves);
    }
    const model::KeyViewpoint* key = data.key(m_displayedKey);
    if (!key)
        return;
    m_document->displaceKeyVertices(m_displayedKey, 0, indices, moves, m_strokeId, tr("Brush “%1”").arg(key->name));
}

void Viewport::endBrush()
{
    m_strokeId = 0;
}

// --- patch painting (the highlight patches of paper 2) ----------------------------------------

void Viewport::setPatchTarget(const QString& name)
{
    if (name == m_patchTarget)
        return;
    m_patchTarget = name;
    updatePatchOverlay();
}

std::vector<std::int32_t> Viewport::facesUnderBrush(const QPointF& position)
{
    Vtk& v = *m_vtk;
    if (!m_initialized || !m_document || !m_document->hasMesh() || m_shape.rows() == 0 || !v.meshActor->GetVisibility())
        return {};
    const algo::TriMesh& mesh = *m_document->data().baseMesh;
    const qreal dpr = devicePixelRatioF();
    makeCurrent();
    v.renderer->ResetCameraClippingRange();
    const int hit = v.picker->Pick(position.x() * dpr, (height() - position.y()) * dpr, 0.0, v.renderer);
    doneCurrent();
    const vtkIdType cell = v.picker->GetCellId();
    if (!hit || cell < 0 || cell >= vtkIdType(mesh.faceCount()))
        return {};
    if (m_vertexFacesMesh.lock() != m_document->data().baseMesh) {
        // Faces around each vertex, counted then filled (CSR): one pass each over the faces.
        const auto nv = std::size_t(mesh.vertexCount());
        m_vertexFaceStart.assign(nv + 1, 0);
        for (Eigen::Index f = 0; f < mesh.faceCount(); ++f)
            for (int k = 0; k < 3; ++k)
                ++m_vertexFaceStart[std::size_t(mesh.faces(f, k)) + 1];
        for (std::size_t i = 0; i < nv; ++i)
            m_vertexFaceStart[i + 1] += m_vertexFaceStart[i];
        m_vertexFaces.resize(std::size_t(m_vertexFaceStart[nv]));
        std::vector<std::int32_t> fill(m_vertexFaceStart.begin(), m_vertexFaceStart.end() - 1);
        for (Eigen::Index f = 0; f < mesh.faceCount(); ++f)
            for (int k = 0; k < 3; ++k)
                m_vertexFaces[std::size_t(fill[std::size_t(mesh.faces(f, k))]++)] = std::int32_t(f);
        m_vertexFacesMesh = m_document->data().baseMesh;
    }
    if (m_patchGrid.empty() || m_strokeId == 0)
        m_patchGrid = algo::VertexGrid(m_shape);
    std::vector<std::uint32_t> near;
    std::vector<float> distances;
    m_patchGrid.radiusQuery(toEigen(v.picker->GetPickPosition()), m_brushRadius, near, distances);
    // Only faces turned towards the camera, as the brush of a paint program works on what is
    // seen: painting one side of a thin part (an ear) leaves the other side alone.
    vtkCamera* cam = v.renderer->GetActiveCamera();
    const Eigen::Vector3f eye = toEigen(cam->GetPosition()).cast<float>();
    const Eigen::Vector3f forward = (toEigen(cam->GetFocalPoint()) - toEigen(cam->GetPosition())).cast<float>();
    const bool parallel = cam->GetParallelProjection() != 0;
    auto facesCamera = [&](std::int32_t f) {
        const Eigen::Vector3f a = m_shape.row(mesh.faces(f, 0)), b = m_shape.row(mesh.faces(f, 1)),
                              c = m_shape.row(mesh.faces(f, 2));
        const Eigen::Vector3f normal = (b - a).cross(c - a);
        const Eigen::Vector3f towardsEye = parallel ? Eigen::Vector3f(-forward) : Eigen::Vector3f(eye - a);
        return normal.dot(towardsEye) > 0.f;
    };
    std::vector<std::int32_t> faces{std::int32_t(cell)};
    for (const auto vertex : near)
        for (auto i = m_vertexFaceStart[vertex]; i < m_vertexFaceStart[vertex + 1]; ++i)
            if (const std::int32_t f = m_vertexFaces[std::size_t(i)]; facesCamera(f))
                faces.push_back(f);
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    return faces;
}

void Viewport::paintPatch(const QPointF& position, Qt::KeyboardModifiers modifiers)
{
    if (!m_document || !m_document->hasMesh())
        return;
    if (m_patchTarget.trimmed().isEmpty()) {
        emit message(tr("Choose or create a patch in the Highlights dock first."));
        return;
    }
    const std::vector<std::int32_t> dab = facesUnderBrush(position);
    if (dab.empty())
        return;
    const algo::FaceSet* set = m_document->data().faceSet(m_patchTarget);
    const std::vector<std::int32_t> before = set ? set->faces : std::vector<std::int32_t>{};
    std::vector<std::int32_t> after;
    after.reserve(before.size() + dab.size());
    if (modifiers & Qt::ControlModifier)
        std::set_difference(before.begin(), before.end(), dab.begin(), dab.end(), std::back_inserter(after));
    else
        std::set_union(before.begin(), before.end(), dab.begin(), dab.end(), std::back_inserter(after));
    if (set && after == before)
        return;
    try {
        m_document->setFaceSet(m_patchTarget, std::move(after), tr("Paint Patch “%1”").arg(m_patchTarget), m_strokeId);
    } catch (const model::EditRefused& e) {
        emit message(e.message());
    }
}

void Viewport::updatePatchOverlay()
{
    Vtk& v = *m_vtk;
    const algo::FaceSet* set = (m_tool == Tool::Patch && m_document && m_document->hasMesh())
        ? m_document->data().faceSet(m_patchTarget)
        : nullptr;
    if (!set || set->faces.empty() || m_shape.rows() != m_document->data().baseMesh->vertexCount()) {
        if (v.patchActor->GetVisibility()) {
            v.patchActor->VisibilityOff();
            update();
        }
        return;
    }
    // Lifted by a thousandth of the model's size along the normals: no depth fighting with the
    // model under it, and too little to see.
    const algo::Faces& faces = m_document->data().baseMesh->faces;
    const algo::Positions normals = algo::vertexNormals(m_shape, faces);
    const float lift = float(1e-3 * m_bounds.diagonal().norm());
    vtkNew<vtkFloatArray> positions;
    positions->SetNumberOfComponents(3);
    positions->SetNumberOfTuples(m_shape.rows());
    float* p = positions->GetPointer(0);
    for (Eigen::Index i = 0; i < m_shape.rows(); ++i)
        for (int k = 0; k < 3; ++k)
            p[3 * i + k] = m_shape(i, k) + lift * normals(i, k);
    vtkNew<vtkPoints> points;
    points->SetData(positions);
    vtkNew<vtkCellArray> triangles;
    triangles->AllocateExact(vtkIdType(set->faces.size()), 3 * vtkIdType(set->faces.size()));
    for (const auto f : set->faces) {
        const vtkIdType ids[3] = {faces(f, 0), faces(f, 1), faces(f, 2)};
        triangles->InsertNextCell(3, ids);
    }
    v.patch->Initialize();
    v.patch->SetPoints(points);
    v.patch->SetPolys(triangles);
    v.patchActor->VisibilityOn();
    update();
}

// --- semi-automatic alignment ----------------------------------------------------------------

void Viewport::setPointMatching(bool on)
{
    m_matching = on;
    m_markers->setVisible(on || !m_modelPoints.empty() || !m_drawingPoints.empty());
    m_markers->setGeometry(rect());
    m_markers->update();
    if (on)
        emit message(tr("Click a feature on the model, then Shift+click the same feature on the drawing; "
                        "six pairs or more, then Solve Camera."));
}

void Viewport::clearMatchedPoints()
{
    m_modelPoints.clear();
    m_drawingPoints.clear();
    m_markers->setVisible(m_matching);
    m_markers->update();
    emit matchedPointsChanged();
}

void Viewport::removeLastMatchedPoint()
{
    if (m_drawingPoints.size() >= m_modelPoints.size() && !m_drawingPoints.empty())
        m_drawingPoints.pop_back();
    else if (!m_modelPoints.empty())
        m_modelPoints.pop_back();
    m_markers->update();
    emit matchedPointsChanged();
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

std::optional<double> Viewport::solveFromMatchedPoints(QString* error)
{
    const model::Drawing* drawing
        = (m_document && m_overlayDrawing) ? m_document->data().drawing(m_overlayDrawing) : nullptr;
    const size_t pairs = std::min(m_modelPoints.size(), m_drawingPoints.size());
    if (!drawing || drawing->image.isNull()) {
        if (error)
            *error = tr("Show a drawing to align first.");
        return std::nullopt;
    }
    if (pairs < 6) {
        if (error)
            *error = tr("%1 pairs of points so far; the camera needs at least six.").arg(pairs);
        return std::nullopt;
    }
    std::string message;
    const auto solved = algo::solveCamera(
        std::vector<Eigen::Vector3d>(m_modelPoints.begin(), m_modelPoints.begin() + std::ptrdiff_t(pairs)),
        std::vector<Eigen::Vector2d>(m_drawingPoints.begin(), m_drawingPoints.begin() + std::ptrdiff_t(pairs)),
        drawing->image.width(), drawing->image.height(), &message);
    if (!solved) {
        if (error)
            *error = tr("The camera could not be solved: %1").arg(QString::fromStdString(message));
        return std::nullopt;
    }
    model::Camera camera;
    camera.eye = solved->eye;
    camera.target = solved->target;
    camera.up = solved->up;
    camera.projection = model::Projection::Perspective;
    camera.fovYDegrees = solved->fovYDegrees;
    m_alignCommit.stop();
    setCamera(camera);
    m_alignCommit.stop();
    m_document->setDrawingCamera(m_overlayDrawing, camera);
    m_markers->update();
    return solved->rmsPixelError;
}

// --- OpenGL ---------------------------------------------------------------------------------

void Viewport::showEvent(QShowEvent* event)
{
    QOpenGLWidget::showEvent(event);
    if (m_observed)
        updateShape(); // catch up with what the main camera did while hidden
}

void Viewport::initializeGL()
{
    vtkGenericOpenGLRenderWindow* window = m_vtk->window;
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
    m_vtk->window->ReleaseGraphicsResources(m_vtk->window);
    m_initialized = false;
    doneCurrent();
}

void Viewport::resizeGL(int w, int h)
{
    const qreal dpr = devicePixelRatioF();
    m_vtk->window->SetSize(qRound(w * dpr), qRound(h * dpr));
    m_markers->setGeometry(0, 0, w, h);
    updateTriadViewport();
    refreshFrameScale();
    // A view framed by the program (load, F, Home) stays framed while the window is resized:
    // the widget's first size is only known here, after the constructor framed the model.
    if (m_framed)
        frameAll();
}

void Viewport::paintGL()
{
    if (!m_initialized)
        return;
    Vtk& v = *m_vtk;
    if (!v.cameraPlaced)
        frameAll();
    QElapsedTimer timer;
    timer.start();
    m_lineMilliseconds = 0.0;
    if (m_stereo != algo::StereoOutput::Off) {
        paintStereo();
    } else {
        const bool lines = linesShown();
        GlFrame frame;
        renderVtkFrame(false, lines, frame);
        if (lines) {
            // Only the pixels the strokes can touch go through the CPU: read them back, blend the
            // coverage in linear light (as the offline renderer), write them back.
            QElapsedTimer lineTimer;
            lineTimer.start();
            const algo::RasterCamera centre = vtkRasterCamera();
            std::vector<float> coverage;
            const QRect box = lineCoverage(centre, centre, frame.depth, coverage);
            if (!box.isEmpty()) {
                QImage region(box.size(), QImage::Format_RGBA8888);
                QOpenGLFunctions* gl = context()->functions();
                gl->glBindFramebuffer(GL_FRAMEBUFFER, defaultFramebufferObject());
                gl->glPixelStorei(GL_PACK_ALIGNMENT, 4);
                gl->glReadPixels(box.x(), centre.height - 1 - box.bottom(), box.width(), box.height(), GL_RGBA,
                    GL_UNSIGNED_BYTE, region.bits());
                region = region.mirrored();
                makeOpaque(region);
                blendLines(region, box.topLeft(), coverage, centre.width, currentLook().lineStyle.color);
                const qreal dpr = devicePixelRatioF();
                QPainter painter(this);
                painter.setCompositionMode(QPainter::CompositionMode_Source);
                painter.drawImage(QRectF(box.x() / dpr, box.y() / dpr, box.width() / dpr, box.height() / dpr), region);
            }
            m_lineMilliseconds = double(lineTimer.nsecsElapsed()) / 1e6;
        }
    }
    // Blending the drawing layer lowers the framebuffer's alpha, and Qt composites the widget
    // with it (premultiplied): the viewport must stay opaque whatever the layers did.
    QOpenGLFunctions* gl = context()->functions();
    gl->glBindFramebuffer(GL_FRAMEBUFFER, defaultFramebufferObject());
    gl->glDisable(GL_SCISSOR_TEST);
    gl->glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
    gl->glClearColor(0.f, 0.f, 0.f, 1.f);
    gl->glClear(GL_COLOR_BUFFER_BIT);
    gl->glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    m_frameMilliseconds = double(timer.nsecsElapsed()) / 1e6;
    ++m_renderCount;
}

void Viewport::renderVtkFrame(bool readColor, bool readDepth, GlFrame& out)
{
    Vtk& v = *m_vtk;
    // Qt touched the GL state (its framebuffer, depth function) since VTK last looked: make VTK
    // re-read it rather than trust its cache, and hand Qt its state back afterwards.
    vtkOpenGLState* state = v.window->GetState();
    state->Reset();
    state->Push();
    v.renderer->ResetCameraClippingRange();
    syncTriadCamera();
    v.windowDepth.clear();
    v.captureDepth = readDepth;
    v.window->Render();
    v.captureDepth = false;
    state->Pop();

    const int* size = v.window->GetSize();
    const int w = size[0], h = size[1];
    if (readDepth) {
        vtkCamera* cam = v.renderer->GetActiveCamera();
        double range[2];
        cam->GetClippingRange(range);
        out.depth = viewDepthFromWindowDepth(v.windowDepth, w, h, range[0], range[1], cam->GetParallelProjection());
    }
    if (readColor && w > 0 && h > 0) {
        out.color = QImage(w, h, QImage::Format_RGBA8888);
        QOpenGLFunctions* gl = context()->functions();
        gl->glBindFramebuffer(GL_FRAMEBUFFER, defaultFramebufferObject());
        gl->glPixelStorei(GL_PACK_ALIGNMENT, 4);
        gl->glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, out.color.bits());
        out.color = out.color.mirrored();
        makeOpaque(out.color);
    }
}

algo::RasterCamera Viewport::vtkRasterCamera() const
{
    vtkCamera* cam = m_vtk->renderer->GetActiveCamera();
    algo::RasterCamera r;
    r.eye = toEigen(cam->GetPosition());
    r.target = toEigen(cam->GetFocalPoint());
    r.up = toEigen(cam->GetViewUp());
    r.orthographic = cam->GetParallelProjection() != 0;
    // VTK's own angle and scale span the whole framebuffer height (a drawing's letterbox included).
    r.fovYDegrees = cam->GetViewAngle();
    r.orthoHeight = 2.0 * cam->GetParallelScale();
    const int* size = m_vtk->window->GetSize();
    r.width = size[0];
    r.height = size[1];
    // vtkCamera's window centre puts the view axis at NDC -x; RasterCamera's shift is in widths.
    r.horizontalShift = -0.5 * cam->GetWindowCenter()[0];
    return r;
}

QRect Viewport::lineCoverage(const algo::RasterCamera& camera, const algo::RasterCamera& lineEye,
    const std::vector<float>& depth, std::vector<float>& coverage)
{
    if (!m_document || !m_document->hasMesh())
        return {};
    const algo::TriMesh& mesh = *m_document->data().baseMesh;
    if (m_shape.rows() != mesh.vertices.rows())
        return {};
    const model::Look& look = currentLook();
    algo::LineView view;
    view.eye = lineEye.eye.cast<float>();
    view.direction = lineEye.forward().cast<float>();
    view.orthographic = lineEye.orthographic;
    m_lines->update(m_shape, mesh, view, look.lines);
    return m_lines->draw(m_shape, look.lineStyle, camera, depth, coverage);
}

void Viewport::paintStereo()
{
    Vtk& v = *m_vtk;
    vtkCamera* cam = v.renderer->GetActiveCamera();
    double position[3], focal[3], up[3], windowCenter[2];
    cam->GetPosition(position);
    cam->GetFocalPoint(focal);
    cam->GetViewUp(up);
    cam->GetWindowCenter(windowCenter);

    // Paper 3, section 3.1: the offline renderer's eye pair (off-axis by default) from VTK's
    // own projection; lines come from the centre eye (section 4.2.2), projected per eye.
    const algo::RasterCamera centre = vtkRasterCamera();
    const auto eyes = algo::stereoPair(centre, resolvedStereoSettings());
    const algo::RasterCamera* eyeCameras[2] = {&eyes.first, &eyes.second};
    const bool lines = linesShown();
    const model::Look& look = currentLook();
    GlFrame frames[2];
    QElapsedTimer lineTimer;
    qint64 lineNanoseconds = 0;
    for (int k = 0; k < 2; ++k) {
        if ((m_eyeOnly == Eye::Left && k == 1) || (m_eyeOnly == Eye::Right && k == 0))
            continue;
        const algo::RasterCamera& eye = *eyeCameras[k];
        cam->SetPosition(eye.eye.data());
        cam->SetFocalPoint(eye.target.data());
        cam->SetViewUp(eye.up.data());
        cam->SetWindowCenter(-2.0 * eye.horizontalShift, 0.0);
        renderVtkFrame(true, lines, frames[k]);
        if (lines && !frames[k].color.isNull()) {
            lineTimer.start();
            std::vector<float> coverage;
            if (!lineCoverage(eye, centre, frames[k].depth, coverage).isEmpty())
                blendLines(frames[k].color, QPoint(0, 0), coverage, eye.width, look.lineStyle.color);
            lineNanoseconds += lineTimer.nsecsElapsed();
        }
    }
    cam->SetPosition(position);
    cam->SetFocalPoint(focal);
    cam->SetViewUp(up);
    cam->SetWindowCenter(windowCenter[0], windowCenter[1]);
    m_lineMilliseconds = double(lineNanoseconds) / 1e6;

    QImage shown;
    if (m_eyeOnly == Eye::Left)
        shown = frames[0].color;
    else if (m_eyeOnly == Eye::Right)
        shown = frames[1].color;
    else if (!frames[0].color.isNull() && !frames[1].color.isNull())
        shown = toSrgb(
            composeStereo(m_stereo, toLinear(frames[0].color), toLinear(frames[1].color), stereoLook().dubois));
    if (shown.isNull())
        return;
    // Side by side and top-bottom are squeezed into the widget, as 3D displays expect them.
    QPainter painter(this);
    painter.setCompositionMode(QPainter::CompositionMode_Source);
    const bool squeezed = shown.size() != frames[0].color.size() && !frames[0].color.isNull();
    painter.setRenderHint(QPainter::SmoothPixmapTransform, squeezed);
    painter.drawImage(QRectF(rect()), shown);
}

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
    const Eigen::Vector3d centroid = mesh ? algo::centroid(m_document->data().baseMesh->vertices) : m_bounds.center();
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

const model::Look& Viewport::currentLook() const
{
    static const model::Look defaultLook;
    return m_document ? m_document->data().look : defaultLook;
}

void Viewport::setEyeOnly(Eye eye)
{
    m_eyeOnly = eye;
    update();
}

QImage Viewport::renderedImage()
{
    return grabFramebuffer();
}

// --- navigation -----------------------------------------------------------------------------

void Viewport::mousePressEvent(QMouseEvent* event)
{
    if (m_drag != Drag::None) {
        event->accept();
        return;
    }
    const Qt::KeyboardModifiers mods = event->modifiers();
    const Qt::MouseButton button = event->button();
    Drag drag = Drag::None;
    // Ctrl+left on the light gizmo's handle grabs the light (elsewhere Ctrl+left is the brush's).
    constexpr double kLightGrabPixels = 14.0;
    const bool onLight = m_vtk->lightActor->GetVisibility() && button == Qt::LeftButton && (mods & Qt::ControlModifier)
        && !(mods & Qt::AltModifier)
        && QLineF(projectToWidget(lightGizmoHandle()), event->position()).length() <= kLightGrabPixels;
    if (onLight) {
        drag = Drag::Light;
    } else if ((mods & Qt::AltModifier) && (mods & Qt::ShiftModifier) && button == Qt::LeftButton) {
        drag = Drag::Roll; // for matching a drawing's tilt (paper 1, section 3.1.1)
    } else if (mods & Qt::AltModifier) {
        // Maya: Alt + left orbit, middle pan, right dolly.
        if (button == Qt::LeftButton)
            drag = Drag::Orbit;
        else if (button == Qt::MiddleButton)
            drag = Drag::Pan;
        else if (button == Qt::RightButton)
            drag = Drag::Dolly;
    } else if (button == Qt::MiddleButton) {
        // Middle button alone for tablets and laptops where Alt is taken by the window manager.
        if (mods & Qt::ShiftModifier)
            drag = Drag::Pan;
        else if (mods & Qt::ControlModifier)
            drag = Drag::Dolly;
        else
            drag = Drag::Orbit;
    } else if (button == Qt::LeftButton && m_tool == Tool::Align && m_matching) {
        if (mods & Qt::ShiftModifier) {
            if (const auto pixel = widgetToDrawing(event->position())) {
                m_drawingPoints.push_back(*pixel);
            } else {
                emit message(tr("Shift+click inside the drawing to place its point."));
            }
        } else {
            const std::int64_t vertex = pickVertex(event->position());
            if (vertex >= 0) {
                // The picked surface point, not the nearest vertex: features rarely sit on one.
                m_modelPoints.push_back(toEigen(m_vtk->picker->GetPickPosition()));
            } else {
                emit message(tr("Click on the model to place a model point; Shift+click places the drawing point."));
            }
        }
        m_markers->setVisible(true);
        m_markers->update();
        emit matchedPointsChanged();
        event->accept();
        return;
    } else if (button == Qt::LeftButton && m_tool == Tool::Brush) {
        drag = Drag::Brush;
        beginBrush(event->position(), mods);
    } else if (button == Qt::LeftButton && m_tool == Tool::Highlight) {
        drag = Drag::Highlight;
        emit highlightDragStarted(event->position());
    } else if (button == Qt::LeftButton && m_tool == Tool::Patch) {
        drag = Drag::Patch;
        m_strokeId = m_document ? m_document->newStrokeId() : 0;
        m_patchGrid = {};
        paintPatch(event->position(), mods);
    }
    if (drag == Drag::None) {
        QOpenGLWidget::mousePressEvent(event);
        return;
    }
    m_drag = drag;
    m_dragButton = button;
    m_lastPos = event->position();
    switch (drag) {
    case Drag::Orbit:
        setCursor(Qt::ClosedHandCursor);
        break;
    case Drag::Pan:
        setCursor(Qt::SizeAllCursor);
        break;
    case Drag::Dolly:
        setCursor(Qt::SizeVerCursor);
        break;
    case Drag::Roll:
        setCursor(Qt::SizeHorCursor);
        break;
    case Drag::Light:
        setCursor(Qt::ClosedHandCursor);
        break;
    case Drag::Brush:
    case Drag::Highlight:
    case Drag::Patch:
    case Drag::None:
        break;
    }
    event->accept();
}

void Viewport::mouseMoveEvent(QMouseEvent* event)
{
    if (m_drag == Drag::None) {
        QOpenGLWidget::mouseMoveEvent(event);
        return;
    }
    if (!(event->buttons() & m_dragButton)) {
        // The release went elsewhere (a popup, a window manager grab): end the drag here.
        if (m_drag == Drag::Brush)
            endBrush();
        if (m_drag == Drag::Highlight)
            emit highlightDragFinished();
        if (m_drag == Drag::Patch)
            m_strokeId = 0;
        m_drag = Drag::None;
        m_dragButton = Qt::NoButton;
        unsetCursor();
        return;
    }
    const QPointF delta = event->position() - m_lastPos;
    m_lastPos = event->position();
    if (delta.isNull())
        return;
    switch (m_drag) {
    case Drag::Orbit:
        orbit(delta.x() * kOrbitDegreesPerPixel, delta.y() * kOrbitDegreesPerPixel);
        break;
    case Drag::Pan:
        pan(delta);
        break;
    // Dragging right or up brings the camera closer.
    case Drag::Dolly:
        dolly(std::exp(-kDollyPerPixel * (delta.x() - delta.y())));
        break;
    case Drag::Roll:
        roll(delta.x() * kOrbitDegreesPerPixel);
        break;
    case Drag::Brush:
        brushMove(delta, event->modifiers());
        break;
    case Drag::Light:
        dragLight(event->position());
        break;
    case Drag::Highlight:
        emit highlightDragged(delta, event->modifiers());
        break;
    case Drag::Patch:
        paintPatch(event->position(), event->modifiers());
        break;
    case Drag::None:
        break;
    }
    event->accept();
}

void Viewport::mouseReleaseEvent(QMouseEvent* event)
{
    if (m_drag != Drag::None && event->button() == m_dragButton) {
        if (m_drag == Drag::Brush)
            endBrush();
        if (m_drag == Drag::Highlight)
            emit highlightDragFinished();
        if (m_drag == Drag::Patch)
            m_strokeId = 0;
        m_drag = Drag::None;
        m_dragButton = Qt::NoButton;
        unsetCursor();
        event->accept();
        return;
    }
    QOpenGLWidget::mouseReleaseEvent(event);
}

void Viewport::wheelEvent(QWheelEvent* event)
{
    const double notches = event->angleDelta().y() / 120.0;
    if (notches == 0.0) {
        event->ignore();
        return;
    }
    dolly(std::pow(kDollyPerWheelNotch, notches));
    event->accept();
}

void Viewport::keyPressEvent(QKeyEvent* event)
{
    if (event->key() == Qt::Key_F && !(event->modifiers() & (Qt::ControlModifier | Qt::AltModifier))) {
        frameAll();
        event->accept();
        return;
    }
    if (event->key() == Qt::Key_Home) {
        resetView();
        event->accept();
        return;
    }
    // Krita's and Photoshop's brush-size keys.
    if (event->key() == Qt::Key_BracketLeft || event->key() == Qt::Key_BracketRight) {
        setBrushRadius(m_brushRadius * (event->key() == Qt::Key_BracketRight ? 1.25 : 0.8));
        emit message(tr("Brush radius %1").arg(m_brushRadius, 0, 'g', 3));
        event->accept();
        return;
    }
    QOpenGLWidget::keyPressEvent(event);
}

// --- the cartoon look and its key light ---------------------------------------------------------

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
    Vtk& v = *m_vtk;
    if (!v.look)
        return; // still constructing
    const bool hasMesh = m_document && m_document->hasMesh() && v.mesh->GetNumberOfPoints() > 0;
    // Brush selection colours are VTK scalars, shown by the clay material: the look steps aside
    // while they are displayed rather than tinting its tones (which would read as a tone change).
    const bool selectionShown = v.meshMapper->GetScalarVisibility() != 0;
    const bool active = m_shadingEnabled && hasMesh && !selectionShown;
    v.look->setActive(active);
    if (m_shadingEnabled && hasMesh) {
        // What the offline render shows: the look's flat background (8-bit sRGB, as the PNG has
        // it) and no ground grid.
        const Eigen::Vector3f bg = m_document->data().look.backgroundColor;
        double encoded[3];
        for (int c = 0; c < 3; ++c)
            encoded[c] = double(std::lround(algo::linearToSrgb(std::clamp(bg[c], 0.f, 1.f)) * 255.f)) / 255.0;
        v.renderer->GradientBackgroundOff();
        v.renderer->SetBackground(encoded);
        v.gridActor->VisibilityOff();
    } else {
        v.renderer->GradientBackgroundOn();
        v.renderer->SetBackground(m_clayBottom.redF(), m_clayBottom.greenF(), m_clayBottom.blueF());
        v.renderer->SetBackground2(m_clayTop.redF(), m_clayTop.greenF(), m_clayTop.blueF());
        v.gridActor->VisibilityOn();
    }
    v.lightActor->SetVisibility(m_lightGizmoVisible && m_shadingEnabled && hasMesh);
}

void Viewport::updateLookShading()
{
    Vtk& v = *m_vtk;
    if (!v.look || !m_document || !m_document->hasMesh() || !v.normals || m_shape.rows() == 0
        || v.normals->GetNumberOfTuples() != vtkIdType(m_shape.rows()))
        return;
    v.look->update(m_document->data(), m_shape, v.normals->GetPointer(0), m_frame);
}

void Viewport::setFrame(int frame)
{
    if (frame == m_frame)
        return;
    m_frame = frame;
    updateLookShading();
    update();
    emit frameChanged(frame);
}

double Viewport::lightGizmoRadius() const
{
    return std::max(0.5 * m_bounds.diagonal().norm(), 1e-6);
}

Eigen::Vector3d Viewport::lightGizmoHandle() const
{
    const model::Light light = m_document ? m_document->data().look.light : model::Light{};
    if (light.type == model::LightType::Point)
        return light.vector;
    Eigen::Vector3d direction = light.vector.normalized();
    if (!direction.allFinite())
        direction = Eigen::Vector3d::UnitZ();
    return m_bounds.center() + 1.3 * lightGizmoRadius() * direction;
}

void Viewport::updateLightGizmo()
{
    Vtk& v = *m_vtk;
    const model::Light light = m_document ? m_document->data().look.light : model::Light{};
    const double radius = lightGizmoRadius();
    if (light.type == model::LightType::Point) {
        vtkNew<vtkSphereSource> sphere;
        sphere->SetCenter(light.vector.data());
        sphere->SetRadius(0.04 * radius);
        sphere->SetThetaResolution(20);
        sphere->SetPhiResolution(12);
        sphere->Update();
        v.lightMapper->SetInputData(sphere->GetOutput());
        return;
    }
    // An arrow at the edge of the bounding sphere pointing from the model towards the light.
    Eigen::Vector3d x = light.vector.normalized();
    if (!x.allFinite())
        x = Eigen::Vector3d::UnitZ();
    Eigen::Vector3d y = x.cross(std::abs(x.y()) < 0.9 ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitX());
    y.normalize();
    const Eigen::Vector3d z = x.cross(y);
    const double length = 0.3 * radius;
    const Eigen::Vector3d start = m_bounds.center() + radius * x;
    vtkNew<vtkTransform> transform;
    const double matrix[16]
        = {length * x.x(), length * y.x(), length * z.x(), start.x(), length * x.y(), length * y.y(), length * z.y(),
            start.y(), length * x.z(), length * y.z(), length * z.z(), start.z(), 0.0, 0.0, 0.0, 1.0};
    transform->SetMatrix(matrix);
    vtkNew<vtkArrowSource> arrow;
    arrow->SetTipResolution(20);
    arrow->SetShaftResolution(12);
    arrow->SetShaftRadius(0.05);
    arrow->SetTipRadius(0.14);
    arrow->SetTipLength(0.35);
    vtkNew<vtkTransformPolyDataFilter> filter;
    filter->SetInputConnection(arrow->GetOutputPort());
    filter->SetTransform(transform);
    filter->Update();
    v.lightMapper->SetInputData(filter->GetOutput());
}

void Viewport::dragLight(const QPointF& position)
{
    if (!m_document || !m_document->hasMesh())
        return;
    vtkRenderer* renderer = m_vtk->renderer;
    const qreal dpr = devicePixelRatioF();
    const double x = position.x() * dpr, y = (height() - position.y()) * dpr;
    auto unproject = [&](double depth) {
        renderer->SetDisplayPoint(x, y, depth);
        renderer->DisplayToWorld();
        const double* w = renderer->GetWorldPoint();
        return Eigen::Vector3d(w[0] / w[3], w[1] / w[3], w[2] / w[3]);
    };
    const Eigen::Vector3d origin = unproject(0.0);
    const Eigen::Vector3d direction = (unproject(1.0) - origin).normalized();
    if (!direction.allFinite())
        return;

    // The handle moves on a sphere about the model's centre: the arrow tip's for a directional
    // light, the light's own distance for a point light. It stays on the side (towards or away
    // from the viewer) it was on; off the sphere it follows the silhouette.
    model::Look look = m_document->data().look;
    const Eigen::Vector3d centre = m_bounds.center();
    const Eigen::Vector3d handle = lightGizmoHandle();
    double radius = (handle - centre).norm();
    if (!(radius > 1e-9))
        radius = lightGizmoRadius();
    const Eigen::Vector3d toCentre = centre - origin;
    const double along = toCentre.dot(direction);
    const Eigen::Vector3d closest = origin + along * direction;
    const double miss2 = (closest - centre).squaredNorm();
    Eigen::Vector3d onSphere;
    if (miss2 <= radius * radius) {
        const double half = std::sqrt(radius * radius - miss2);
        const bool front = (handle - centre).dot(-direction) >= 0.0;
        onSphere = closest + (front ? -half : half) * direction;
    } else {
        onSphere = centre + radius * (closest - centre).normalized();
    }
    const Eigen::Vector3d unit = (onSphere - centre).normalized();
    if (!unit.allFinite())
        return;
    look.light.vector = look.light.type == model::LightType::Point ? Eigen::Vector3d(centre + radius * unit) : unit;
    m_document->setLook(look); // consecutive look edits merge: one drag, one undo step
}

} // namespace celform::views
