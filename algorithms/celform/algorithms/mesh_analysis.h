// Checks run on every imported mesh: hard errors that make a mesh unusable (NaN coordinates,
// indices out of range) and topology findings that load with a warning (holes, components,
// non-manifold edges).
#pragma once

#include "celform/algorithms/tri_mesh.h"

#include <optional>
#include <string>

namespace celform::algo {

/// Finds the first defect that makes the mesh unusable: no vertices or faces, a non-finite
/// coordinate, a face index out of [0, #V). Returns a short English description, or nothing.
std::optional<std::string> findFatalDefect(const TriMesh& mesh);

struct TopologyReport {
    std::int64_t components = 0; ///< face-connected pieces (through shared vertices)
    std::int64_t boundaryEdges = 0; ///< edges with exactly one face
    std::int64_t boundaryLoops = 0; ///< connected runs of boundary edges (holes)
    std::int64_t nonManifoldEdges = 0; ///< edges with more than two faces
    std::int64_t inconsistentEdges = 0; ///< two-face edges whose faces disagree on orientation
    std::int64_t degenerateFaces = 0; ///< repeated index or zero area
    std::int64_t unreferencedVertices = 0;

    [[nodiscard]] bool isClean() const
    {
        return components <= 1 && boundaryEdges == 0 && nonManifoldEdges == 0 && inconsistentEdges == 0
            && degenerateFaces == 0;
    }
    /// One-line English summary of what is not clean, e.g. "106 holes, 2 components".
    [[nodiscard]] std::string summary() const;
};

/// Edge adjacency by bucketing half-edges per lower vertex: O(E), no quadratic edge list.
/// Expects a mesh that passed findFatalDefect().
TopologyReport analyseTopology(const TriMesh& mesh);

} // namespace celform::algo
