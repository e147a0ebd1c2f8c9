// The control cage's wireframe actor (control_cage.h).
#include "celform/views/viewport/control_cage.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTypeInt32Array.h>

#include <cstring>

namespace celform::views {

struct ControlCage::Vtk {
    vtkNew<vtkPolyData> cage;
    vtkNew<vtkPolyDataMapper> mapper;
    vtkNew<vtkActor> actor;
    vtkNew<vtkFloatArray> positions;
    const algo::TriMesh* mesh = nullptr;
    std::uint64_t generation = 0;
};

ControlCage::ControlCage(vtkRenderer* renderer)
    : m(std::make_unique<Vtk>())
{
    m->positions->SetNumberOfComponents(3);
    m->mapper->SetInputData(m->cage);
    m->mapper->ScalarVisibilityOff();
    m->actor->SetMapper(m->mapper);
    vtkProperty* p = m->actor->GetProperty();
    p->SetRepresentationToWireframe();
    p->LightingOff();
    p->SetColor(0.16, 0.30, 0.62); // Maya's cage blue, dark enough over light tones
    p->SetLineWidth(1.0);
    p->SetOpacity(0.8);
    m->actor->PickableOff();
    m->actor->VisibilityOff();
    renderer->AddActor(m->actor);
}

ControlCage::~ControlCage() = default;

bool ControlCage::isShown() const
{
    return m->actor->GetVisibility() != 0;
}

void ControlCage::show(const algo::TriMesh* mesh, const algo::Shape* shape)
{
    Vtk& v = *m;
    if (!mesh || !shape || shape->positions.rows() != mesh->vertexCount() || mesh->vertexCount() == 0) {
        v.actor->VisibilityOff();
        v.mesh = nullptr; // the topology is rebuilt when shown again (the mesh may be another)
        return;
    }
    v.actor->VisibilityOn();
    const auto count = vtkIdType(mesh->vertexCount());
    if (mesh != v.mesh) {
        // 32-bit connectivity shared in layout with algo::Faces, as the model's own polydata.
        const auto faces = vtkIdType(mesh->faceCount());
        vtkNew<vtkTypeInt32Array> connectivity;
        connectivity->SetNumberOfTuples(3 * faces);
        std::memcpy(connectivity->GetPointer(0), mesh->faces.data(), sizeof(std::int32_t) * 3 * std::size_t(faces));
        vtkNew<vtkTypeInt32Array> offsets;
        offsets->SetNumberOfTuples(faces + 1);
        for (vtkIdType f = 0; f <= faces; ++f)
            offsets->SetValue(f, std::int32_t(3 * f));
        vtkNew<vtkCellArray> triangles;
        triangles->SetData(offsets, connectivity);
        v.positions->SetNumberOfTuples(count);
        vtkNew<vtkPoints> points;
        points->SetData(v.positions);
        v.cage->Initialize();
        v.cage->SetPoints(points);
        v.cage->SetPolys(triangles);
        v.mesh = mesh;
        v.generation = 0;
    }
    if (shape->generation != v.generation) {
        std::memcpy(v.positions->GetPointer(0), shape->positions.data(), sizeof(float) * 3 * std::size_t(count));
        v.positions->Modified();
        v.cage->Modified();
        v.generation = shape->generation;
    }
}

} // namespace celform::views
