// Optimise Light for Stereo in the editor (paper 3, 4.1) as a job of the JobRunner:
// model::optimiseLight on a worker thread with a copy of what it reads, behind a progress dialog
// with Cancel (a step per iteration). The finished report is handed back on the GUI thread; the
// caller stores it with the Document (one undo step). Cancel leaves the document as it was.
#pragma once

#include "celform/model/analysis/light_optimisation.h"

#include <QString>

#include <functional>
#include <memory>

class QWidget;

namespace celform::app {

class JobRunner;

/// Everything a run reads, copied from the document and the viewport when it starts.
struct LightOptimisationJob {
    model::ProjectData data; ///< the mesh (shared), face sets and look
    algo::Positions shape; ///< the shape on screen
    std::vector<float> offsets; ///< the shading offsets in effect for it (Viewport::displayedShadingOffsets)
    std::uint64_t generation = 0;
    int frame = 0;
    model::Camera camera;
    int width = 0;
    int height = 0;
    model::LightOptimisationRequest request;
};

/// What the editor says of a finished run: the improvement of what the optimiser lowers, the
/// segments inside the window, the depth error; and a warning (empty when none) when fewer segments
/// are inside the window than before or the depth error rose.
struct LightOptimisationSummary {
    QString text;
    QString warning;
};
LightOptimisationSummary summariseLightOptimisation(const model::LightOptimisationReport& report);

using LightOptimisationApply = std::function<void(const std::shared_ptr<const model::LightOptimisationReport>&)>;

/// Starts the run behind a progress dialog on parent; apply gets the report (completed or
/// cancelled) on the GUI thread, showError a failure. The runner deletes itself when finished.
JobRunner* startLightOptimisation(LightOptimisationJob job, QWidget* parent, LightOptimisationApply apply,
    std::function<void(const QString&)> showError);

} // namespace celform::app
