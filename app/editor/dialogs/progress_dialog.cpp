// The editor's progress dialog for long jobs (progress_dialog.h).
#include "editor/dialogs/progress_dialog.h"

#include <QCoreApplication>
#include <QProgressDialog>

namespace celform::app {

QProgressDialog* makeProgressDialog(QWidget* parent, const QString& objectName, const QString& title,
    const QString& label, int maximum, int minimumDurationMs)
{
    auto* progress = new QProgressDialog(parent);
    progress->setObjectName(objectName);
    progress->setWindowTitle(title);
    progress->setLabelText(label);
    progress->setCancelButtonText(QCoreApplication::translate("celform::app::ProgressDialog", "Cancel"));
    progress->setRange(0, maximum);
    progress->setWindowModality(Qt::WindowModal);
    progress->setMinimumDuration(minimumDurationMs);
    progress->setAutoClose(false);
    progress->setAutoReset(false);
    progress->setMinimumWidth(420);
    progress->setValue(0);
    return progress;
}

} // namespace celform::app
