// celform.run(): any sub-command of the command line run in this process, through the command
// line's own table and run functions, with its output captured. What `celform SUB ARGS...` prints
// on standard output comes back as text (and as Python objects with json=True); its errors are
// raised with the messages the command line prints.
#include "cli_args.h"
#include "runtime.h"

#include "cli/command_line.h"

#include "celform/model/data/io_error.h"

#include <pybind11/stl.h>

#include <QTemporaryFile>

#include <cstdio>
#include <unistd.h>

namespace celform::python {
namespace {

/// Standard output and error sent to temporary files while it lives (both the file descriptors
/// and C's streams), put back after.
class CapturedOutput {
public:
    CapturedOutput()
    {
        std::fflush(stdout);
        std::fflush(stderr);
        for (int i = 0; i < 2; ++i) {
            m_files[i] = std::tmpfile();
            m_saved[i] = m_files[i] ? ::dup(i + 1) : -1;
            if (m_saved[i] >= 0)
                ::dup2(::fileno(m_files[i]), i + 1);
        }
    }
    ~CapturedOutput() { restore(); }
    /// Puts the streams back and returns what was written to each.
    std::pair<QByteArray, QByteArray> restore()
    {
        std::fflush(stdout);
        std::fflush(stderr);
        QByteArray texts[2];
        for (int i = 0; i < 2; ++i) {
            if (m_saved[i] >= 0) {
                ::dup2(m_saved[i], i + 1);
                ::close(m_saved[i]);
                m_saved[i] = -1;
            }
            if (m_files[i]) {
                std::rewind(m_files[i]);
                char buffer[65536];
                std::size_t n;
                while ((n = std::fread(buffer, 1, sizeof buffer, m_files[i])) > 0)
                    texts[i].append(buffer, qsizetype(n));
                std::fclose(m_files[i]);
                m_files[i] = nullptr;
            }
        }
        return {texts[0], texts[1]};
    }

private:
    std::FILE* m_files[2] = {nullptr, nullptr};
    int m_saved[2] = {-1, -1};
};

/// The first line the command line would print for a failed run, without its "celform: ".
QString lastError(const QByteArray& err)
{
    QStringList lines = QString::fromUtf8(err).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    for (const QString& line : lines)
        if (line.startsWith(QLatin1String("celform: ")))
            return line.mid(9);
    return lines.isEmpty() ? QString() : lines.constLast();
}

py::object run(const std::string& name, const py::args& args, bool capture, const py::kwargs& kwargs)
{
    ensureApplication();
    const QString sub = QString::fromStdString(name);
    const app::SubCommand& command = subCommand(sub);
    QStringList words;
    for (const py::handle a : args)
        words << (py::isinstance<py::str>(a) ? QString::fromStdString(py::cast<std::string>(a)) : toQString(a));
    words << optionWords(command, kwargs);
    const bool json = kwargs.contains("json") && py::bool_(kwargs["json"]);

    // As the dispatcher (command_line.cpp): the sub-command's options, its argument count, then
    // its run function; an edit the document refuses names the project.
    const CliOptions options(sub, words);
    if (options.positional().size() != qsizetype(command.arguments.size()))
        throw app::UsageError{options.positional().size() < qsizetype(command.arguments.size())
                ? app::Cli::tr("missing arguments")
                : app::Cli::tr("unexpected argument “%1”").arg(options.positional().constLast())};
    // Python's own buffered output goes first.
    py::module_::import("sys").attr("stdout").attr("flush")();
    py::module_::import("sys").attr("stderr").attr("flush")();
    int code = 0;
    QByteArray out, err;
    {
        std::optional<CapturedOutput> captured;
        if (capture)
            captured.emplace();
        py::gil_scoped_release release;
        try {
            code = command.run(options.in());
        } catch (const model::EditRefused& e) {
            qsizetype project = 0;
            while (project + 1 < qsizetype(command.arguments.size())
                && qstrcmp(command.arguments[std::size_t(project)].name, "P") != 0)
                ++project;
            if (captured)
                captured->restore();
            throw model::IoError(options.positional().value(project), e.message());
        } catch (...) {
            if (captured)
                captured->restore();
            throw;
        }
        if (captured)
            std::tie(out, err) = captured->restore();
    }
    if (code != app::kExitOk) {
        // Not captured: the message went to the process's standard error already.
        const QString message
            = capture ? lastError(err) : app::Cli::tr("celform %1 exited with code %2").arg(sub).arg(code);
        if (code == app::kExitUsage)
            throw app::UsageError{message};
        throwIo(message);
    }
    if (!capture)
        return py::none();
    if (!err.isEmpty())
        // Warnings go on to Python's standard error, as the command line prints them.
        py::module_::import("sys").attr("stderr").attr("write")(py::str(err.constData(), std::size_t(err.size())));
    const py::str text(out.constData(), std::size_t(out.size()));
    if (json && !out.trimmed().isEmpty())
        return py::module_::import("json").attr("loads")(text);
    return std::move(text);
}

} // namespace

void bindRun(py::module_& m)
{
    m.def("run", &run, py::arg("sub_command"), py::kw_only(), py::arg("capture") = true,
        R"(Runs a sub-command of the command line in this process, through the same code.

celform.run("render", "p.celform", frames=(0, 47), out="shot_####.png") is
`celform render p.celform --frames 0-47 --out shot_####.png`: positional arguments are the
sub-command's arguments; keyword arguments its options (see docs/python.md). Returns what the
sub-command prints on standard output, as Python objects when json=True; warnings go to
sys.stderr. Raises celform.UsageError (exit code 2) or celform.IoError (exit code 3) with the
command line's message. capture=False leaves the output on the process's own streams.)");
}

} // namespace celform::python
