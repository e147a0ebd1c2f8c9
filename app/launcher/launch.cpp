// Starting `celform` without a sub-command: every check that can fail is made before the editor
// module is loaded and before a QApplication exists, because Qt's xcb plugin aborts the process
// when it finds no display. Messages are translated: the failure paths create a QCoreApplication
// for the translators and run the checks again to word them.
#include "launcher/launch.h"

#include "cli/command_line.h"
#include "cli/command.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QLibrary>
#include <QLibraryInfo>
#include <QLocale>
#include <QTranslator>

namespace celform::app {
namespace {

/// The editor module's entry: creates the QApplication and runs the editor (app/editor/editor_module.cpp).
using EditorEntry = int (*)(int argc, char** argv);
constexpr const char* kEditorEntry = "celform_editor_main";

QStringList argumentList(int argc, char** argv)
{
    QStringList arguments;
    for (int i = 0; i < argc; ++i)
        arguments << QString::fromLocal8Bit(argv[i]);
    return arguments;
}

/// Whether Qt can open a window: a display server is named, or a platform plugin is chosen.
bool displayAvailable()
{
    return !qEnvironmentVariableIsEmpty("DISPLAY") || !qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY")
        || !qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM");
}

/// Takes out Qt's own window-system options (-platform offscreen, -style fusion, ...), which
/// QApplication removes before the editor reads its arguments; says whether one chose a platform
/// or an X display.
QStringList withoutQtOptions(const QStringList& arguments, bool* choosesDisplay)
{
    static const QStringList flags = {QStringLiteral("-reverse"), QStringLiteral("-widgetcount"),
        QStringLiteral("-nograb"), QStringLiteral("-dograb"), QStringLiteral("-sync")};
    static const QStringList withValue = {QStringLiteral("-platform"), QStringLiteral("-platformpluginpath"),
        QStringLiteral("-platformtheme"), QStringLiteral("-plugin"), QStringLiteral("-qwindowgeometry"),
        QStringLiteral("-qwindowtitle"), QStringLiteral("-qwindowicon"), QStringLiteral("-session"),
        QStringLiteral("-style"), QStringLiteral("-stylesheet"), QStringLiteral("-display"),
        QStringLiteral("-geometry"), QStringLiteral("-name"), QStringLiteral("-title"), QStringLiteral("-visual")};
    QStringList kept;
    for (qsizetype i = 0; i < arguments.size(); ++i) {
        // Qt reads "--platform" as "-platform".
        const QString a = arguments[i].startsWith(QLatin1String("--")) ? arguments[i].mid(1) : arguments[i];
        if (i > 0 && flags.contains(a))
            continue;
        if (i > 0 && withValue.contains(a) && i + 1 < arguments.size()) {
            *choosesDisplay = *choosesDisplay || a == QLatin1String("-platform") || a == QLatin1String("-display");
            ++i;
            continue;
        }
        kept << arguments[i];
    }
    return kept;
}

/// Where the module may be: beside the binary (the build tree) or in ../lib/celform (installed).
QStringList editorModuleCandidates()
{
    const QDir dir = QFileInfo(QStringLiteral("/proc/self/exe")).canonicalFilePath().isEmpty()
        ? QDir::current()
        : QFileInfo(QFileInfo(QStringLiteral("/proc/self/exe")).canonicalFilePath()).dir();
    const QString name = QStringLiteral(CELFORM_EDITOR_MODULE_NAME);
    return {dir.filePath(name), QDir::cleanPath(dir.filePath(QStringLiteral("../lib/celform/") + name))};
}

} // namespace

void setApplicationIdentity()
{
    QCoreApplication::setOrganizationName(QStringLiteral("Celform"));
    QCoreApplication::setApplicationName(QStringLiteral("Celform"));
    QCoreApplication::setApplicationVersion(QStringLiteral(CELFORM_VERSION));
}

void installTranslations(QCoreApplication& app)
{
    installTranslations(app, QLocale());
}

void installTranslations(QCoreApplication& app, const QLocale& locale)
{
    auto* qt = new QTranslator(&app);
    if (qt->load(
            locale, QStringLiteral("qtbase"), QStringLiteral("_"), QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QCoreApplication::installTranslator(qt);
    auto* own = new QTranslator(&app);
    if (own->load(locale, QStringLiteral("celform"), QStringLiteral("_"), QStringLiteral(":/i18n")))
        QCoreApplication::installTranslator(own);
}

int parseEditorArguments(const QStringList& arguments, EditorArguments& parsed, QString* message, bool checkDisplay)
{
    QCommandLineParser parser;
    const QCommandLineOption help({QStringLiteral("h"), QStringLiteral("help")}, QString());
    const QCommandLineOption version({QStringLiteral("v"), QStringLiteral("version")}, QString());
    const QCommandLineOption screenshot(QStringLiteral("screenshot"), QString(), QStringLiteral("FILE"));
    parser.addOptions({help, version, screenshot});
    bool choosesDisplay = false;
    const QStringList editorArguments = withoutQtOptions(arguments, &choosesDisplay);
    auto problem = [&](int code, const QString& text) {
        if (message)
            *message = QStringLiteral("celform: ") + text;
        return code;
    };
    if (!parser.parse(editorArguments))
        return problem(kExitUsage,
            parser.errorText() + QLatin1Char('\n') + Cli::tr("usage:") + QLatin1Char(' ') + synopsisLines().constLast()
                + QLatin1Char('\n') + Cli::tr("(celform --help lists the sub-commands)"));
    parsed.help = parser.isSet(help);
    parsed.version = parser.isSet(version);
    parsed.screenshot = parser.value(screenshot);
    if (parsed.help || parsed.version)
        return kExitOk;
    const QStringList files = parser.positionalArguments();
    if (files.size() > 1)
        return problem(kExitUsage, QCoreApplication::translate("main", "only one project can be opened"));
    parsed.project = files.value(0);
    if (!parsed.project.isEmpty() && !QFileInfo::exists(parsed.project)) {
        // A bare word is a mistyped sub-command; anything with a suffix or a folder is a file.
        const QFileInfo info(parsed.project);
        if (info.suffix().isEmpty() && !parsed.project.contains(QLatin1Char('/')))
            return problem(kExitUsage,
                Cli::tr("unknown sub-command “%1”; the sub-commands are %2 (celform --help)")
                    .arg(parsed.project, subCommandNames().join(QStringLiteral(", "))));
        return problem(kExitBadInput, Cli::tr("%1: the file does not exist").arg(parsed.project));
    }
    if (checkDisplay && !choosesDisplay && !displayAvailable())
        return problem(kExitUsage,
            Cli::tr("the editor needs a display, and neither DISPLAY nor WAYLAND_DISPLAY is set (run it under "
                    "xvfb-run, or set QT_QPA_PLATFORM); the sub-commands need none (celform --help)"));
    return kExitOk;
}

int launchEditor(int argc, char** argv)
{
    const QStringList arguments = argumentList(argc, argv);
    EditorArguments parsed;
    int code = parseEditorArguments(arguments, parsed, nullptr);
    QString message;
    QLibrary module;
    EditorEntry entry = nullptr;
    if (code == kExitOk && !parsed.help && !parsed.version) {
        for (const QString& candidate : editorModuleCandidates()) {
            if (!QFileInfo::exists(candidate))
                continue;
            module.setFileName(candidate);
            entry = module.load() ? reinterpret_cast<EditorEntry>(module.resolve(kEditorEntry)) : nullptr;
            break;
        }
        if (!entry)
            code = kExitBadInput;
    }
    if (entry)
        return entry(argc, argv); // the module is never unloaded: its libraries stay until exit

    // Help, version or a problem: answered as the command line does, translated.
    QCoreApplication app(argc, argv);
    installTranslations(app);
    if (parsed.help || parsed.version)
        return runCommandLine(
            {arguments.value(0), parsed.help ? QStringLiteral("--help") : QStringLiteral("--version")});
    if (code == kExitBadInput && parseEditorArguments(arguments, parsed, &message) == kExitOk)
        message = module.fileName().isEmpty()
            ? Cli::tr("celform: the editor module %1 is missing (looked in %2)")
                  .arg(QStringLiteral(CELFORM_EDITOR_MODULE_NAME), editorModuleCandidates().join(QStringLiteral(", ")))
            : Cli::tr("celform: %1: the editor module cannot be loaded: %2")
                  .arg(module.fileName(), module.errorString());
    else
        parseEditorArguments(arguments, parsed, &message);
    printErr(message);
    return code;
}

} // namespace celform::app
