// Automatic Shading Offsets (paper 3, section 4.3) as a job of the JobRunner: model::solveAutoOffsets
// on a worker thread with a copy of the project, behind a progress dialog with Cancel (a step
// per analysis); the caller stores the values with the Document on the GUI thread (one undo step).
#pragma once

#include "celform/model/analysis/auto_offsets.h"

#include <functional>

class QWidget;

namespace celform::app {

class JobRunner;

/// Starts the solve behind a progress dialog on parent; apply gets a completed result on the
/// GUI thread (a cancelled one changes nothing). A refusal is shown in a message box. The runner
/// deletes itself when finished.
JobRunner* startAutoOffsets(model::ProjectData data, const model::AutoOffsetsRequest& request, QWidget* parent,
    std::function<void(const model::AutoOffsetsResult&)> apply);

} // namespace celform::app
