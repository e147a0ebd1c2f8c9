// The camera path and the current camera in the Observer view (camera_path_overlay.h).
#include "celform/views/overlays/camera_path_overlay.h"

#include "celform/model/document/document.h"
#include "celform/views/viewport/viewport.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cmath>

namespace celform::views {
namespace {

constexpr double kPathColor[3] = {0.27, 0.59, 0.92};
constexpr double kGlyphColor[3] = {0.95, 0.45, 0.15};

void styleActor(vtkActor* actor, vtkPolyData* data, const double color[3])
{
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(data);
    mapper->ScalarVisibilityOff();
    actor->SetMapper(mapper);
    actor->PickableOff();
    // Unlit, flat colour: a diagram in the scene, not part of the model.
    vtkProperty* property = actor->GetProperty();
    property->SetColor(color[0], color[1], color[2]);
    property->SetAmbient(1.0);
    property->SetDiffuse(0.0);
    property->SetSpecular(0.0);
    property->SetLineWidth(2.0f);
    property->SetPointSize(6.0f);
}

} // namespace

struct CameraPathOverlay::Props {
    vtkNew<vtkPolyData> path;
    vtkNew<vtkActor> pathActor;
    vtkNew<vtkPolyData> glyph;
    vtkNew<vtkActor> glyphActor;
};

CameraPathOverlay::CameraPathOverlay(Viewport* observer, Viewport* driver)
    : QObject(observer)
    , m_observer(observer)
    , m_driver(driver)
    , m_document(observer->document())
    , m_props(std::make_unique<Props>())
{
    setObjectName(QStringLiteral("cameraPathOverlay"));
    styleActor(m_props->pathActor, m_props->path, kPathColor);
    styleActor(m_props->glyphActor, m_props->glyph, kGlyphColor);
    m_props->glyphActor->GetProperty()->SetOpacity(0.85);
    observer->modelRenderer()->AddActor(m_props->pathActor);
    observer->modelRenderer()->AddActor(m_props->glyphActor);
    connect(m_document, &model::Document::changed, this, &CameraPathOverlay::documentChanged);
    if (driver)
        connect(driver, &Viewport::cameraChanged, this, &CameraPathOverlay::updateGlyph);
    measureModel();
    rebuildPath();
    updateGlyph();
}

// The observer's renderer holds its own references to the actors, and the overlay dies with the
// observer (whose scene is gone by then): nothing to take out.
CameraPathOverlay::~CameraPathOverlay() = default;

vtkPolyData* CameraPathOverlay::pathPolyData() const
{
    return m_props->path;
}

vtkPolyData* CameraPathOverlay::cameraGlyph() const
{
    return m_props->glyph;
}

void CameraPathOverlay::setVisible(bool on)
{
    m_visible = on;
    rebuildPath();
    updateGlyph();
}

void CameraPathOverlay::documentChanged(const model::ChangeSet& change)
{
    using model::Part;
    if (change.reset || change.has(Part::CameraPath) || change.has(Part::Mesh))
        rebuildPath();
    if (change.reset || change.has(Part::Mesh)) {
        measureModel();
        updateGlyph();
    }
}

void CameraPathOverlay::measureModel()
{
    m_modelSize = 1.0;
    if (!m_document->hasMesh())
        return;
    const algo::Positions& v = m_document->data().baseMesh->vertices;
    if (v.rows() == 0)
        return;
    const Eigen::Vector3f extent = v.colwise().maxCoeff() - v.colwise().minCoeff();
    m_modelSize = std::max(1e-9, double(extent.norm()));
}

void CameraPathOverlay::rebuildPath()
{
    const auto& keys = m_document->data().look.cameraPath.keys;
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(vtkIdType(keys.size()));
    vtkNew<vtkCellArray> line;
    vtkNew<vtkCellArray> verts;
    line->InsertNextCell(vtkIdType(keys.size()));
    for (std::size_t i = 0; i < keys.size(); ++i) {
        const Eigen::Vector3d& eye = keys[i].camera.eye;
        points->SetPoint(vtkIdType(i), eye.x(), eye.y(), eye.z());
        line->InsertCellPoint(vtkIdType(i));
        verts->InsertNextCell(1);
        verts->InsertCellPoint(vtkIdType(i));
    }
    m_props->path->SetPoints(points);
    m_props->path->SetLines(keys.size() >= 2 ? line.GetPointer() : vtkNew<vtkCellArray>().GetPointer());
    m_props->path->SetVerts(verts);
    m_props->path->Modified();
    m_props->pathActor->SetVisibility(m_visible && !keys.empty());
    if (m_observer)
        m_observer->update();
}

void CameraPathOverlay::updateGlyph()
{
    if (!m_driver || !m_document->hasMesh()) {
        m_props->glyphActor->SetVisibility(false);
        return;
    }
    m_camera = m_driver->camera();
    // A pyramid: apex at the eye, its base a view rectangle in front of it, a quarter of the
    // model's size away, so it reads at any distance from the model.
    const Eigen::Vector3d forward = m_camera.forward();
    const Eigen::Vector3d right = m_camera.right();
    const Eigen::Vector3d up = m_camera.trueUp();
    const double length = 0.25 * m_modelSize;
    const double aspect = m_driver->height() > 0 ? double(m_driver->width()) / m_driver->height() : 1.0;
    const double halfHeight = m_camera.projection == model::Projection::Perspective
        ? length * std::tan(0.5 * m_camera.fovYDegrees * M_PI / 180.0)
        : 0.5 * length;
    const double halfWidth = halfHeight * aspect;
    const Eigen::Vector3d centre = m_camera.eye + length * forward;
    const Eigen::Vector3d corners[4]
        = {centre - halfWidth * right - halfHeight * up, centre + halfWidth * right - halfHeight * up,
            centre + halfWidth * right + halfHeight * up, centre - halfWidth * right + halfHeight * up};
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->InsertNextPoint(m_camera.eye.data());
    for (const Eigen::Vector3d& c : corners)
        points->InsertNextPoint(c.data());
    // A small triangle over the top edge marks which way is up, as camera icons do.
    const Eigen::Vector3d topMid = centre + halfHeight * up;
    points->InsertNextPoint(Eigen::Vector3d(topMid - 0.4 * halfWidth * right).data());
    points->InsertNextPoint(Eigen::Vector3d(topMid + 0.4 * halfWidth * right).data());
    points->InsertNextPoint(Eigen::Vector3d(topMid + 0.5 * halfHeight * up).data());
    vtkNew<vtkCellArray> faces;
    for (vtkIdType i = 0; i < 4; ++i) {
        const vtkIdType tri[3] = {0, 1 + i, 1 + (i + 1) % 4};
        faces->InsertNextCell(3, tri);
    }
    const vtkIdType upMark[3] = {5, 6, 7};
    faces->InsertNextCell(3, upMark);
    vtkNew<vtkCellArray> lines;
    const vtkIdType rim[5] = {1, 2, 3, 4, 1};
    lines->InsertNextCell(5, rim);
    m_props->glyph->SetPoints(points);
    m_props->glyph->SetPolys(faces);
    m_props->glyph->SetLines(lines);
    m_props->glyph->Modified();
    m_props->glyphActor->SetVisibility(m_visible);
    if (m_observer)
        m_observer->update();
}

} // namespace celform::views
