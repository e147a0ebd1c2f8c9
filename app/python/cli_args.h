// Python keyword arguments as a sub-command's options: render(view=(0, 0, 1), size=(640, 480),
// lines="silhouette,crease") is `celform render --view 0,0,1 --size 640x480 --lines
// silhouette,crease`, parsed by the sub-command's own option table and read by the command line's
// own readers (app/cli/options.h), so every value is checked as there, with the same messages.
//
// A keyword is the option's name with _ for - (a trailing _ is dropped: pass_ is --pass). Values:
// None leaves the option out; True gives a flag, or "on" for an option with a value; False leaves
// a flag out, or gives "off"; a number is written so that it reads back the same; a sequence of
// numbers is joined with commas (size: WxH; frames: A-B or A-B:STEP); a list of strings or paths
// repeats the option; anything else is str() of it.
#pragma once

#include "runtime.h"

#include "cli/command.h"

#include <QCommandLineParser>

#include <memory>

namespace celform::python {

/// The sub-command of the command line's table named name; UsageError when there is none.
const app::SubCommand& subCommand(const QString& name);

/// A sub-command's options from keyword arguments, as command-line words.
QStringList optionWords(const app::SubCommand& command, const py::kwargs& kwargs);

/// A sub-command's command line parsed by its own option table, for the readers that take an
/// Invocation. Positional arguments are checked by the caller.
class CliOptions {
public:
    CliOptions(const QString& subCommandName, const QStringList& words);
    CliOptions(const QString& subCommandName, const py::kwargs& kwargs)
        : CliOptions(subCommandName, optionWords(subCommand(subCommandName), kwargs))
    { }
    CliOptions(const CliOptions&) = delete;
    CliOptions& operator=(const CliOptions&) = delete;

    [[nodiscard]] const app::Invocation& in() const { return *m_invocation; }
    [[nodiscard]] const app::SubCommand& command() const { return m_command; }
    [[nodiscard]] QStringList positional() const { return m_parser.positionalArguments(); }

private:
    const app::SubCommand& m_command;
    QCommandLineParser m_parser;
    std::unique_ptr<app::Invocation> m_invocation;
};

} // namespace celform::python
