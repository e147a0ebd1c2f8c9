// The `celform` Python module (docs/python.md): its exceptions, celform.Document and its parts,
// and celform.run(). Loading it maps the model (Qt Core and Gui), not the editor nor OpenImageIO;
// a QCoreApplication is made when the first document opens or sub-command runs, if the process has
// no Qt application yet. Nothing needs a display.
#include "document.h"
#include "runtime.h"

#include "cli/command_line.h"

#include "celform/model/render/render_output.h"

namespace celform::python {
namespace {

void setDefaultImporter()
{
    // The model starts `celform import-mesh` / `import-image` for Assimp's formats and most drawing
    // formats (import_process.h): this build's program unless CELFORM_EXECUTABLE names another.
    if (qEnvironmentVariableIsEmpty("CELFORM_EXECUTABLE"))
        qputenv("CELFORM_EXECUTABLE", CELFORM_PYTHON_EXECUTABLE);
}

} // namespace
} // namespace celform::python

PYBIND11_MODULE(celform, m)
{
    namespace cp = celform::python;
    namespace py = pybind11;
    m.doc() = "Celform: view-dependent geometry and cartoon look for cel animation, without a display. "
              "The Document's operations, the renderer, the exporters and the analyses, through the same "
              "code as the `celform` command line (docs/python.md).";
    m.attr("__version__") = CELFORM_VERSION;
    cp::setDefaultImporter();
    cp::registerExceptions(m);
    m.def(
        "sub_commands", [] { return cp::toPython(celform::app::subCommandNames()); },
        "The command line's sub-commands, in its table's order.");
    m.def(
        "render_passes", [] { return cp::toPython(celform::model::renderPassNames()); },
        "The pass names of render(pass_=...).");
    py::class_<cp::PyDocument> document(
        m, "Document", "A Celform project open in memory, with its undo history: the model's Document.");
    cp::bindDocument(m, document);
    cp::bindEvaluate(m, document);
    cp::bindRender(m, document);
    cp::bindAnalysis(document);
    cp::bindRun(m);
}
