// Keyword arguments as command-line words, parsed by the sub-command's table (see cli_args.h).
#include "cli_args.h"

#include <pybind11/stl.h>

#include <vector>

namespace celform::python {
namespace {

const std::vector<app::SubCommand>& allCommands()
{
    // The command line's groups, as its dispatcher gathers them (command_line.cpp), and the
    // hidden ones last.
    static const std::vector<app::SubCommand> commands = [] {
        std::vector<app::SubCommand> all;
        for (auto group :
            {app::projectCommands, app::keyCommands, app::lookCommands, app::highlightCommands, app::analysisCommands,
                app::offsetsCommands, app::cameraCommands, app::fitCommands, app::exportCommands})
            for (app::SubCommand& c : group())
                all.push_back(std::move(c));
        return all;
    }();
    return commands;
}

const app::OptionSpec* findOption(const app::SubCommand& command, const QString& name)
{
    for (const app::OptionSpec& o : command.options)
        if (name == QLatin1String(o.name))
            return &o;
    return nullptr;
}

bool isNumber(const py::handle& v)
{
    return !py::isinstance<py::bool_>(v) && (py::isinstance<py::int_>(v) || py::isinstance<py::float_>(v));
}

/// A number as the command line reads it back: ints as they are, floats by repr (shortest text
/// that reads back the same double).
QString numberText(const py::handle& v)
{
    return QString::fromStdString(py::cast<std::string>(py::repr(v)));
}

QString scalarText(const py::handle& v)
{
    if (isNumber(v))
        return numberText(v);
    if (py::isinstance<py::str>(v))
        return QString::fromStdString(py::cast<std::string>(v));
    if (py::hasattr(v, "__fspath__") || py::isinstance<py::bytes>(v))
        return toQString(v);
    return QString::fromStdString(py::cast<std::string>(py::str(v)));
}

/// numpy arrays and scalars as Python lists and numbers.
py::object plain(py::object v)
{
    if (py::hasattr(v, "tolist") && !py::isinstance<py::str>(v))
        return v.attr("tolist")();
    return v;
}

bool isSequence(const py::handle& v)
{
    return py::isinstance<py::tuple>(v) || py::isinstance<py::list>(v);
}

bool allNumbers(const py::handle& v)
{
    const py::sequence items = v.cast<py::sequence>();
    bool numbers = py::len(items) > 0;
    for (const py::handle item : items)
        numbers = numbers && isNumber(item);
    return numbers;
}

/// One option value: a scalar, or numbers joined (size: WxH; frames: A-B or A-B:STEP; else commas).
QString valueText(const QString& name, const py::object& v)
{
    if (!isSequence(v) || !allNumbers(v))
        return scalarText(v);
    QStringList parts;
    for (const py::handle item : v.cast<py::sequence>())
        parts << numberText(item);
    if (name == QLatin1String("size"))
        return parts.join(QLatin1Char('x'));
    if (name == QLatin1String("frames") && (parts.size() == 2 || parts.size() == 3))
        return parts[0] + QLatin1Char('-') + parts[1] + (parts.size() == 3 ? QLatin1Char(':') + parts[2] : QString());
    return parts.join(QLatin1Char(','));
}

} // namespace

const app::SubCommand& subCommand(const QString& name)
{
    for (const app::SubCommand& c : allCommands())
        if (name == QLatin1String(c.name))
            return c;
    QString message = app::Cli::tr("celform: unknown sub-command “%1”").arg(name);
    if (message.startsWith(QLatin1String("celform: ")))
        message = message.mid(9);
    throw app::UsageError{message};
}

QStringList optionWords(const app::SubCommand& command, const py::kwargs& kwargs)
{
    QStringList words;
    for (const auto& [key, value] : kwargs) {
        QString name = QString::fromStdString(py::cast<std::string>(key));
        while (name.endsWith(QLatin1Char('_')))
            name.chop(1);
        name.replace(QLatin1Char('_'), QLatin1Char('-'));
        const QString flag = QStringLiteral("--") + name;
        if (value.is_none())
            continue;
        const app::OptionSpec* spec = findOption(command, name);
        if (py::isinstance<py::bool_>(value)) {
            const bool on = value.cast<bool>();
            if (spec && spec->valueName)
                words << flag << (on ? QStringLiteral("on") : QStringLiteral("off"));
            else if (on)
                words << flag;
            continue;
        }
        const py::object v = plain(py::reinterpret_borrow<py::object>(value));
        if (isSequence(v) && !allNumbers(v)) {
            // A list of strings, paths or number tuples: the option once for each.
            for (const py::handle item : v.cast<py::sequence>())
                words << flag << valueText(name, plain(py::reinterpret_borrow<py::object>(item)));
            continue;
        }
        words << flag << valueText(name, v);
    }
    return words;
}

CliOptions::CliOptions(const QString& subCommandName, const QStringList& words)
    : m_command(subCommand(subCommandName))
{
    // As the command line's dispatcher sets its parser up (command_line.cpp).
    m_parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    for (const app::OptionSpec& o : m_command.options)
        m_parser.addOption(o.valueName
                ? QCommandLineOption(QLatin1String(o.name), QString(), QLatin1String(o.valueName))
                : QCommandLineOption(QLatin1String(o.name), QString()));
    if (!m_parser.parse(QStringList{QStringLiteral("celform ") + QLatin1String(m_command.name)} + words))
        throw app::UsageError{m_parser.errorText()};
    m_invocation = std::make_unique<app::Invocation>(m_command, m_parser);
}

} // namespace celform::python
