// One sub-command of `celform` as the table lists it (name, synopsis, description, arguments,
// options, run function), what its run function is handed, and the output helpers they share.
// The table itself is in command_line.cpp; the sub-commands live in one file per group beside this one.
#pragma once

#include "cli/command_line.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QJsonObject>
#include <QString>
#include <QStringList>

#include <memory>
#include <vector>

namespace celform::model {
class Document;
struct ProjectData;
} // namespace celform::model

namespace celform::app {

// Gives lupdate the context "celform::app::Cli" for every Cli::tr() of the command line, and the
// table's descriptions marked with QT_TRANSLATE_NOOP("celform::app::Cli", ...).
struct Cli {
    Q_DECLARE_TR_FUNCTIONS(celform::app::Cli)
};

/// A usage error (exit 2): the dispatcher prints the message and the sub-command's synopsis.
struct UsageError {
    QString message;
};

/// A positional argument of a sub-command, as its help lists it.
struct ArgumentSpec {
    const char* name;
    const char* description; ///< QT_TRANSLATE_NOOP("celform::app::Cli", ...)
};

/// An option of a sub-command: --name, with a value when valueName is set.
struct OptionSpec {
    const char* name;
    const char* valueName; ///< nullptr for a flag
    const char* description; ///< QT_TRANSLATE_NOOP("celform::app::Cli", ...)
};

class Invocation;

/// One entry of the sub-command table: it drives dispatch, `celform --help`, `celform SUB --help`
/// and README.md's synopsis (a test holds the two to the same lines).
struct SubCommand {
    const char* name; ///< the word after `celform`
    std::vector<const char*> synopsis; ///< the README's lines, each starting with "celform "
    const char* description; ///< one line, QT_TRANSLATE_NOOP("celform::app::Cli", ...)
    std::vector<ArgumentSpec> arguments;
    std::vector<OptionSpec> options;
    int (*run)(const Invocation&); ///< returns the exit code; throws UsageError, IoError, EditRefused
};

/// The description of the project file argument most sub-commands take.
inline constexpr const char* kProjectArgument = QT_TRANSLATE_NOOP("celform::app::Cli", "Project file (.celform).");
/// The description of --json where it prints the result.
inline constexpr const char* kJsonOption = QT_TRANSLATE_NOOP("celform::app::Cli", "Print machine-readable JSON.");

/// The sub-commands of each group (app/cli/<group>.cpp), in the order of the README.
std::vector<SubCommand> projectCommands(); // new, info
std::vector<SubCommand> keyCommands(); // key, brush, eval
std::vector<SubCommand> lookCommands(); // set, render
std::vector<SubCommand> highlightCommands(); // highlight, patch
std::vector<SubCommand> analysisCommands(); // analyze, curvature, optimize-light, segments
std::vector<SubCommand> offsetsCommands(); // offsets
std::vector<SubCommand> cameraCommands(); // camera
std::vector<SubCommand> fitCommands(); // outline, fit
std::vector<SubCommand> exportCommands(); // export
/// The hidden ones: run by the model as its child processes, left out of help and the README.
std::vector<SubCommand> importCommands(); // import-mesh, import-image

/// The artist's say over the depth analysis (issue 26) as `info --json`, `patch --json` and
/// `segments --json` print it: the focal points (painted, faces below 1, mean importance) and the
/// segment overrides (groups, faces in them).
QJsonObject faceImportanceJson(const model::ProjectData& data);
QJsonObject segmentOverridesJson(const model::ProjectData& data);

/// A sub-command's parsed command line: options by name, positional arguments by index.
class Invocation {
public:
    Invocation(const SubCommand& command, const QCommandLineParser& parser)
        : m_command(command)
        , m_parser(parser)
    { }
    [[nodiscard]] bool isSet(const char* option) const { return m_parser.isSet(QLatin1String(option)); }
    [[nodiscard]] QString value(const char* option) const { return m_parser.value(QLatin1String(option)); }
    [[nodiscard]] QStringList values(const char* option) const { return m_parser.values(QLatin1String(option)); }
    /// The index-th positional argument (the table's count is checked before run).
    [[nodiscard]] QString argument(int index) const { return m_parser.positionalArguments().value(index); }
    [[nodiscard]] int countSet(std::initializer_list<const char*> options) const
    {
        int n = 0;
        for (const char* o : options)
            n += isSet(o) ? 1 : 0;
        return n;
    }
    [[nodiscard]] const SubCommand& command() const { return m_command; }

private:
    const SubCommand& m_command;
    const QCommandLineParser& m_parser;
};

void printOut(const QString& text);
void printErr(const QString& line);
/// Prints an object as indented JSON on standard output.
void printJson(const QJsonObject& object);

/// Opens a project for an edit; the caller saves it once at the end.
std::unique_ptr<model::Document> openProject(const QString& path);

} // namespace celform::app
