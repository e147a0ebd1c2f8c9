// VTK objects of the viewport: a vtkGenericOpenGLRenderWindow drawing into the QOpenGLWidget's
// framebuffer (docs/pitfalls.md, "VTK in a Qt 6 widget") with four layers: 0 background (the drawing when it is under
// the model, else the model), 1 the model over a drawing, 2 a drawing over the model, 3 the axes triad.
#include "celform/views/viewport/viewport_scene.h"

#include "celform/algorithms/shading.h"
#include "celform/views/viewport/look_shading.h"

#include <vtkActor.h>
#include <vtkArrowSource.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellPicker.h>
#include <vtkCommand.h>
#include <vtkFloatArray.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkImageActor.h>
#include <vtkImageData.h>
#include <vtkImageProperty.h>
#include <vtkLightKit.h>
#include <vtkNew.h>
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
#include <cmath>
#include <cstring>

namespace celform::views {
namespace {

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

Eigen::Vector3d toEigen(const double v[3])
{
    return {v[0], v[1], v[2]};
}

} // namespace

struct ViewportScene::Vtk {
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
    QColor clayTop{200, 201, 204};
    QColor clayBottom{150, 151, 155};
};

ViewportScene::ViewportScene()
    : m(std::make_unique<Vtk>())
{
    Vtk& v = *m;
    // The context belongs to Qt; VTK only draws into the framebuffer Qt has bound in paintGL.
    v.window->SetOwnContext(false);
    v.window->SetIsCurrent(true);
    // Antialiasing is VTK's: it resolves its own multisampled buffer before blitting into Qt's,
    // which must stay single-sampled (see Viewport::defaultFormat()). FXAA is not an option: its
    // pass re-binds framebuffers behind Qt and the frame comes out black.
    v.window->SetMultiSamples(4); // see Viewport::initializeGL() for software GL
    v.window->SetNumberOfLayers(4);
    v.window->AddRenderer(v.renderer);
    v.window->AddRenderer(v.drawingRenderer);
    v.window->AddRenderer(v.triadRenderer);

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
    // The look replaces this clay material while shading is enabled (applyShading()).
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

    // The triad lives in a layer of its own with a camera that only copies the orientation of
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

    v.depthCapture->SetClientData(m.get());
    v.depthCapture->SetCallback([](vtkObject*, unsigned long, void* clientData, void*) {
        Vtk& vtk = *static_cast<Vtk*>(clientData);
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
    setClayBackground(v.clayTop, v.clayBottom);
}

ViewportScene::~ViewportScene() = default;

vtkGenericOpenGLRenderWindow* ViewportScene::window() const
{
    return m->window;
}

vtkRenderer* ViewportScene::renderer() const
{
    return m->renderer;
}

vtkCamera* ViewportScene::camera() const
{
    return m->renderer->GetActiveCamera();
}

LookShading& ViewportScene::look() const
{
    return *m->look;
}

// --- the model ---------------------------------------------------------------------------------

void ViewportScene::setMesh(const algo::TriMesh* mesh)
{
    Vtk& v = *m;
    if (!mesh || mesh->vertexCount() == 0) {
        v.mesh->Initialize();
        v.positions = nullptr;
        v.normals = nullptr;
        v.meshActor->VisibilityOff();
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
    std::memcpy(v.normals->GetPointer(0), mesh->normals().data(), sizeof(float) * 3 * size_t(vertexCount));
    v.positions = positions;

    v.mesh->Initialize();
    v.mesh->SetPoints(points);
    v.mesh->SetPolys(triangles);
    v.mesh->GetPointData()->SetNormals(v.normals);
    v.meshActor->VisibilityOn();
}

bool ViewportScene::hasMesh() const
{
    return m->positions != nullptr && m->mesh->GetNumberOfPoints() > 0;
}

void ViewportScene::uploadShape(const algo::Positions& shape, const algo::Positions& normals)
{
    Vtk& v = *m;
    if (!v.positions || v.positions->GetNumberOfTuples() != vtkIdType(shape.rows()) || normals.rows() != shape.rows())
        return;
    const auto count = std::size_t(shape.rows());
    std::memcpy(v.positions->GetPointer(0), shape.data(), sizeof(float) * 3 * count);
    v.positions->Modified();
    std::memcpy(v.normals->GetPointer(0), normals.data(), sizeof(float) * 3 * count);
    v.normals->Modified();
    v.mesh->Modified();
}

void ViewportScene::uploadRows(
    const algo::Positions& shape, const algo::Positions& normals, const std::vector<std::uint32_t>& rows)
{
    Vtk& v = *m;
    if (!v.positions || v.positions->GetNumberOfTuples() != vtkIdType(shape.rows()) || normals.rows() != shape.rows())
        return;
    // Written in place: the arrays keep their storage and VTK sees a modified array.
    float* positions = v.positions->GetPointer(0);
    float* normalRows = v.normals->GetPointer(0);
    for (const std::uint32_t r : rows) {
        if (Eigen::Index(r) >= shape.rows())
            continue;
        for (int k = 0; k < 3; ++k) {
            positions[3 * std::size_t(r) + std::size_t(k)] = shape(Eigen::Index(r), k);
            normalRows[3 * std::size_t(r) + std::size_t(k)] = normals(Eigen::Index(r), k);
        }
    }
    v.positions->Modified();
    v.normals->Modified();
    v.mesh->Modified();
}

const float* ViewportScene::normals() const
{
    return m->normals ? m->normals->GetPointer(0) : nullptr;
}

void ViewportScene::setSelectionColors(
    const algo::BrushSelection* selection, const algo::BrushSelection* mirror, Eigen::Index vertexCount)
{
    Vtk& v = *m;
    const bool any = (selection && !selection->indices.empty()) || (mirror && !mirror->indices.empty());
    if (!any || vertexCount == 0) {
        v.meshMapper->ScalarVisibilityOff();
        v.mesh->GetPointData()->SetScalars(nullptr);
        return;
    }
    v.colors->SetNumberOfTuples(vertexCount);
    unsigned char* c = v.colors->GetPointer(0);
    const unsigned char base[3] = {204, 196, 184};
    for (Eigen::Index i = 0; i < vertexCount; ++i)
        std::memcpy(c + 3 * i, base, 3);
    auto paint = [c, &base](const algo::BrushSelection* s) {
        if (!s)
            return;
        for (size_t k = 0; k < s->indices.size(); ++k) {
            const float w = s->weights[k];
            unsigned char* p = c + 3 * size_t(s->indices[k]);
            const float red[3] = {230.f, 40.f, 30.f};
            for (int j = 0; j < 3; ++j)
                p[j] = static_cast<unsigned char>(std::lround(base[j] + (red[j] - base[j]) * (0.25f + 0.75f * w)));
        }
    };
    paint(selection);
    paint(mirror);
    v.colors->Modified();
    v.mesh->GetPointData()->SetScalars(v.colors);
    v.meshMapper->ScalarVisibilityOn();
}

bool ViewportScene::selectionShown() const
{
    return m->meshMapper->GetScalarVisibility() != 0;
}

// --- surroundings --------------------------------------------------------------------------------

void ViewportScene::rebuildGrid(const Eigen::AlignedBox3d& bounds)
{
    // A ground grid under the model (Y up), with a round spacing a little under a tenth of its
    // size, so the floor reads as scale without competing with the model.
    const Eigen::Vector3d center = bounds.center();
    const Eigen::Vector3d size = bounds.sizes();
    const double extent = std::max({size.x(), size.z(), 0.5 * size.y(), 1e-6});
    const double spacing = std::pow(10.0, std::floor(std::log10(extent / 4.0)));
    const int halfLines = std::min(int(std::ceil(extent / spacing)), 40);
    const double half = halfLines * spacing;
    const double y = bounds.min().y();
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
    m->grid->Initialize();
    m->grid->SetPoints(points);
    m->grid->SetLines(lines);
    m->grid->Modified();
}

void ViewportScene::setClayBackground(const QColor& top, const QColor& bottom)
{
    Vtk& v = *m;
    v.renderer->SetBackground2(top.redF(), top.greenF(), top.blueF());
    v.renderer->SetBackground(bottom.redF(), bottom.greenF(), bottom.blueF());
    v.drawingRenderer->SetBackground2(top.redF(), top.greenF(), top.blueF());
    v.drawingRenderer->SetBackground(bottom.redF(), bottom.greenF(), bottom.blueF());
    // The grid is a shade of the background: visible, never louder than the model.
    const double r = 0.5 * (top.redF() + bottom.redF()), g = 0.5 * (top.greenF() + bottom.greenF()),
                 b = 0.5 * (top.blueF() + bottom.blueF());
    v.gridActor->GetProperty()->SetColor(r * 0.82, g * 0.82, b * 0.82);
    v.clayTop = top;
    v.clayBottom = bottom;
}

void ViewportScene::applyShading(
    bool lookActive, bool lookBackground, const Eigen::Vector3f& background, bool showLight)
{
    Vtk& v = *m;
    v.look->setActive(lookActive);
    if (lookBackground) {
        // What the offline render shows: the look's flat background (8-bit sRGB, as the PNG has
        // it) and no ground grid.
        double encoded[3];
        for (int c = 0; c < 3; ++c)
            encoded[c] = double(std::lround(algo::linearToSrgb(std::clamp(background[c], 0.f, 1.f)) * 255.f)) / 255.0;
        v.renderer->GradientBackgroundOff();
        v.renderer->SetBackground(encoded);
        v.gridActor->VisibilityOff();
    } else {
        v.renderer->GradientBackgroundOn();
        v.renderer->SetBackground(v.clayBottom.redF(), v.clayBottom.greenF(), v.clayBottom.blueF());
        v.renderer->SetBackground2(v.clayTop.redF(), v.clayTop.greenF(), v.clayTop.blueF());
        v.gridActor->VisibilityOn();
    }
    v.lightActor->SetVisibility(showLight);
}

void ViewportScene::setLightGizmo(const model::Light& light, const Eigen::Vector3d& centre, double radius)
{
    Vtk& v = *m;
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
    const Eigen::Vector3d start = centre + radius * x;
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

bool ViewportScene::lightGizmoVisible() const
{
    return m->lightActor->GetVisibility() != 0;
}

void ViewportScene::setPatchOverlay(const algo::Positions& shape, const algo::Positions& normals,
    const algo::Faces& faces, const algo::FaceSet* set, float lift)
{
    Vtk& v = *m;
    if (!set || set->faces.empty() || normals.rows() != shape.rows()) {
        v.patchActor->VisibilityOff();
        return;
    }
    vtkNew<vtkFloatArray> positions;
    positions->SetNumberOfComponents(3);
    positions->SetNumberOfTuples(shape.rows());
    float* p = positions->GetPointer(0);
    for (Eigen::Index i = 0; i < shape.rows(); ++i)
        for (int k = 0; k < 3; ++k)
            p[3 * i + k] = shape(i, k) + lift * normals(i, k);
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
}

void ViewportScene::placeTriad(int width, int height, int cornerPixels)
{
    Vtk& v = *m;
    const double w = std::max(width, 1), h = std::max(height, 1);
    const double side = std::min(double(cornerPixels), 0.3 * std::min(w, h));
    v.triadRenderer->SetViewport(0.0, 0.0, side / w, side / h);
    vtkCamera* main = v.renderer->GetActiveCamera();
    vtkCamera* triad = v.triadRenderer->GetActiveCamera();
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

// --- the reference drawing ----------------------------------------------------------------------

void ViewportScene::setDrawing(const QImage* image, bool onTop, double opacity)
{
    Vtk& v = *m;
    if (!image || image->isNull()) {
        v.drawingActor->VisibilityOff();
        v.renderer->SetLayer(0);
        v.drawingRenderer->SetLayer(2);
        return;
    }
    if (image->cacheKey() != v.drawingImageKey) {
        // VTK images start at the bottom row: copy the rows upside down.
        const QImage rgba = image->convertToFormat(QImage::Format_RGBA8888);
        v.drawingImage->SetDimensions(rgba.width(), rgba.height(), 1);
        v.drawingImage->AllocateScalars(VTK_UNSIGNED_CHAR, 4);
        auto* dst = static_cast<unsigned char*>(v.drawingImage->GetScalarPointer());
        for (int y = 0; y < rgba.height(); ++y)
            std::memcpy(dst + size_t(y) * size_t(rgba.width()) * 4, rgba.constScanLine(rgba.height() - 1 - y),
                size_t(rgba.width()) * 4);
        v.drawingImage->Modified();
        v.drawingImageKey = image->cacheKey();
        // The image's height fills the view, as the vertical field of view of an aligned camera.
        vtkCamera* cam = v.drawingRenderer->GetActiveCamera();
        const double cx = 0.5 * (rgba.width() - 1), cy = 0.5 * (rgba.height() - 1);
        cam->SetFocalPoint(cx, cy, 0.0);
        cam->SetPosition(cx, cy, 1000.0);
        cam->SetViewUp(0.0, 1.0, 0.0);
        cam->SetClippingRange(1.0, 2000.0);
    }
    v.drawingActor->VisibilityOn();
    v.drawingActor->SetOpacity(onTop ? std::clamp(opacity, 0.0, 1.0) : 1.0);
    if (onTop) {
        v.renderer->SetLayer(0);
        v.drawingRenderer->SetLayer(2);
    } else {
        v.drawingRenderer->SetLayer(0);
        v.renderer->SetLayer(1);
    }
}

void ViewportScene::fitDrawing(int width, int height)
{
    Vtk& v = *m;
    if (!v.drawingActor->GetVisibility())
        return;
    int dims[3];
    v.drawingImage->GetDimensions(dims);
    if (dims[0] > 0 && dims[1] > 0 && width > 0 && height > 0) {
        const double fit = std::min(double(width) / dims[0], double(height) / dims[1]);
        v.drawingRenderer->GetActiveCamera()->SetParallelScale(0.5 * height / fit);
    }
}

// --- picking and depth --------------------------------------------------------------------------

std::optional<ViewportScene::Pick> ViewportScene::pick(double x, double y) const
{
    Vtk& v = *m;
    if (!hasMesh() || !v.meshActor->GetVisibility())
        return std::nullopt;
    v.renderer->ResetCameraClippingRange();
    const int hit = v.picker->Pick(x, y, 0.0, v.renderer);
    const vtkIdType cell = v.picker->GetCellId();
    if (!hit || cell < 0 || cell >= v.mesh->GetNumberOfCells())
        return std::nullopt;
    return Pick{std::int64_t(cell), toEigen(v.picker->GetPickPosition())};
}

void ViewportScene::captureDepthOnNextRender(bool on)
{
    // Turning the capture off after the render keeps what it read: the compositor reads it then
    // (clearing it here left the lines without depth, so hidden lines were drawn too).
    if (on)
        m->windowDepth.clear();
    m->captureDepth = on;
}

const std::vector<float>& ViewportScene::capturedDepth() const
{
    return m->windowDepth;
}

} // namespace celform::views
