// The control cage (issue 25; Maya's Smooth Mesh Preview shows it the same way): the control
// mesh's triangles as a wireframe over the displayed subdivided surface, following the control
// shape (base, key or blend at the playhead). Not pickable: picks go to the surface.
#pragma once

#include "celform/algorithms/tri_mesh.h"

#include <cstdint>
#include <memory>

class vtkRenderer;

namespace celform::views {

class ControlCage {
public:
    explicit ControlCage(vtkRenderer* renderer);
    ~ControlCage();
    ControlCage(const ControlCage&) = delete;
    ControlCage& operator=(const ControlCage&) = delete;

    /// Shows mesh's faces on shape (#V by 3), or hides the cage (null). Cheap when neither the
    /// mesh nor the shape's generation changed; a new shape copies the positions in place.
    void show(const algo::TriMesh* mesh, const algo::Shape* shape);
    [[nodiscard]] bool isShown() const;

private:
    struct Vtk;
    std::unique_ptr<Vtk> m;
};

} // namespace celform::views
