// File > Export… and the export behind a progress dialog (export_dialog.h).
#include "export_dialog.h"

#include "main_window.h"
#include "shortcuts.h"

#include "celform/model/document.h"
#include "celform/model/io_error.h"

#include <QAction>
#include <QComboBox>
#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMessageBox>
#include <QProgressDialog>
#include <QPushButton>
#include <QSpinBox>
#include <QStatusBar>
#include <QThread>
#include <QtConcurrent/QtConcurrentRun>

namespace celform::app {
namespace {

/// The file suffix of a format (an OBJ sequence's files end in .obj).
QString suffixOf(model::ExportFormat format)
{
    return format == model::ExportFormat::ObjSequence ? QStringLiteral("obj") : model::exportFormatName(format);
}

QString formatLabel(model::ExportFormat format)
{
    switch (format) {
    case model::ExportFormat::Gltf:
        return ExportDialog::tr("glTF 2.0 (.gltf): keys as morph targets, weights and camera animated");
    case model::ExportFormat::Glb:
        return ExportDialog::tr("glTF 2.0 binary (.glb)");
    case model::ExportFormat::Pc2:
        return ExportDialog::tr("PC2 point cache (.pc2): the shape at every frame");
    case model::ExportFormat::ObjSequence:
        return ExportDialog::tr("OBJ sequence: one .obj per frame");
    }
    return {};
}

} // namespace

ExportDialog::ExportDialog(const model::Document* document, QWidget* parent)
    : QDialog(parent)
    , m_format(new QComboBox(this))
    , m_first(new QSpinBox(this))
    , m_last(new QSpinBox(this))
    , m_file(new QLineEdit(this))
{
    setObjectName(QStringLiteral("exportDialog"));
    setWindowTitle(tr("Export"));
    m_format->setObjectName(QStringLiteral("exportFormat"));
    for (model::ExportFormat f : model::exportFormats())
        m_format->addItem(formatLabel(f), int(f));
    const model::SceneTime& time = document->data().time;
    for (QSpinBox* box : {m_first, m_last})
        box->setRange(-model::kMaxFrame, model::kMaxFrame);
    m_first->setObjectName(QStringLiteral("exportFirstFrame"));
    m_last->setObjectName(QStringLiteral("exportLastFrame"));
    m_first->setValue(time.firstFrame);
    m_last->setValue(time.lastFrame);
    m_file->setObjectName(QStringLiteral("exportFile"));
    const QString project = document->filePath();
    const QFileInfo info(project.isEmpty() ? QDir::home().filePath(QStringLiteral("untitled")) : project);
    m_file->setText(QDir::toNativeSeparators(info.dir().filePath(info.completeBaseName() + QStringLiteral(".gltf"))));

    auto* range = new QHBoxLayout;
    range->addWidget(m_first);
    range->addWidget(new QLabel(tr("to"), this));
    range->addWidget(m_last);
    auto* file = new QHBoxLayout;
    file->addWidget(m_file, 1);
    auto* browseButton = new QPushButton(tr("Browse…"), this);
    file->addWidget(browseButton);
    auto* form = new QFormLayout(this);
    form->addRow(tr("&Format:"), m_format);
    form->addRow(tr("F&rames:"), range);
    form->addRow(tr("F&ile:"), file);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
    buttons->addButton(tr("&Export"), QDialogButtonBox::AcceptRole)->setObjectName(QStringLiteral("exportButton"));
    form->addRow(buttons);
    connect(buttons, &QDialogButtonBox::accepted, this, &ExportDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(browseButton, &QPushButton::clicked, this, &ExportDialog::browse);
    connect(m_format, &QComboBox::currentIndexChanged, this, &ExportDialog::formatChanged);
}

model::ExportJob ExportDialog::job() const
{
    model::ExportJob job;
    job.format = model::ExportFormat(m_format->currentData().toInt());
    job.firstFrame = m_first->value();
    job.lastFrame = m_last->value();
    job.output = QDir::fromNativeSeparators(m_file->text().trimmed());
    if (!job.output.isEmpty())
        job.output = QFileInfo(job.output).absoluteFilePath();
    return job;
}

void ExportDialog::accept()
{
    const model::ExportJob j = job();
    QString problem = model::exportJobProblem(j);
    if (problem.isEmpty() && QFileInfo(j.output).suffix().toLower() != suffixOf(j.format))
        problem = tr("The file must end in .%1 for this format.").arg(suffixOf(j.format));
    if (!problem.isEmpty()) {
        QMessageBox::warning(this, windowTitle(), problem);
        return;
    }
    QDialog::accept();
}

void ExportDialog::formatChanged()
{
    // Keep the file's name, change its suffix.
    const QString wanted = suffixOf(model::ExportFormat(m_format->currentData().toInt()));
    const QFileInfo info(QDir::fromNativeSeparators(m_file->text().trimmed()));
    if (info.fileName().isEmpty() || info.suffix().toLower() == wanted)
        return;
    m_file->setText(QDir::toNativeSeparators(info.dir().filePath(info.completeBaseName() + '.' + wanted)));
}

void ExportDialog::browse()
{
    const model::ExportFormat format = model::ExportFormat(m_format->currentData().toInt());
    const QString suffix = suffixOf(format);
    QString path = QFileDialog::getSaveFileName(this, windowTitle(), m_file->text(),
        formatLabel(format) + QStringLiteral(" (*.") + suffix + QLatin1Char(')'), nullptr,
        format == model::ExportFormat::ObjSequence ? QFileDialog::DontConfirmOverwrite : QFileDialog::Options());
    if (path.isEmpty())
        return;
    if (QFileInfo(path).suffix().toLower() != suffix)
        path += QLatin1Char('.') + suffix;
    m_file->setText(QDir::toNativeSeparators(path));
}

ExportRunner::ExportRunner(model::ProjectData data, QString source, model::ExportJob job, QWidget* parent)
    : QObject(parent)
    , m_data(std::move(data))
    , m_source(std::move(source))
    , m_job(std::move(job))
    , m_parent(parent)
{ }

ExportRunner::~ExportRunner()
{
    if (!m_running)
        return;
    m_cancel = true;
    m_future.waitForFinished();
    delete m_progress;
}

void ExportRunner::start()
{
    if (m_running)
        return;
    m_running = true;
    m_cancel = false;
    m_error.clear();
    m_progress = new QProgressDialog(m_parent);
    m_progress->setObjectName(QStringLiteral("exportProgress"));
    m_progress->setWindowTitle(tr("Export"));
    m_progress->setLabelText(tr("Exporting %1…").arg(QFileInfo(m_job.output).fileName()));
    m_progress->setCancelButtonText(tr("Cancel"));
    m_progress->setRange(0, m_job.frameCount());
    m_progress->setWindowModality(Qt::WindowModal);
    m_progress->setMinimumDuration(0);
    m_progress->setAutoClose(false);
    m_progress->setAutoReset(false);
    m_progress->setMinimumWidth(420);
    connect(m_progress, &QProgressDialog::canceled, this, &ExportRunner::cancel);
    m_progress->setValue(0);
    m_progress->show();

    m_future = QtConcurrent::run([this] {
        model::ExportCallbacks callbacks;
        // At most one update per percent: a long range must not flood the GUI thread's queue.
        callbacks.progress = [this, shown = -1](int done, int total) mutable {
            const int percent = int(qint64(done) * 100 / std::max(1, total));
            if (percent == shown && done != total)
                return;
            shown = percent;
            QMetaObject::invokeMethod(
                this,
                [this, done] {
                    if (m_progress)
                        m_progress->setValue(done);
                },
                Qt::QueuedConnection);
        };
        callbacks.cancelled = [this] { return m_cancel.load(); };
        model::ExportResult result;
        QString error;
        try {
            result = model::exportProject(m_data, m_source, m_job, callbacks);
        } catch (const model::IoError& e) {
            error = e.message();
        } catch (const std::bad_alloc&) {
            error = tr("%1: not enough memory to export").arg(m_job.output);
        }
        QMetaObject::invokeMethod(
            this, [this, result, error] { workerFinished(result, error); }, Qt::QueuedConnection);
    });
}

void ExportRunner::cancel()
{
    if (m_running)
        m_cancel = true;
}

void ExportRunner::workerFinished(const model::ExportResult& result, const QString& error)
{
    m_running = false;
    if (m_progress) {
        m_progress->hide();
        m_progress->deleteLater();
    }
    if (!error.isEmpty()) {
        m_error = error;
        auto* box = new QMessageBox(QMessageBox::Warning, tr("Export Failed"), tr("The export could not be finished."),
            QMessageBox::Ok, m_parent);
        box->setObjectName(QStringLiteral("exportErrorBox"));
        box->setInformativeText(error);
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->open();
        emit message(tr("Export failed: %1").arg(error));
        emit finished(false);
        return;
    }
    if (result.cancelled) {
        emit message(tr("Export cancelled."));
        emit finished(false);
        return;
    }
    QString text = tr("Exported %L1 frames to %2").arg(result.frames).arg(QDir::toNativeSeparators(m_job.output));
    for (const QString& w : result.warnings)
        text += QStringLiteral(" — ") + w;
    emit message(text);
    emit finished(true);
}

void installExportAction(MainWindow* window)
{
    auto* action = new QAction(MainWindow::tr("E&xport…"), window);
    action->setObjectName(QStringLiteral("actionExport"));
    const QString tip = MainWindow::tr(
        "Export the animation seen through the camera path as glTF, a PC2 point cache or OBJ files, as celform "
        "export does");
    action->setToolTip(tip);
    action->setStatusTip(tip);
    action->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_E));
    window->addAction(action);
    QObject::connect(action, &QAction::triggered, window, [window] {
        auto* dialog = new ExportDialog(window->document(), window);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        QObject::connect(dialog, &QDialog::accepted, window, [window, dialog] {
            const model::Document* document = window->document();
            const QString source = document->filePath().isEmpty() ? MainWindow::tr("Untitled project")
                                                                  : QFileInfo(document->filePath()).fileName();
            auto* runner = new ExportRunner(document->data(), source, dialog->job(), window);
            runner->setObjectName(QStringLiteral("exportRunner"));
            QObject::connect(runner, &ExportRunner::message, window,
                [window](const QString& text) { window->statusBar()->showMessage(text, 10000); });
            QObject::connect(runner, &ExportRunner::finished, runner, &QObject::deleteLater);
            runner->start();
        });
        dialog->open();
    });
    const auto update = [window, action] { action->setEnabled(window->document()->hasMesh()); };
    QObject::connect(window->document(), &model::Document::changed, window, update);
    update();
    // Beside the render actions: before the separator above Quit.
    if (QAction* quit = window->action(QStringLiteral("actionQuit")))
        if (QMenu* file = menuOf(quit)) {
            const QList<QAction*> items = file->actions();
            const qsizetype at = items.indexOf(quit);
            QAction* before = at > 0 && items[at - 1]->isSeparator() ? items[at - 1] : quit;
            file->insertAction(before, action);
        }
}

} // namespace celform::app
