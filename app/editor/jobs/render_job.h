// File > Render Image and Render Sequence as a job of the JobRunner: model::renderFrames (the
// code path of `celform render`) on a copy of the document, a step per frame, Cancel between
// frames keeping the files already written, errors in a message box naming the file, and the
// output opened when done.
#pragma once

#include "celform/model/data/project_data.h"
#include "celform/model/render/render_job.h"

class QMainWindow;

namespace celform::app {

class JobRunner;

/// Starts rendering data (a copy of the document as it is now; source names it in errors) as
/// job describes, with its messages in window's status bar. openWhenDone: the image, or a
/// sequence's folder, opens in the desktop's viewer when the render completes. The runner
/// (object name "renderRunner") deletes itself when finished.
JobRunner* startRender(QMainWindow* window, model::ProjectData data, const QString& source, const model::RenderJob& job,
    bool openWhenDone);

} // namespace celform::app
