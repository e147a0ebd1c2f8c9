// The surface the viewport displays (issue 25, "A smooth surface, view-dependent"): the displayed
// control shape (DisplayedShape: base, key or blend at the playhead) through the Loop stencil of
// the displayed level (model::subdividedSurface, built once per base model and level), or the
// control shape itself at level 0. Shading, lines and highlights read the displayed surface; the
// brush, patch painting and alignment picking stay on the control mesh, so a pick on the
// displayed surface is carried back to its control face here.
#pragma once

#include "celform/algorithms/brush.h"
#include "celform/algorithms/subdivision.h"
#include "celform/algorithms/tri_mesh.h"
#include "celform/model/data/project_data.h"

#include <Eigen/Core>

#include <cstdint>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace celform::model {
struct SubdividedSurface;
}

namespace celform::views {

class DisplayedShape;

class SubdividedDisplay {
public:
    SubdividedDisplay();
    ~SubdividedDisplay();

    /// The level to display for data's base model (0: the control mesh). Returns true when the
    /// displayed topology changed (the scene needs the new mesh). The surface is looked up again
    /// after invalidate() (a new base model, face sets or base shading offsets).
    bool setLevel(const model::ProjectData& data, int level);
    void invalidate() { m_lookUp = true; }
    [[nodiscard]] int level() const { return m_surface ? m_level : 0; }

    /// Follows control after its refresh; controlBefore is the generation control had before it.
    /// A partial change of the control shape (some rows) recomputes only the stencil rows those
    /// rows reach and the normals around them. Allocates once per level.
    void refresh(const DisplayedShape& control, std::uint64_t controlBefore);

    /// What is on screen: the subdivided stand-in project (its base model, face sets, base offsets;
    /// take the look from the document) or the control one, the shape, its normals and the rows
    /// the last refresh changed (empty after a full one).
    struct View {
        const model::ProjectData* data = nullptr;
        const algo::TriMesh* mesh = nullptr;
        const algo::Shape* shape = nullptr;
        const algo::Positions* normals = nullptr;
        const std::vector<std::uint32_t>* changed = nullptr;
    };
    [[nodiscard]] View view(const model::ProjectData& controlData, const DisplayedShape& control) const;

    /// Per-vertex values of the control mesh (shading offsets, brush weights) on the displayed
    /// vertices, through the same stencil; control itself at level 0.
    [[nodiscard]] const std::vector<float>& perVertex(const std::vector<float>& control, std::vector<float>& out) const;

    /// A point picked on the displayed face `face` at position: its control face and the point
    /// with the same barycentric coordinates on that face of controlShape (faces controlFaces).
    [[nodiscard]] std::pair<std::int64_t, Eigen::Vector3d> toControl(std::int64_t face, const Eigen::Vector3d& position,
        const algo::Faces& controlFaces, const algo::Positions& controlShape) const;

    /// The brush selections (control vertices) as one selection of the displayed vertices, their
    /// weights carried through the stencil; the mirror's weight wins where both select.
    [[nodiscard]] const algo::BrushSelection* selection(
        const algo::BrushSelection* selection, const algo::BrushSelection* mirror, Eigen::Index controlVertices);

private:
    std::shared_ptr<const model::SubdividedSurface> m_surface; ///< null at level 0
    int m_level = 0;
    bool m_lookUp = true;
    std::uint64_t m_source = 0; ///< generation of the control shape m_shape was made from
    algo::Shape m_shape; ///< the subdivided positions
    algo::Positions m_limitNormals; ///< the surface's limit normals, as the CPU renderer shades with them
    algo::SubdivisionScratch m_scratch;
    std::vector<std::uint32_t> m_moved, m_changed;
    std::vector<std::int32_t> m_normalRows;
    std::vector<float> m_controlWeights, m_weights;
    algo::BrushSelection m_selection;
};

} // namespace celform::views
