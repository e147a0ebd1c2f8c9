// A derivative-free search of the light (issue 26, "an objective that cannot make depth worse"):
// compass (pattern) search over the sphere of directions, or over positions for a point light,
// minimising any objective of the light. Celform minimises the depth error of thesis 4.4 with
// it (model::optimiseLight), an objective with no gradient: it counts pixels of a picture.
#pragma once

#include "celform/algorithms/light_optimisation.h"
#include "celform/algorithms/progress.h"

#include <Eigen/Core>

#include <functional>
#include <vector>

namespace celform::algo {

struct LightSearchSettings {
    /// The first step: radians for a direction, model radii (scale) for a position. A quarter
    /// radian (about 14 degrees) is about the turn one gradient iteration makes at its start
    /// (1/8, 5.0.2) times two: the search starts from the gradient's answer and looks around it.
    double initialStep = 0.25;
    double minStep = 0.02; ///< stops when the step is smaller (about 1 degree)
    int maxEvaluations = 32; ///< objective calls, the start's included
    double scale = 1.0; ///< point lights: the length of a step of 1
};

/// One light the search evaluated.
struct LightSearchVisit {
    Eigen::Vector3d light = Eigen::Vector3d::Zero();
    double value = 0.0;
    double step = 0.0;
    bool accepted = false; ///< it became the best so far
};

struct LightSearchResult {
    LightPose best;
    double bestValue = 0.0;
    double startValue = 0.0;
    std::vector<LightSearchVisit> visits; ///< in order, the start first
    bool cancelled = false;
};

/// Compass search from start: polls the four turns (±step about two axes perpendicular to the
/// light) of a direction, or the six moves (±step·scale along x, y and z) of a position, moves to
/// the first that lowers the objective, and halves the step when none does, until the step is
/// below minStep or maxEvaluations are spent. The best value never rises; a direction stays a
/// unit vector. Deterministic. progress counts evaluations (total maxEvaluations) and may stop it.
LightSearchResult searchLight(const LightPose& start, const std::function<double(const LightPose&)>& objective,
    const LightSearchSettings& settings, Progress* progress = nullptr);

} // namespace celform::algo
