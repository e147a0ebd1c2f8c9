// The sub-command table and its dispatcher: parsing each sub-command's options from its entry,
// `celform --help` and `celform SUB --help` from the same entries, and the exit codes of errors.
#include "cli/command_line.h"

#include "cli/command.h"

#include "celform/model/document/document.h"
#include "celform/model/data/io_error.h"

#include <QJsonDocument>
#include <QTextStream>

#include <exception>
#include <new>

namespace celform::app {
namespace {

const std::vector<SubCommand>& table()
{
    static const std::vector<SubCommand> commands = [] {
        std::vector<SubCommand> all;
        for (auto group : {projectCommands, keyCommands, lookCommands, highlightCommands, analysisCommands,
                 offsetsCommands, cameraCommands, fitCommands, exportCommands})
            for (SubCommand& c : group())
                all.push_back(std::move(c));
        return all;
    }();
    return commands;
}

/// The sub-commands nobody types (importCommands()): dispatched, never listed.
const std::vector<SubCommand>& hiddenTable()
{
    static const std::vector<SubCommand> commands = importCommands();
    return commands;
}

const SubCommand* find(const QString& name)
{
    for (const auto* commands : {&table(), &hiddenTable()})
        for (const SubCommand& c : *commands)
            if (name == QLatin1String(c.name))
                return &c;
    return nullptr;
}

// Command syntax is not translated; only the words around it are.
const char* const kVersionSynopsis = "celform --version";
const char* const kEditorSynopsis = "celform [PROJECT] [--screenshot FILE.png]";

bool isHelp(const QString& word)
{
    return word == QLatin1String("--help") || word == QLatin1String("-h") || word == QLatin1String("help");
}

QString synopsisOf(const SubCommand& c)
{
    QStringList lines;
    for (const char* line : c.synopsis)
        lines << QLatin1String(line);
    return lines.join(QStringLiteral("\n       "));
}

/// Rows of "  name  description", the descriptions in one column.
QString columns(const QList<QPair<QString, QString>>& rows)
{
    qsizetype width = 0;
    for (const auto& [left, right] : rows)
        width = std::max(width, left.size());
    QString text;
    for (const auto& [left, right] : rows)
        text += QStringLiteral("  ") + left.leftJustified(width + 2) + right + QLatin1Char('\n');
    return text;
}

QString commandHelp(const SubCommand& c)
{
    QString text = Cli::tr("usage:") + QLatin1Char(' ') + synopsisOf(c) + QStringLiteral("\n\n")
        + Cli::tr(c.description) + QStringLiteral("\n\n");
    QList<QPair<QString, QString>> arguments, options;
    for (const ArgumentSpec& a : c.arguments)
        arguments.append({QLatin1String(a.name), Cli::tr(a.description)});
    for (const OptionSpec& o : c.options)
        options.append({QStringLiteral("--") + QLatin1String(o.name)
                + (o.valueName ? QLatin1Char(' ') + QLatin1String(o.valueName) : QString()),
            Cli::tr(o.description)});
    options.append({QStringLiteral("-h, --help"), Cli::tr("Show this help.")});
    return text + Cli::tr("Arguments:") + QLatin1Char('\n') + columns(arguments) + QLatin1Char('\n')
        + Cli::tr("Options:") + QLatin1Char('\n') + columns(options);
}

QString globalHelp()
{
    QList<QPair<QString, QString>> commands;
    for (const SubCommand& c : table())
        commands.append({QLatin1String(c.name), Cli::tr(c.description)});
    QString text = Cli::tr("usage:") + QLatin1Char(' ') + QLatin1String(kEditorSynopsis) + QStringLiteral("\n       ")
        + QStringLiteral("celform SUB-COMMAND ...\n\n")
        + Cli::tr("Without a sub-command celform opens the editor (it needs a display). The sub-commands run without "
                  "one:")
        + QLatin1Char('\n') + columns(commands) + QLatin1Char('\n');
    for (const QString& line : synopsisLines())
        text += QStringLiteral("  ") + line + QLatin1Char('\n');
    return text + QLatin1Char('\n') + Cli::tr("celform SUB-COMMAND --help describes each option.") + QLatin1Char('\n')
        + Cli::tr("Exit codes: 0 success, 2 usage error, 3 bad input.") + QLatin1Char('\n');
}

/// Parses the options of a sub-command's entry and runs it. args[0] is the sub-command's name.
int dispatch(const SubCommand& command, const QStringList& args)
{
    QCommandLineParser parser;
    parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    parser.addHelpOption();
    for (const OptionSpec& o : command.options)
        parser.addOption(o.valueName
                ? QCommandLineOption(QLatin1String(o.name), Cli::tr(o.description), QLatin1String(o.valueName))
                : QCommandLineOption(QLatin1String(o.name), Cli::tr(o.description)));
    // QCommandLineParser wants a program name first.
    if (!parser.parse(QStringList{QStringLiteral("celform ") + QLatin1String(command.name)} + args.mid(1)))
        throw UsageError{parser.errorText()};
    if (parser.isSet(QStringLiteral("help"))) {
        printOut(commandHelp(command));
        return kExitOk;
    }
    if (parser.positionalArguments().size() != qsizetype(command.arguments.size()))
        throw UsageError{parser.positionalArguments().size() < qsizetype(command.arguments.size())
                ? Cli::tr("missing arguments")
                : Cli::tr("unexpected argument “%1”").arg(parser.positionalArguments().constLast())};
    try {
        return command.run(Invocation(command, parser));
    } catch (const model::EditRefused& e) {
        // The document refused an edit of the project: bad input, named by the project's file.
        qsizetype project = 0;
        while (project + 1 < qsizetype(command.arguments.size())
            && qstrcmp(command.arguments[std::size_t(project)].name, "P") != 0)
            ++project;
        throw model::IoError(parser.positionalArguments().value(project), e.message());
    }
}

} // namespace

void printOut(const QString& text)
{
    QTextStream(stdout) << text;
}

void printErr(const QString& line)
{
    QTextStream(stderr) << line << Qt::endl;
}

void printJson(const QJsonObject& object)
{
    printOut(QString::fromUtf8(QJsonDocument(object).toJson(QJsonDocument::Indented)));
}

std::unique_ptr<model::Document> openProject(const QString& path)
{
    auto doc = std::make_unique<model::Document>();
    doc->open(path);
    return doc;
}

QStringList subCommandNames()
{
    QStringList names;
    for (const SubCommand& c : table())
        names << QLatin1String(c.name);
    return names;
}

QStringList synopsisLines()
{
    QStringList lines;
    for (const SubCommand& c : table())
        for (const char* line : c.synopsis)
            lines << QLatin1String(line);
    return lines << QLatin1String(kVersionSynopsis) << QLatin1String(kEditorSynopsis);
}

bool isCommandLineInvocation(const QStringList& arguments)
{
    if (arguments.size() < 2)
        return false;
    const QString& first = arguments.at(1);
    return find(first) || first == QLatin1String("--version") || first == QLatin1String("-v") || isHelp(first);
}

int runCommandLine(const QStringList& arguments)
{
    const QString first = arguments.value(1);
    const SubCommand* command = find(first);
    try {
        if (first == QLatin1String("--version") || first == QLatin1String("-v")) {
            printOut(QStringLiteral("celform %1\n").arg(QCoreApplication::applicationVersion()));
            return kExitOk;
        }
        if (isHelp(first)) {
            // `celform help SUB` is `celform SUB --help`.
            const SubCommand* about = find(arguments.value(2));
            printOut(about ? commandHelp(*about) : globalHelp());
            return kExitOk;
        }
        if (!command) {
            printErr(Cli::tr("celform: unknown sub-command “%1”").arg(first));
            printErr(globalHelp());
            return kExitUsage;
        }
        return dispatch(*command, arguments.mid(1));
    } catch (const UsageError& e) {
        printErr(QStringLiteral("celform: ") + e.message);
        if (command)
            printErr(Cli::tr("usage:") + QLatin1Char(' ') + synopsisOf(*command) + QLatin1Char('\n')
                + Cli::tr("(celform %1 --help describes each option)").arg(QLatin1String(command->name)));
        return kExitUsage;
    } catch (const model::IoError& e) {
        printErr(QStringLiteral("celform: ") + e.message());
        return kExitBadInput;
    } catch (const std::bad_alloc&) {
        printErr(Cli::tr("celform: out of memory"));
        return kExitBadInput;
    } catch (const std::exception& e) {
        printErr(QStringLiteral("celform: ") + QString::fromLocal8Bit(e.what()));
        return kExitBadInput;
    }
}

} // namespace celform::app
