// File > Export… (export_dialog.h).
#include "editor/dialogs/export_dialog.h"

#include "editor/jobs/export_job.h"
#include "editor/main_window.h"
#include "editor/settings/shortcuts.h"

#include "celform/model/document/document.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
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
#include <QPushButton>
#include <QSpinBox>
#include <QStatusBar>

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
    case model::ExportFormat::Usda:
        return ExportDialog::tr("USD (.usda): time-sampled points, normals and camera");
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
    , m_blendShapes(new QCheckBox(tr("&Keys as blend shapes (animated weights)"), this))
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
    // A row whose field is a layout gets a label without a buddy, which shows its '&' as text:
    // the labels name the field their mnemonic focuses.
    auto* framesLabel = new QLabel(tr("F&rames:"), this);
    framesLabel->setObjectName(QStringLiteral("exportFramesLabel"));
    framesLabel->setBuddy(m_first);
    form->addRow(framesLabel, range);
    auto* fileLabel = new QLabel(tr("F&ile:"), this);
    fileLabel->setObjectName(QStringLiteral("exportFileLabel"));
    fileLabel->setBuddy(m_file);
    form->addRow(fileLabel, file);
    m_blendShapes->setObjectName(QStringLiteral("exportBlendShapes"));
    m_blendShapes->setToolTip(tr("USD: the enabled keys as UsdSkel blend shapes whose weights follow the camera "
                                 "path; the points then hold the shape without them"));
    form->addRow(QString(), m_blendShapes);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
    buttons->addButton(tr("&Export"), QDialogButtonBox::AcceptRole)->setObjectName(QStringLiteral("exportButton"));
    form->addRow(buttons);
    connect(buttons, &QDialogButtonBox::accepted, this, &ExportDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(browseButton, &QPushButton::clicked, this, &ExportDialog::browse);
    connect(m_format, &QComboBox::currentIndexChanged, this, &ExportDialog::formatChanged);
    formatChanged();
}

model::ExportJob ExportDialog::job() const
{
    model::ExportJob job;
    job.format = model::ExportFormat(m_format->currentData().toInt());
    job.firstFrame = m_first->value();
    job.lastFrame = m_last->value();
    job.blendShapes = job.format == model::ExportFormat::Usda && m_blendShapes->isChecked();
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
    const auto format = model::ExportFormat(m_format->currentData().toInt());
    m_blendShapes->setEnabled(format == model::ExportFormat::Usda);
    // Keep the file's name, change its suffix.
    const QString wanted = suffixOf(format);
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

void installExportAction(MainWindow* window)
{
    QAction* action = addWindowAction(window, QStringLiteral("actionExport"), MainWindow::tr("E&xport…"),
        QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_E),
        MainWindow::tr("Export the animation seen through the camera path as glTF, a PC2 point cache, OBJ "
                       "files or USD, as celform export does"));
    QObject::connect(action, &QAction::triggered, window, [window] {
        auto* dialog = new ExportDialog(window->document(), window);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        QObject::connect(dialog, &QDialog::accepted, window, [window, dialog] {
            const model::Document* document = window->document();
            const QString source = document->filePath().isEmpty() ? MainWindow::tr("Untitled project")
                                                                  : QFileInfo(document->filePath()).fileName();
            startExport(window, document->data(), source, dialog->job());
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
