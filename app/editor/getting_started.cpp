#include "editor/getting_started.h"

#include <QCoreApplication>
#include <QDialog>
#include <QDialogButtonBox>
#include <QTextBrowser>
#include <QVBoxLayout>

namespace celform::app {

namespace {
struct Guide {
    Q_DECLARE_TR_FUNCTIONS(celform::app::GettingStarted)
};
} // namespace

QDialog* showGettingStarted(QWidget* parent)
{
    if (auto* open = parent ? parent->findChild<QDialog*>(QStringLiteral("gettingStarted")) : nullptr) {
        open->raise();
        open->activateWindow();
        return open;
    }
    auto* dialog = new QDialog(parent);
    dialog->setObjectName(QStringLiteral("gettingStarted"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setWindowTitle(Guide::tr("Getting Started"));
    auto* layout = new QVBoxLayout(dialog);
    auto* browser = new QTextBrowser(dialog);
    browser->setOpenExternalLinks(true);
    // The guide and its pictures are resources: relative image paths resolve next to it.
    browser->setSource(QUrl(QStringLiteral("qrc:/celform/docs/getting-started.md")), QTextDocument::MarkdownResource);
    layout->addWidget(browser);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, dialog);
    QObject::connect(buttons, &QDialogButtonBox::rejected, dialog, &QDialog::close);
    layout->addWidget(buttons);
    dialog->resize(820, 760);
    dialog->show();
    return dialog;
}

} // namespace celform::app
