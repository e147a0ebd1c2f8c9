// celform.Document: the model's Document held for Python, and how its edits report errors.
#pragma once

#include "runtime.h"

#include "celform/model/data/io_error.h"
#include "celform/model/document/document.h"

#include <atomic>
#include <memory>

namespace celform::python {

struct PyDocument {
    PyDocument();
    std::unique_ptr<model::Document> doc;

    model::Document* operator->() const { return doc.get(); }
    /// The project's name in error messages: its file, as the command line names it.
    [[nodiscard]] QString source() const;

    /// Renders and exports read the document on threads of their own with the GIL released; while
    /// one runs, an edit from another Python thread is refused (RuntimeError) rather than changing
    /// the data under it.
    std::atomic<int> jobs{0};
    void requireIdle() const;
    struct Job {
        explicit Job(PyDocument& d)
            : doc(d)
        {
            ++doc.jobs;
        }
        ~Job() { --doc.jobs; }
        Job(const Job&) = delete;
        Job& operator=(const Job&) = delete;
        PyDocument& doc;
    };
};

/// Runs f, an edit of d: an edit the document refuses is an IoError naming the project, as the
/// command line's dispatcher reports it.
template <typename F> auto guardedEdit(const PyDocument& d, F f) -> decltype(f())
{
    d.requireIdle();
    try {
        return f();
    } catch (const model::EditRefused& e) {
        throw model::IoError(d.source(), e.message());
    }
}

void bindDocument(py::module_& m, py::class_<PyDocument>& document);
void bindEvaluate(py::module_& m, py::class_<PyDocument>& document);
void bindRender(py::module_& m, py::class_<PyDocument>& document);
void bindAnalysis(py::class_<PyDocument>& document);
void bindRun(py::module_& m);

} // namespace celform::python
