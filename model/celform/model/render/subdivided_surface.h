// The smooth surface a frame is rendered on (issue 25, "A smooth surface, view-dependent"): the
// Loop subdivision stencil of the base model's topology at a level (algo/subdivision.h), applied to
// the frame's blended, animated, deformed control shape after everything else, and a stand-in
// project whose base model is the subdivided mesh: children keep their control face's material,
// face sets (highlight patches) and UVs, the base layer of shading offsets goes through the same
// stencil. The renderer, the lines, the highlights, the depth analysis and the stereo pair take
// that project and the subdivided shape as they would take the control ones.
#pragma once

#include "celform/algorithms/subdivision.h"
#include "celform/model/data/project_data.h"

#include <QString>

#include <memory>
#include <vector>

namespace celform::model {

struct SubdividedSurface {
    int level = 0;
    /// Per topology and level: shared by the surfaces of one base model whose face sets differ.
    std::shared_ptr<const algo::SubdivisionStencil> stencil;
    /// The base model at the level (positions: its rest pose subdivided), its face sets and base
    /// shading offsets; keys, drawings and the animation are left out.
    ProjectData display;

    /// shape (the control mesh's, #V by 3) through the stencil into out (sized once).
    void apply(const algo::Positions& shape, algo::Positions& out) const;
    /// Per-vertex shading offsets through the stencil; empty stays empty.
    void apply(const std::vector<float>& offsets, std::vector<float>& out) const;
};

/// About how many bytes rendering the base model at a level needs beyond the control mesh (the
/// stencil, the subdivided mesh, its edges and the renderer's per-vertex and per-face data).
qint64 subdivisionBytesNeeded(const algo::TriMesh& mesh, int level);

/// The empty string when the level fits in the memory at hand (availableRenderMemory, less what
/// the render itself needs, extraBytes), else why not, naming the sizes.
QString subdivisionMemoryProblem(const algo::TriMesh& mesh, int level, qint64 extraBytes = 0);

/// The surface of the project's base model at level (1-3), shared (several threads may ask at
/// once): the stencil is built once per base model and level, the stand-in project again when the
/// face sets or base shading offsets change. Null at level 0 or without a base model.
std::shared_ptr<const SubdividedSurface> subdividedSurface(const ProjectData& data, int level);

} // namespace celform::model
