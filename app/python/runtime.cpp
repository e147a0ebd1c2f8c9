// The celform module's runtime: the Qt application, the exceptions, the progress callback.
#include "runtime.h"

#include "cli/command.h"
#include "launcher/launch.h"

#include "celform/model/data/io_error.h"

#include <QCoreApplication>
#include <QJsonDocument>

#include <new>

namespace celform::python {
namespace {

// The exception types, made once when the module loads and kept for the process's life (never
// released: they outlive the interpreter's finalisation of the module).
PyObject* g_error = nullptr;
PyObject* g_usageError = nullptr;
PyObject* g_ioError = nullptr;
PyObject* g_cancelled = nullptr;

PyObject* defineException(py::module_& module, const char* name, py::tuple bases, const char* doc)
{
    const std::string qualified = std::string("celform.") + name;
    PyObject* type = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, bases.ptr(), nullptr);
    if (!type)
        throw py::error_already_set();
    module.add_object(name, py::handle(type));
    return type;
}

void setError(PyObject* type, const QString& message)
{
    PyErr_SetString(type, message.toUtf8().constData());
}

} // namespace

void ensureApplication()
{
    if (QCoreApplication::instance())
        return;
    // argc and argv must outlive the application; it lives as long as the process.
    static int argc = 1;
    static char name[] = "celform";
    static char* argv[] = {name, nullptr};
    app::setApplicationIdentity();
    static QCoreApplication* application = new QCoreApplication(argc, argv);
    app::installTranslations(*application);
}

void registerExceptions(py::module_& module)
{
    const py::handle exception(PyExc_Exception);
    g_error = defineException(module, "Error", py::make_tuple(exception),
        "An error of Celform: the command line's message for the same problem.");
    g_usageError
        = defineException(module, "UsageError", py::make_tuple(py::handle(g_error), py::handle(PyExc_ValueError)),
            "A value the command line refuses as a usage error (exit code 2): it names the option.");
    g_ioError = defineException(module, "IoError", py::make_tuple(py::handle(g_error), py::handle(PyExc_OSError)),
        "Bad input or an output that cannot be written (exit code 3): it names the file and the problem.");
    g_cancelled = defineException(
        module, "Cancelled", py::make_tuple(py::handle(g_error)), "A long call stopped by its progress callback.");
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p)
                std::rethrow_exception(p);
        } catch (const app::UsageError& e) {
            setError(g_usageError, e.message);
        } catch (const model::IoError& e) {
            setError(g_ioError, e.message());
        } catch (const model::EditRefused& e) {
            // Where no project names it (the callers name the project when there is one).
            setError(g_ioError, e.message());
        }
    });
}

void throwUsage(const QString& message)
{
    throw app::UsageError{message};
}

void throwIo(const QString& message)
{
    setError(g_ioError, message);
    throw py::error_already_set();
}

QString toQString(const py::handle& value)
{
    const py::object text = py::module_::import("os").attr("fspath")(value);
    if (py::isinstance<py::bytes>(text))
        return QString::fromLocal8Bit(py::cast<std::string>(text).c_str());
    return QString::fromStdString(py::cast<std::string>(text));
}

py::str toPython(const QString& text)
{
    return py::str(text.toStdString());
}

py::list toPython(const QStringList& list)
{
    py::list out;
    for (const QString& s : list)
        out.append(toPython(s));
    return out;
}

py::object toPython(const QJsonObject& object)
{
    const QByteArray text = QJsonDocument(object).toJson(QJsonDocument::Compact);
    return py::module_::import("json").attr("loads")(py::str(text.constData(), std::size_t(text.size())));
}

CallbackProgress::CallbackProgress(py::object callback)
    : m_callback(std::move(callback))
{
    if (!m_callback.is_none() && !PyCallable_Check(m_callback.ptr()))
        throw py::type_error("progress must be a callable progress(done, total, label) or None");
}

CallbackProgress::~CallbackProgress()
{
    // The stored exception is released with the GIL taken.
    if (m_error) {
        py::gil_scoped_acquire gil;
        m_error.reset();
    }
}

void CallbackProgress::progress(std::int64_t done, std::int64_t total, const std::string& label)
{
    if (m_cancel.load())
        return;
    py::gil_scoped_acquire gil;
    try {
        if (m_callback.is_none())
            return;
        const py::object answer = m_callback(done, total, py::str(label));
        // False (not None) stops the job.
        if (answer.ptr() == Py_False)
            m_cancel.store(true);
    } catch (py::error_already_set& e) {
        m_error.emplace(std::move(e));
        m_cancel.store(true);
    }
}

void CallbackProgress::checkSignals()
{
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) {
        py::error_already_set e;
        if (!m_error)
            m_error.emplace(std::move(e));
        m_cancel.store(true);
    }
}

void CallbackProgress::rethrow()
{
    if (m_error) {
        py::error_already_set e = std::move(*m_error);
        m_error.reset();
        throw e;
    }
}

} // namespace celform::python
