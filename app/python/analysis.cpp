// The Document's sub-commands that work on its project file: analyze, curvature, optimize-light,
// offsets, highlight, patch, outline and fit run through celform.run() (run.cpp), that is through
// the command line's own run functions, on the document's file. The document is saved first when
// it has unsaved edits, and opened again when the sub-command changed the file (its undo history
// then starts afresh, as after File > Open).
#include "document.h"

#include "cli/command.h"

#include <QFile>

#include <pybind11/stl.h>

#include <sys/stat.h>

namespace celform::python {
namespace {

using app::Cli;

/// The file's identity and time: an atomic save replaces the file (a new inode).
std::tuple<dev_t, ino_t, long long, long long> fileStamp(const QString& path)
{
    struct stat s { };
    if (::stat(QFile::encodeName(path).constData(), &s) != 0)
        return {};
    return {s.st_dev, s.st_ino, (long long)s.st_mtim.tv_sec, (long long)s.st_mtim.tv_nsec};
}

py::object onFile(
    PyDocument& d, const std::string& subCommand, const py::args& before, const py::kwargs& kwargs, bool json)
{
    if (d->filePath().isEmpty())
        throw app::UsageError{Cli::tr("“%1” works on the project file: save the document first (Document.save(path))")
                                  .arg(QString::fromStdString(subCommand))};
    d.requireIdle();
    if (d->isModified()) {
        py::gil_scoped_release release;
        d->saveAs(d->filePath());
    }
    const QString path = d->filePath();
    const auto stamp = fileStamp(path);
    py::list args;
    args.append(py::str(subCommand));
    for (const py::handle a : before)
        args.append(a);
    args.append(toPython(path));
    py::dict options(kwargs);
    if (json)
        options["json"] = true;
    const py::object result = py::module_::import("celform").attr("run")(*py::tuple(args), **options);
    if (fileStamp(path) != stamp)
        d->open(path);
    return result;
}

} // namespace

void bindAnalysis(py::class_<PyDocument>& document)
{
    document.def(
        "command",
        [](PyDocument& d, const std::string& subCommand, const py::args& before, const py::kwargs& kw) {
            return onFile(d, subCommand, before, kw, false);
        },
        py::arg("sub_command"),
        "Any sub-command that takes the project file, on the document's file: doc.command(\"segments\", "
        "list=True, json=True) is `celform segments P --list --json`, doc.command(\"key\", \"set\", key=..., "
        "mesh=...) is `celform key set P ...` (saved first, reopened when changed).");
    document.def(
        "analyze", [](PyDocument& d, const py::kwargs& kw) { return onFile(d, "analyze", py::args(), kw, true); },
        "`celform analyze --json`: the depth analysis's segments and error (keywords: its options).");
    document.def(
        "curvature", [](PyDocument& d, const py::kwargs& kw) { return onFile(d, "curvature", py::args(), kw, true); },
        "`celform curvature --json` (out=FILE.ply required).");
    document.def(
        "optimize_light",
        [](PyDocument& d, const py::kwargs& kw) { return onFile(d, "optimize-light", py::args(), kw, true); },
        "`celform optimize-light --json`: moves the key light (saved in the project, unless dry_run=True).");
    document.def(
        "offsets", [](PyDocument& d, const py::kwargs& kw) { return onFile(d, "offsets", py::args(), kw, true); },
        "`celform offsets --json`: auto=True, clear=True or smooth=N.");
    document.def(
        "highlight",
        [](PyDocument& d, const py::kwargs& kw) {
            return onFile(d, "highlight", py::args(), kw, kw.contains("list") || kw.contains("add"));
        },
        "`celform highlight`: list=True, add=NAME (epsilon, op=[...], ...), remove=NAME, rename=NAME with to=NEW.");
    document.def(
        "patch",
        [](PyDocument& d, const py::kwargs& kw) { return onFile(d, "patch", py::args(), kw, !kw.contains("remove")); },
        "`celform patch`: list=True, add=NAME or subtract=NAME with sphere=[...], faces=[...], material=[...]; "
        "remove=NAME.");
    document.def(
        "outline", [](PyDocument& d, const py::kwargs& kw) { return onFile(d, "outline", py::args(), kw, true); },
        "`celform outline --json`: the outline Fit to Drawing aims at (drawing=NAME, out=FILE.svg|.png).");
    document.def(
        "fit", [](PyDocument& d, const py::kwargs& kw) { return onFile(d, "fit", py::args(), kw, true); },
        "`celform fit --json`: Fit to Drawing (key=NAME, camera=True, shape=True, ...).");
}

} // namespace celform::python
