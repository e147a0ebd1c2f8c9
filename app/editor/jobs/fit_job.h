// Fit to Drawing as jobs of the JobRunner (model/analysis/drawing_fit.h): Fit Camera to Drawing
// and Fit Shape to Drawing solve on a worker thread with a copy of the project, behind a progress
// dialog with Cancel; the caller applies the result through the Document on the GUI thread (one
// undo step each). A fit that fails (a drawing without a usable outline, a model out of view)
// throws its sentence as the job's error and changes nothing; a cancelled one changes nothing.
#pragma once

#include "celform/model/analysis/drawing_fit.h"

#include <functional>

class QWidget;

namespace celform::app {

class JobRunner;

/// Starts Fit Camera to Drawing for drawingId (and the key linked to it, keyId, or 0) behind a
/// progress dialog on parent. apply gets a fit that succeeded, on the GUI thread; showError the
/// sentence of one that failed. The runner deletes itself when finished.
JobRunner* startFitCamera(model::ProjectData data, model::ObjectId drawingId, model::ObjectId keyId, QWidget* parent,
    std::function<void(const model::CameraFit&)> apply, std::function<void(const QString&)> showError);

/// Starts Fit Shape to Drawing for keyId against drawingId (0: its first linked drawing), as
/// startFitCamera.
JobRunner* startFitShape(model::ProjectData data, model::ObjectId keyId, model::ObjectId drawingId,
    const model::ShapeFitRequest& request, QWidget* parent, std::function<void(const model::ShapeFit&)> apply,
    std::function<void(const QString&)> showError);

} // namespace celform::app
