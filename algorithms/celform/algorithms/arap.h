// As-rigid-as-possible surface deformation (Sorkine and Alexa, "As-Rigid-As-Possible Surface
// Modeling", 2007): cotangent-weighted spokes, per-vertex rotations by SVD (local step) and one
// sparse Cholesky solve per iteration (global step). Handles are soft constraints whose stiffness
// may change from call to call: the sparsity pattern, its symbolic analysis and the rest shape's
// weights are computed once, only the numeric factorisation is redone when the handles change.
#pragma once

#include "celform/algorithms/mesh_types.h"
#include "celform/algorithms/progress.h"

#include <Eigen/Core>

#include <cstdint>
#include <memory>
#include <vector>

namespace celform::algo {

/// A target for one vertex: where it should go and how firmly (relative to its spokes' stiffness,
/// so 1 weighs like its neighbours, 100 nearly pins it).
struct ArapHandle {
    std::int32_t vertex = 0;
    Eigen::Vector3d target = Eigen::Vector3d::Zero();
    double stiffness = 100.0;
};

class ArapSolver {
public:
    /// rest: the undeformed shape; free: per vertex, whether it may move (others stay at their
    /// rest position). Vertices without faces stay put.
    ArapSolver(const Positions& rest, const Faces& faces, const std::vector<std::uint8_t>& free);
    ~ArapSolver();
    ArapSolver(const ArapSolver&) = delete;
    ArapSolver& operator=(const ArapSolver&) = delete;

    /// Sets the handles (free vertices only; others are ignored) and refactorises numerically.
    /// False when the factorisation fails.
    bool setHandles(const std::vector<ArapHandle>& handles);
    /// iterations local-global steps from current (#V by 3, updated in place; fixed vertices are
    /// reset to their rest positions). Stops early, returning false, when progress asks to cancel
    /// (checked between iterations; current then holds the last whole iteration).
    bool solve(Eigen::MatrixXd& current, int iterations, const Progress* progress = nullptr);
    /// Free vertex count.
    [[nodiscard]] std::int64_t freeCount() const;

private:
    struct Data;
    std::unique_ptr<Data> m;
};

} // namespace celform::algo
