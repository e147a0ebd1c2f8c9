// File > Export as a job of the JobRunner: model::exportProject (the code path of `celform
// export`) on a copy of the document, a step per frame, Cancel leaving no file of a one-file
// format, errors in a message box naming the file.
#pragma once

#include "celform/model/data/project_data.h"
#include "celform/model/export/export.h"

class QMainWindow;

namespace celform::app {

class JobRunner;

/// Starts exporting data (a copy of the document as it is now; source names it in errors) as job
/// describes, with its messages in window's status bar. The runner (object name "exportRunner")
/// deletes itself when finished.
JobRunner* startExport(
    QMainWindow* window, model::ProjectData data, const QString& source, const model::ExportJob& job);

} // namespace celform::app
