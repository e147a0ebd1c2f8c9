// Entry point: sub-commands run on the model alone (QCoreApplication, no display); anything else
// opens the editor, which the launcher loads as a module so that the command line never maps VTK,
// OpenGL or Qt Widgets. Translations follow the system locale.
#include "cli/command_line.h"
#include "launcher/large_pages.h"
#include "launcher/launch.h"

#include <QCoreApplication>
#include <QGuiApplication>

int main(int argc, char** argv)
{
    celform::app::restartWithLargePagesIfUseful(argc, argv);
    celform::app::setApplicationIdentity();
    QStringList arguments;
    for (int i = 0; i < argc; ++i)
        arguments << QString::fromLocal8Bit(argv[i]);
    if (!celform::app::isCommandLineInvocation(arguments))
        return celform::app::launchEditor(argc, argv);
    // The import child draws SVG text, which needs a QGuiApplication's fonts: on the offscreen
    // platform (fontconfig's fonts, no display), whatever QT_QPA_PLATFORM says (issue 27).
    if (arguments.value(1) == QLatin1String("import-image")) {
        qputenv("QT_QPA_PLATFORM", "offscreen");
        QGuiApplication app(argc, argv);
        return celform::app::runCommandLine(QCoreApplication::arguments());
    }
    QCoreApplication app(argc, argv);
    celform::app::installTranslations(app);
    return celform::app::runCommandLine(QCoreApplication::arguments());
}
