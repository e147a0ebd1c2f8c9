// Optimise Light Along Shot in the editor (issue 26) as a job of the JobRunner:
// model::optimiseLightTrack over the scene's frames on a worker thread with a copy of the project,
// behind a progress dialog with Cancel (a step per frame). The finished report is handed back on
// the GUI thread; the caller stores the track with the Document (one undo step). Cancel leaves the
// document as it was.
#pragma once

#include "celform/model/analysis/light_track_optimisation.h"

#include <QString>

#include <functional>
#include <memory>

class QWidget;

namespace celform::app {

class JobRunner;

/// Everything a run reads, copied from the document when it starts.
struct LightTrackJob {
    model::ProjectData data;
    model::RenderJob frames; ///< the frames (first, last, step), the size, no camera: the shot camera
    model::LightTrackRequest request;
};

/// The status bar's words for a finished run.
QString summariseLightTrack(const model::LightTrackReport& report);

using LightTrackApply = std::function<void(const std::shared_ptr<const model::LightTrackReport>&)>;

/// Starts the run behind a progress dialog on parent; apply gets the report (completed or
/// cancelled) on the GUI thread, showError a failure. The runner deletes itself when finished.
JobRunner* startLightTrackOptimisation(
    LightTrackJob job, QWidget* parent, LightTrackApply apply, std::function<void(const QString&)> showError);

} // namespace celform::app
