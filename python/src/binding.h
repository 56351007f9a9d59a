// binding.h — what the pieces of the Python extension `fabvdb._fabvdb` share:
// the Context (a fabvdb_ctx used by one call at a time), run() (a C API call
// made without the GIL, with progress, Ctrl-C and statuses turned into Python
// exceptions), and the Mesh and Volume handles. Binds fabvdb.h only.
// Copyright (C) 2026 the fabvdb developers. GPL-3.0-or-later.
#ifndef FABVDB_PYTHON_BINDING_H
#define FABVDB_PYTHON_BINDING_H

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "fabvdb.h"

namespace fabvdb_python {

namespace py = pybind11;

// A library context. Calls on one Context are serialised by its mutex (the C
// API allows one thread at a time); cancel() is safe from any thread.
class Context {
public:
    Context(int threads, uint64_t memory_budget);
    ~Context();
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;
    void cancel() { fabvdb_ctx_cancel(ctx_); }
    uint64_t memory_budget() const { return fabvdb_ctx_memory_budget(ctx_); }
    int threads() const { return threads_; }
    fabvdb_ctx* get() { return ctx_; }
    std::mutex& mutex() { return mutex_; }

private:
    fabvdb_ctx* ctx_ = nullptr;
    int threads_ = 0;
    std::mutex mutex_;
};

// Raises the Python exception of `status` (fabvdb.Error's subclass) with `message`.
[[noreturn]] void raise_status(fabvdb_status status, const std::string& message);
// Raises fabvdb.InvalidArgumentError with `message` (checks made before a call).
[[noreturn]] void raise_invalid(const std::string& message);

// The call behind run(): the C API call to make on the given context.
using Call = std::function<fabvdb_status(fabvdb_ctx*)>;
// Makes `call` on context with the GIL released. The progress callback
// (None, or callable(stage: str, fraction: float) returning a truthy value to
// cancel) is called with the GIL held from the calling thread; on the main
// thread pending signals are run there too, so Ctrl-C cancels the call and
// KeyboardInterrupt is raised once it has returned. An exception raised by the
// callback cancels the call and is raised again. Any other failure raises the
// status's exception with the library's message.
void run(Context& context, const py::object& progress, const Call& call);

// An immutable triangle mesh owned by Python.
struct Mesh {
    explicit Mesh(fabvdb_mesh* handle) : handle(handle) {}
    ~Mesh() { fabvdb_mesh_free(handle); }
    Mesh(const Mesh&) = delete;
    Mesh& operator=(const Mesh&) = delete;
    fabvdb_mesh* handle;
};

// A narrow-band level set owned by Python.
struct Volume {
    explicit Volume(fabvdb_volume* handle) : handle(handle) {}
    ~Volume() { fabvdb_volume_free(handle); }
    Volume(const Volume&) = delete;
    Volume& operator=(const Volume&) = delete;
    fabvdb_volume* handle;
};

// A new (count, columns) array (1 column: (count,)) holding a copy of data.
template <class T>
py::array_t<T> copy_array(const T* data, size_t count, size_t columns) {
    std::vector<py::ssize_t> shape{py::ssize_t(count)};
    if (columns > 1) shape.push_back(py::ssize_t(columns));
    py::array_t<T> a(shape);
    if (count) std::copy(data, data + count * columns, a.mutable_data());
    return a;
}

// A report's JSON text, then freed (the Python layer parses it into a dict).
std::string take_report(fabvdb_report* report);

// Decomposition options from/to a dict keyed by the C struct's field names
// ("solid" for FABVDB_DECOMPOSE_SOLID); an unknown key is InvalidArgumentError.
fabvdb_decompose_options decompose_options_from(const py::dict& dict);
py::dict decompose_options_to(const fabvdb_decompose_options& options);

// The module's parts, each defined in its own file.
void bind_errors(py::module_& m);
void bind_context(py::module_& m);
void bind_mesh(py::module_& m);
void bind_commands(py::module_& m);
void bind_session(py::module_& m);

}  // namespace fabvdb_python

#endif
