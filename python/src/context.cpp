// context.cpp — the extension's contexts, exceptions and run(): every C API
// call of the module goes through run(), which releases the GIL, forwards
// progress to Python, turns Ctrl-C into a cancel (KeyboardInterrupt after the
// call returns, never a partial result) and statuses into exceptions.
// Copyright (C) 2026 the fabvdb developers. GPL-3.0-or-later.
#include <optional>

#include "binding.h"

namespace fabvdb_python {

namespace {

// fabvdb.Error and one subclass per status, indexed by the status code.
PyObject* status_errors[9] = {};

// What the progress adapter needs during one call.
struct CallState {
    const py::object* progress;
    std::optional<py::error_already_set> error;  // KeyboardInterrupt or the callback's exception
};

int progress_adapter(void* user, const char* stage, double fraction) {
    CallState* state = static_cast<CallState*>(user);
    py::gil_scoped_acquire gil;
    if (state->error) return 1;
    // Runs Python's signal handlers when on the main thread: SIGINT raises.
    if (PyErr_CheckSignals() != 0) {
        state->error.emplace();
        return 1;
    }
    if (state->progress->is_none()) return 0;
    try {
        py::object answer = (*state->progress)(stage, fraction);
        return PyObject_IsTrue(answer.ptr()) == 1 ? 1 : 0;
    } catch (py::error_already_set& error) {
        state->error.emplace(std::move(error));
        return 1;
    }
}

}  // namespace

Context::Context(int threads, uint64_t memory_budget) : threads_(threads) {
    if (threads < 0) raise_invalid("threads must be 0 (every core) or more");
    if (fabvdb_ctx_new(&ctx_) != FABVDB_OK) throw std::bad_alloc();
    fabvdb_ctx_set_threads(ctx_, threads);
    fabvdb_ctx_set_memory_budget(ctx_, memory_budget);
}

Context::~Context() { fabvdb_ctx_free(ctx_); }

void raise_status(fabvdb_status status, const std::string& message) {
    const int code = int(status);
    PyObject* type = (code >= 1 && code <= 8) ? status_errors[code] : status_errors[0];
    std::string text = message.empty() ? std::string(fabvdb_status_string(status)) : message;
    py::object error = py::reinterpret_steal<py::object>(PyObject_CallFunction(type, "s", text.c_str()));
    if (!error) throw py::error_already_set();
    error.attr("status") = code;
    PyErr_SetObject(type, error.ptr());
    throw py::error_already_set();
}

void raise_invalid(const std::string& message) { raise_status(FABVDB_ERR_INVALID_ARGUMENT, message); }

void run(Context& context, const py::object& progress, const Call& call) {
    if (!progress.is_none() && !PyCallable_Check(progress.ptr())) raise_invalid("progress must be callable or None");
    CallState state{&progress, std::nullopt};
    fabvdb_status status = FABVDB_OK;
    std::string message;
    {
        py::gil_scoped_release release;
        std::lock_guard<std::mutex> lock(context.mutex());
        fabvdb_ctx* ctx = context.get();
        fabvdb_ctx_set_progress(ctx, &progress_adapter, &state);
        status = call(ctx);
        if (status != FABVDB_OK) message = fabvdb_last_error(ctx);
        fabvdb_ctx_set_progress(ctx, nullptr, nullptr);
    }
    if (state.error) throw std::move(*state.error);
    if (status != FABVDB_OK) raise_status(status, message);
}

std::string take_report(fabvdb_report* report) {
    std::string text = report ? fabvdb_report_json(report) : "";
    fabvdb_report_free(report);
    return text;
}

void bind_errors(py::module_& m) {
    struct Kind {
        int code;
        const char* name;
        PyObject* also;  // a built-in base that fits, or NULL
        const char* doc;
    };
    const Kind kinds[] = {
        {1, "InvalidArgumentError", PyExc_ValueError, "A parameter is out of its range, or an array has the wrong shape."},
        {2, "FileError", nullptr, "A file could not be opened, read, written or renamed."},
        {3, "BadInputError", PyExc_ValueError,
         "The input is malformed or cannot be processed (the message names the defect)."},
        {4, "OutOfBudgetError", nullptr, "The operation would exceed the context's memory budget."},
        {5, "OutOfMemoryError", PyExc_MemoryError, "Memory allocation failed."},
        {6, "CancelledError", nullptr, "The progress callback or Context.cancel() cancelled the call."},
        {7, "InternalError", nullptr, "A bug or an unexpected library failure."},
        {8, "NotFoundError", PyExc_LookupError, "A key or item asked for does not exist."},
    };
    PyObject* base = PyErr_NewExceptionWithDoc(
        "fabvdb.Error",
        "A fabvdb call failed. str(error) is the library's message; error.status is its fabvdb_status code.",
        PyExc_Exception, nullptr);
    if (!base) throw py::error_already_set();
    status_errors[0] = base;
    m.attr("Error") = py::handle(base);
    for (const Kind& kind : kinds) {
        py::tuple bases = kind.also ? py::make_tuple(py::handle(base), py::handle(kind.also))
                                    : py::make_tuple(py::handle(base));
        std::string name = std::string("fabvdb.") + kind.name;
        PyObject* type = PyErr_NewExceptionWithDoc(name.c_str(), kind.doc, bases.ptr(), nullptr);
        if (!type) throw py::error_already_set();
        status_errors[kind.code] = type;
        m.attr(kind.name) = py::handle(type);
    }
}

void bind_context(py::module_& m) {
    py::class_<Context, std::shared_ptr<Context>>(m, "Context",
                        "A library context: worker threads, memory budget, cancellation. One call at a time "
                        "runs on a context (others wait); cancel() is safe from any thread.")
        .def(py::init<int, uint64_t>(), py::arg("threads") = 0, py::arg("memory_budget") = 0)
        .def("cancel", &Context::cancel,
             "Cancels the call running on this context (or the next one started); it raises CancelledError.")
        .def_property_readonly("memory_budget", &Context::memory_budget, "The memory budget in force, bytes.")
        .def_property_readonly("threads", &Context::threads, "Worker threads (0: every core).");
}

}  // namespace fabvdb_python
