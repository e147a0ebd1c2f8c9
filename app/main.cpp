// Entry point: sub-commands run without a display (QCoreApplication); anything else opens the
// editor. Translations follow the system locale.
#include "cli.h"
#include "main_window.h"

#include "celform/views/viewport.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QLibraryInfo>
#include <QLocale>
#include <QSurfaceFormat>
#include <QTimer>
#include <QTranslator>

#include <memory>

namespace {

void setApplicationIdentity()
{
    QCoreApplication::setOrganizationName(QStringLiteral("Celform"));
    QCoreApplication::setApplicationName(QStringLiteral("Celform"));
    QCoreApplication::setApplicationVersion(QStringLiteral(CELFORM_VERSION));
}

/// Loads Qt's own strings and ours for the system locale; English needs none.
void installTranslations(QCoreApplication& app)
{
    const QLocale locale;
    auto* qt = new QTranslator(&app);
    if (qt->load(
            locale, QStringLiteral("qtbase"), QStringLiteral("_"), QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QCoreApplication::installTranslator(qt);
    auto* own = new QTranslator(&app);
    if (own->load(locale, QStringLiteral("celform"), QStringLiteral("_"), QStringLiteral(":/i18n")))
        QCoreApplication::installTranslator(own);
}

} // namespace

int main(int argc, char** argv)
{
    setApplicationIdentity();
    {
        QStringList arguments;
        for (int i = 0; i < argc; ++i)
            arguments << QString::fromLocal8Bit(argv[i]);
        if (celform::app::isCommandLineInvocation(arguments)) {
            QCoreApplication app(argc, argv);
            installTranslations(app);
            return celform::app::runCommandLine(QCoreApplication::arguments());
        }
    }

    // The viewport's GL format must be the default before QApplication exists (STACK.md).
    QSurfaceFormat::setDefaultFormat(celform::views::Viewport::defaultFormat());
    QApplication app(argc, argv);
    installTranslations(app);

    QCommandLineParser parser;
    parser.setApplicationDescription(QCoreApplication::translate("main",
        "Celform: view-dependent models and cartoon looks for cel animation.\n"
        "Sub-commands (celform new, info, ...) run without the editor: see celform --help."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(QStringLiteral("PROJECT"),
        QCoreApplication::translate("main", "Project (.celform) or mesh file to open."), QStringLiteral("[PROJECT]"));
    const QCommandLineOption screenshot(QStringLiteral("screenshot"),
        QCoreApplication::translate("main", "Open, render once, save a PNG of the main window to FILE and quit."),
        QStringLiteral("FILE"));
    parser.addOption(screenshot);
    if (!parser.parse(QCoreApplication::arguments())) {
        fprintf(stderr, "celform: %s\n", qPrintable(parser.errorText()));
        return celform::app::kExitUsage;
    }
    if (parser.isSet(QStringLiteral("help")))
        parser.showHelp(0);
    if (parser.isSet(QStringLiteral("version")))
        parser.showVersion();
    if (parser.positionalArguments().size() > 1) {
        fprintf(
            stderr, "celform: %s\n", qPrintable(QCoreApplication::translate("main", "only one project can be opened")));
        return celform::app::kExitUsage;
    }

    const bool screenshotMode = parser.isSet(screenshot);
    celform::app::MainWindow window(
        screenshotMode ? celform::app::MainWindow::Mode::Batch : celform::app::MainWindow::Mode::Interactive);
    const QString file = parser.positionalArguments().value(0);
    if (!file.isEmpty() && !window.openFile(file) && screenshotMode)
        return celform::app::kExitBadInput;
    if (screenshotMode) {
        window.resize(1400, 900);
        window.show();
        return window.saveScreenshot(parser.value(screenshot)) ? celform::app::kExitOk : celform::app::kExitBadInput;
    }
    window.show();
    QTimer::singleShot(0, &window, &celform::app::MainWindow::offerRecovery);
    return app.exec();
}
