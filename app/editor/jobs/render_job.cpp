// A render as a job of the JobRunner (render_job.h).
#include "editor/jobs/render_job.h"

#include "editor/jobs/job_runner.h"

#include <QCoreApplication>
#include <QDesktopServices>
#include <QDir>
#include <QFileInfo>
#include <QMainWindow>
#include <QMessageBox>
#include <QStatusBar>
#include <QStringList>
#include <QUrl>

#include <memory>

namespace celform::app {
namespace {

/// The context its strings were translated in (translations/celform_ja.ts) before the JobRunner.
struct RenderText {
    Q_DECLARE_TR_FUNCTIONS(celform::app::RenderRunner)
};

/// Keeps the files written, for the message at the end and the error's count of frames kept.
class WrittenFiles : public model::RenderFrameListener {
public:
    explicit WrittenFiles(QStringList& files)
        : m_files(files)
    { }
    void frameDone(int, const QString& file, bool skipped) override
    {
        if (!skipped)
            m_files << file;
    }

private:
    QStringList& m_files;
};

/// "Open when done" found no program to open the result (no file manager or image viewer): says
/// where it is, in a box that does not wait.
void tellNotOpened(QMainWindow* window, bool sequence, const QString& path)
{
    auto* box = new QMessageBox(QMessageBox::Information, RenderText::tr("Render Finished"),
        sequence ? RenderText::tr("No file manager could be opened. The frames are in:")
                 : RenderText::tr("No image viewer could be opened. The image is:"),
        QMessageBox::Ok, window);
    box->setObjectName(QStringLiteral("renderNotOpenedBox"));
    box->setInformativeText(QDir::toNativeSeparators(path));
    box->setTextInteractionFlags(Qt::TextSelectableByMouse);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

} // namespace

JobRunner* startRender(
    QMainWindow* window, model::ProjectData data, const QString& source, const model::RenderJob& job, bool openWhenDone)
{
    const bool sequence = job.isSequence();
    // Written by the worker, read on the GUI thread once it has finished.
    auto written = std::make_shared<QStringList>();
    const auto status = [window](const QString& text) { window->statusBar()->showMessage(text, 10000); };

    JobSpec spec;
    spec.progressName = QStringLiteral("renderProgress");
    spec.title = sequence ? RenderText::tr("Render Sequence") : RenderText::tr("Render Image");
    spec.label = sequence ? RenderText::tr("Rendering frame %1 (1 of %2)…").arg(job.firstFrame).arg(job.frameCount())
                          : RenderText::tr("Rendering %1 (%2 × %3)…")
                                .arg(QFileInfo(job.framePath(job.firstFrame)).fileName())
                                .arg(job.size.width())
                                .arg(job.size.height());
    spec.steps = job.frameCount();
    spec.delayMs = 0;
    // A Cancel pressed when a frame is written stops the render before the next one.
    spec.waitForEachStep = true;
    spec.describe = [job](std::int64_t done, std::int64_t total, const QString&) {
        if (done >= total)
            return QString();
        return RenderText::tr("Rendering frame %1 (%2 of %3)…").arg(job.frameAt(int(done))).arg(done + 1).arg(total);
    };
    spec.outOfMemory = RenderText::tr("%1: not enough memory to render %2 × %3 pixels")
                           .arg(source)
                           .arg(job.size.width())
                           .arg(job.size.height());
    spec.errorBoxName = QStringLiteral("renderErrorBox");
    spec.errorTitle = RenderText::tr("Render Failed");
    spec.errorText = RenderText::tr("The render could not be finished.");
    spec.errorDetails = [written, sequence](const QString& error) {
        QString details = error;
        if (sequence && !written->isEmpty())
            details += QStringLiteral("\n\n")
                + RenderText::tr("The frames written before the error are kept (%L1).").arg(written->size());
        return details;
    };

    auto work = [data = std::move(data), source, job, written, sequence, openWhenDone, status, window](
                    algo::Progress& progress) -> JobRunner::Finish {
        WrittenFiles files(*written);
        const int count = model::renderFrames(data, source, job, &progress, &files);
        return [count, job, written, sequence, openWhenDone, status, window] {
            if (count != job.frameCount()) {
                status(RenderText::tr("Render cancelled; the files written are kept (%L1).").arg(written->size()));
                return false;
            }
            const QString first = written->value(0);
            status(sequence
                    ? RenderText::tr("Rendered %L1 frames to %2")
                          .arg(written->size())
                          .arg(QDir::toNativeSeparators(QFileInfo(first).absolutePath()))
                    : RenderText::tr("Rendered %1").arg(QDir::toNativeSeparators(QFileInfo(first).absoluteFilePath())));
            if (openWhenDone) {
                const QString shown = sequence ? QFileInfo(first).absolutePath() : QFileInfo(first).absoluteFilePath();
                if (!QDesktopServices::openUrl(QUrl::fromLocalFile(shown)))
                    tellNotOpened(window, sequence, shown);
            }
            return true;
        };
    };
    auto* runner = new JobRunner(std::move(spec), std::move(work), window);
    runner->setObjectName(QStringLiteral("renderRunner"));
    QObject::connect(runner, &JobRunner::cancelling, window,
        [status] { status(RenderText::tr("Stopping the render after the frame being drawn…")); });
    QObject::connect(runner, &JobRunner::failed, window,
        [status](const QString& error) { status(RenderText::tr("Render failed: %1").arg(error)); });
    QObject::connect(runner, &JobRunner::finished, runner, &QObject::deleteLater);
    runner->start();
    return runner;
}

} // namespace celform::app
