// The editor as a module: `celform` loads it (app/launcher/launch.cpp) when a window is wanted, so that
// VTK, OpenGL and Qt Widgets are mapped only then. Its one entry creates the QApplication and runs
// the main window; the launcher has already checked the arguments and that a display exists.
#include "cli/command_line.h"
#include "launcher/launch.h"
#include "editor/main_window.h"
#include "editor/settings/preferences.h"

#include "celform/views/viewport/viewport.h"

#include <QApplication>
#include <QSurfaceFormat>
#include <QTimer>

#include <cstdio>

extern "C" Q_DECL_EXPORT int celform_editor_main(int argc, char** argv)
{
    using celform::app::MainWindow;
    // The viewport's GL format must be the default before QApplication exists (docs/pitfalls.md,
    // "VTK in a Qt 6 widget").
    QSurfaceFormat::setDefaultFormat(celform::views::Viewport::defaultFormat());
    QApplication app(argc, argv);
    // The language of Edit > Preferences (the system's unless chosen there), read at start only.
    celform::app::installTranslations(app, celform::app::Preferences::load().locale());

    celform::app::EditorArguments parsed;
    QString message;
    // The QApplication has its display (QApplication took out -platform and the like).
    if (const int code
        = celform::app::parseEditorArguments(QCoreApplication::arguments(), parsed, &message, /*checkDisplay=*/false)) {
        fprintf(stderr, "%s\n", qPrintable(message));
        return code;
    }
    const bool screenshotMode = !parsed.screenshot.isEmpty();
    MainWindow window(screenshotMode ? MainWindow::Mode::Batch : MainWindow::Mode::Interactive);
    if (!parsed.project.isEmpty() && !window.openFile(parsed.project) && screenshotMode)
        return celform::app::kExitBadInput;
    if (screenshotMode) {
        window.resize(1400, 900);
        window.show();
        return window.saveScreenshot(parsed.screenshot) ? celform::app::kExitOk : celform::app::kExitBadInput;
    }
    window.show();
    QTimer::singleShot(0, &window, &MainWindow::offerRecovery);
    return app.exec();
}
