#include "editor/getting_started.h"

#include <QCoreApplication>
#include <QDialog>
#include <QDialogButtonBox>
#include <QImage>
#include <QResizeEvent>
#include <QScrollBar>
#include <QTextBrowser>
#include <QVBoxLayout>

#include <algorithm>

namespace celform::app {

namespace {
struct Guide {
    Q_DECLARE_TR_FUNCTIONS(celform::app::GettingStarted)
};

/// The guide's browser: its pictures (full-size screenshots of the editor) are scaled down to the
/// width of the text, so that the guide reads in a dock-sized window without scrolling sideways,
/// and again when the window is resized.
class GuideBrowser : public QTextBrowser {
public:
    using QTextBrowser::QTextBrowser;

    QVariant loadResource(int type, const QUrl& name) override
    {
        QVariant resource = QTextBrowser::loadResource(type, name);
        if (type != QTextDocument::ImageResource)
            return resource;
        QImage image = resource.value<QImage>();
        if (image.isNull())
            image.loadFromData(resource.toByteArray());
        const int width = pictureWidth();
        if (!image.isNull() && image.width() > width)
            image = image.scaledToWidth(width, Qt::SmoothTransformation);
        return image.isNull() ? resource : QVariant(image);
    }

protected:
    void resizeEvent(QResizeEvent* event) override
    {
        QTextBrowser::resizeEvent(event);
        if (event->oldSize().width() == event->size().width() || source().isEmpty())
            return;
        // Reload: the document caches its images at the old width.
        const int position = verticalScrollBar()->value();
        const QUrl page = source();
        setSource(QUrl());
        setSource(page, QTextDocument::MarkdownResource);
        verticalScrollBar()->setValue(position);
    }

private:
    [[nodiscard]] int pictureWidth() const
    {
        // The frame and paragraph margins around a picture take a little more than the document margin.
        return std::max(120, viewport()->width() - 2 * int(document()->documentMargin()) - 24);
    }
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
    auto* browser = new GuideBrowser(dialog);
    browser->setOpenExternalLinks(true);
    // The guide and its pictures are resources: relative image paths resolve next to it.
    browser->setSource(QUrl(QStringLiteral("qrc:/celform/docs/getting-started.md")), QTextDocument::MarkdownResource);
    layout->addWidget(browser);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, dialog);
    QObject::connect(buttons, &QDialogButtonBox::rejected, dialog, &QDialog::close);
    layout->addWidget(buttons);
    // About a dock's width beside the editor; the pictures follow the width.
    dialog->resize(640, 760);
    dialog->show();
    return dialog;
}

} // namespace celform::app
