// mesh.cpp — fabvdb.Mesh and fabvdb.Volume: numpy arrays in (any float/int
// dtype, converted once, checked), read-only array views out (no copy: they
// keep the mesh alive), file reading and writing, level sets. Binds fabvdb.h only.
// Copyright (C) 2026 the fabvdb developers. GPL-3.0-or-later.
#include <vector>

#include "binding.h"

namespace fabvdb_python {

namespace {

std::string shape_text(const py::array& a) {
    std::string text = "(";
    for (py::ssize_t i = 0; i < a.ndim(); ++i) text += (i ? ", " : "") + std::to_string(a.shape(i));
    return text + (a.ndim() == 1 ? ",)" : ")");
}

// An (n, 3) array of the given role, or InvalidArgumentError naming the defect.
py::array as_rows_of_three(const py::object& object, const char* role) {
    py::array a = py::array::ensure(object);
    if (!a) raise_invalid(std::string(role) + " must be an array-like of shape (n, 3)");
    const bool empty = a.size() == 0 && (a.ndim() == 1 || (a.ndim() == 2 && a.shape(1) == 3));
    if (!empty && (a.ndim() != 2 || a.shape(1) != 3))
        raise_invalid(std::string(role) + " must have shape (n, 3), got " + shape_text(a));
    return a;
}

std::unique_ptr<Mesh> make_mesh(const py::object& vertices_in, const py::object& triangles_in) {
    py::array vertices = as_rows_of_three(vertices_in, "vertices");
    py::array triangles = as_rows_of_three(triangles_in, "triangles");
    const char vkind = vertices.dtype().kind(), tkind = triangles.dtype().kind();
    if (vertices.size() && vkind != 'f' && vkind != 'i' && vkind != 'u')
        raise_invalid("vertices must be numbers (a float or integer dtype), got dtype " +
                      std::string(py::str(vertices.dtype())));
    if (triangles.size() && tkind != 'i' && tkind != 'u')
        raise_invalid("triangles must be vertex indices (an integer dtype), got dtype " +
                      std::string(py::str(triangles.dtype())));
    // Converted once: a C-contiguous float64 array is used as it is.
    auto v = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(vertices);
    if (!v) throw py::error_already_set();
    const size_t vertex_count = size_t(vertices.size() / 3), triangle_count = size_t(triangles.size() / 3);
    const uint32_t* indices = nullptr;
    std::vector<uint32_t> converted;
    py::array_t<uint32_t, py::array::c_style> direct;
    if (triangles.dtype().is(py::dtype::of<uint32_t>()) && (triangles.flags() & py::array::c_style)) {
        direct = py::reinterpret_borrow<py::array_t<uint32_t, py::array::c_style>>(triangles);
        indices = direct.data();
    } else if (triangle_count) {
        auto t = py::array_t<int64_t, py::array::c_style | py::array::forcecast>::ensure(triangles);
        if (!t) throw py::error_already_set();
        const int64_t* data = t.data();
        converted.resize(3 * triangle_count);
        for (size_t i = 0; i < 3 * triangle_count; ++i) {
            const int64_t index = data[i];
            if (index < 0 || uint64_t(index) >= vertex_count)  // a huge uint64 wraps negative
                raise_status(FABVDB_ERR_BAD_INPUT,
                             "triangles: triangle " + std::to_string(i / 3) + " refers to vertex " +
                                 std::to_string(index) + " but there are " + std::to_string(vertex_count) +
                                 " vertices");
            converted[i] = uint32_t(index);
        }
        indices = converted.data();
    }
    Context context(1, 0);
    fabvdb_mesh* handle = nullptr;
    const double* points = v.data();
    run(context, py::none(), [&](fabvdb_ctx* ctx) {
        return fabvdb_mesh_new(ctx, points, vertex_count, indices, triangle_count, &handle);
    });
    return std::make_unique<Mesh>(handle);
}

// A read-only (count, 3) view of `data`, keeping `owner` alive.
template <class T>
py::array view(const T* data, size_t count, const py::object& owner) {
    py::array_t<T> a({py::ssize_t(count), py::ssize_t(3)}, {py::ssize_t(3 * sizeof(T)), py::ssize_t(sizeof(T))},
                     count ? data : nullptr, owner);
    py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
    return std::move(a);
}

}  // namespace

void bind_mesh(py::module_& m) {
    py::class_<Mesh>(m, "Mesh",
                     "An immutable triangle mesh: vertex positions in millimetres and triangles of three 0-based "
                     "vertex indices.")
        .def(py::init(&make_mesh), py::arg("vertices"), py::arg("triangles"),
             "Makes a mesh from an (n, 3) array of positions (any float or integer dtype) and an (m, 3) array "
             "of vertex indices (any integer dtype). Both are converted once and copied.\n"
             "Raises InvalidArgumentError (wrong shape or dtype) or BadInputError (an index out of range, a "
             "non-finite coordinate).")
        .def_property_readonly(
            "vertices",
            [](py::object self) {
                const Mesh& mesh = self.cast<const Mesh&>();
                return view(fabvdb_mesh_vertices(mesh.handle), fabvdb_mesh_vertex_count(mesh.handle), self);
            },
            "The (n, 3) float64 positions, a read-only view (no copy).")
        .def_property_readonly(
            "triangles",
            [](py::object self) {
                const Mesh& mesh = self.cast<const Mesh&>();
                return view(fabvdb_mesh_triangles(mesh.handle), fabvdb_mesh_triangle_count(mesh.handle), self);
            },
            "The (m, 3) uint32 vertex indices, a read-only view (no copy).")
        .def_property_readonly("vertex_count", [](const Mesh& mesh) { return fabvdb_mesh_vertex_count(mesh.handle); })
        .def_property_readonly("triangle_count",
                               [](const Mesh& mesh) { return fabvdb_mesh_triangle_count(mesh.handle); });

    m.def(
        "_read_mesh",
        [](Context& context, const std::string& path, const py::object& progress) {
            fabvdb_mesh* handle = nullptr;
            run(context, progress, [&](fabvdb_ctx* ctx) { return fabvdb_mesh_read(ctx, path.c_str(), &handle); });
            return std::make_unique<Mesh>(handle);
        },
        py::arg("context"), py::arg("path"), py::arg("progress"));
    m.def("_write_mesh", [](Context& context, const Mesh& mesh, const std::string& path) {
        run(context, py::none(), [&](fabvdb_ctx* ctx) { return fabvdb_mesh_write(ctx, mesh.handle, path.c_str()); });
    });
    m.def("_scale_mesh", [](Context& context, const Mesh& mesh, double factor) {
        fabvdb_mesh* handle = nullptr;
        run(context, py::none(), [&](fabvdb_ctx* ctx) { return fabvdb_mesh_scale(ctx, mesh.handle, factor, &handle); });
        return std::make_unique<Mesh>(handle);
    });

    py::class_<Volume>(m, "Volume",
                       "A solid as a sparse narrow-band signed distance field (OpenVDB, negative inside, mm).")
        .def_property_readonly("voxel_size", [](const Volume& v) { return fabvdb_volume_voxel_size(v.handle); },
                               "The voxel edge length, mm.");
    m.def("_read_volume", [](Context& context, const std::string& path) {
        fabvdb_volume* handle = nullptr;
        run(context, py::none(), [&](fabvdb_ctx* ctx) { return fabvdb_volume_read(ctx, path.c_str(), &handle); });
        return std::make_unique<Volume>(handle);
    });
    m.def("_write_volume", [](Context& context, const Volume& volume, const std::string& path) {
        run(context, py::none(),
            [&](fabvdb_ctx* ctx) { return fabvdb_volume_write(ctx, volume.handle, path.c_str()); });
    });
}

}  // namespace fabvdb_python
