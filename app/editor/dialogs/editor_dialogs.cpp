// The actions of the editor's dialogs (editor_dialogs.h).
#include "editor/dialogs/editor_dialogs.h"

#include "editor/dialogs/export_dialog.h"
#include "editor/main_window.h"
#include "editor/settings/preferences.h"
#include "editor/dialogs/preferences_dialog.h"
#include "editor/dialogs/render_dialog.h"
#include "editor/jobs/render_job.h"
#include "editor/settings/shortcuts.h"
#include "editor/dialogs/shortcuts_dialog.h"

#include "celform/model/document/document.h"

#include <QAction>
#include <QFileInfo>
#include <QMenu>
#include <QStatusBar>

namespace celform::app {
namespace {

/// The menu holding an action of the window.
QMenu* menuHolding(MainWindow* window, const char* actionName)
{
    const QAction* action = window->action(QString::fromLatin1(actionName));
    return action ? menuOf(action) : nullptr;
}

QAction* makeAction(MainWindow* window, const QString& name, const QString& text, const QString& tip)
{
    return addWindowAction(window, name, text, {}, tip);
}

/// Shows the render dialog; on Render, renders the document as it is now behind a progress dialog.
void renderFromDialog(MainWindow* window, RenderDialog::Kind kind)
{
    auto* dialog = new RenderDialog(kind, window->document(), window->viewport(), window);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    QObject::connect(dialog, &QDialog::accepted, window, [window, dialog] {
        const model::Document* document = window->document();
        const QString source = document->filePath().isEmpty() ? MainWindow::tr("Untitled project")
                                                              : QFileInfo(document->filePath()).fileName();
        startRender(window, document->data(), source, dialog->job(), dialog->openWhenDone());
    });
    dialog->open();
}

} // namespace

void installEditorDialogs(MainWindow* window)
{
    QAction* renderImage = makeAction(window, QStringLiteral("actionRenderImage"), MainWindow::tr("&Render Image…"),
        MainWindow::tr("Render the current frame to an image file, as celform render does"));
    renderImage->setShortcut(QKeySequence(Qt::Key_F12));
    QObject::connect(
        renderImage, &QAction::triggered, window, [window] { renderFromDialog(window, RenderDialog::Kind::Image); });
    QAction* renderSequence = makeAction(window, QStringLiteral("actionRenderSequence"),
        MainWindow::tr("Render Se&quence…"), MainWindow::tr("Render a range of frames to numbered image files"));
    renderSequence->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_F12));
    QObject::connect(renderSequence, &QAction::triggered, window,
        [window] { renderFromDialog(window, RenderDialog::Kind::Sequence); });
    // Nothing to render without a base model.
    const auto updateRender = [window, renderImage, renderSequence] {
        renderImage->setEnabled(window->document()->hasMesh());
        renderSequence->setEnabled(window->document()->hasMesh());
    };
    QObject::connect(window->document(), &model::Document::changed, window, updateRender);
    updateRender();
    if (QMenu* file = menuHolding(window, "actionQuit")) {
        QAction* quit = window->action(QStringLiteral("actionQuit"));
        file->insertAction(quit, renderImage);
        file->insertAction(quit, renderSequence);
        file->insertSeparator(quit);
    }
    installExportAction(window); // File > Export… (export_dialog.h)

    QAction* shortcuts = makeAction(window, QStringLiteral("actionKeyboardShortcuts"),
        MainWindow::tr("&Keyboard Shortcuts"), MainWindow::tr("Every keyboard shortcut of the editor, searchable"));
    shortcuts->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Slash));
    QObject::connect(shortcuts, &QAction::triggered, window, [window] {
        auto* dialog = window->findChild<ShortcutsDialog*>();
        if (!dialog) {
            dialog = new ShortcutsDialog(window, window);
            dialog->setAttribute(Qt::WA_DeleteOnClose);
        } else {
            dialog->refresh();
        }
        dialog->show();
        dialog->raise();
        dialog->activateWindow();
    });
    if (QMenu* help = menuHolding(window, "actionNavigationHelp")) {
        const QList<QAction*> items = help->actions();
        const int at = int(items.indexOf(window->action(QStringLiteral("actionNavigationHelp"))));
        help->insertAction(items.value(at + 1), shortcuts);
    }

    QAction* preferences = makeAction(window, QStringLiteral("actionPreferences"), MainWindow::tr("&Preferences…"),
        MainWindow::tr("Navigation, autosave, undo steps, language, new projects' look and keyboard shortcuts"));
    preferences->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Comma));
    preferences->setMenuRole(QAction::PreferencesRole);
    if (QMenu* edit = menuHolding(window, "actionUndo")) {
        edit->addSeparator();
        edit->addAction(preferences);
    }
    // Undo and Redo change their text with the history: the shortcut lists use a fixed name.
    for (const auto& [name, text] :
        {std::pair{"actionUndo", MainWindow::tr("Undo")}, {"actionRedo", MainWindow::tr("Redo")}})
        if (QAction* action = window->action(QString::fromLatin1(name)))
            action->setProperty("shortcutName", text);

    // Last, so that every action's default keys are noted before the user's are applied.
    auto* applier = new PreferencesApplier(window);
    QObject::connect(preferences, &QAction::triggered, window, [window, applier] {
        auto* dialog = window->findChild<PreferencesDialog*>();
        if (!dialog) {
            dialog = new PreferencesDialog(applier, window, window);
            dialog->setAttribute(Qt::WA_DeleteOnClose);
        }
        dialog->open();
        dialog->raise();
    });
}

} // namespace celform::app
