// session.cpp — fabvdb._Decomposition, a decomposition session (the studio's
// handle): made from a mesh or a decomposition.json, changed by the four edits
// and re-runs, undo/redo, with its arrays (S_low, labels, sides, heat map,
// draft map, lines) copied out as numpy arrays. Each call is atomic (the C API's
// guarantee) and runs without the GIL. Binds fabvdb.h only.
// Copyright (C) 2026 the fabvdb developers. GPL-3.0-or-later.
#include <algorithm>

#include "binding.h"

namespace fabvdb_python {

namespace {

struct Session {
    std::shared_ptr<Context> context;
    fabvdb_decomposition* handle = nullptr;
    ~Session() { fabvdb_decomposition_free(handle); }
};

std::unique_ptr<Session> session_new(std::shared_ptr<Context> context, const Mesh& mesh, const py::dict& options,
                                     const py::object& progress) {
    const fabvdb_decompose_options o = decompose_options_from(options);
    auto session = std::make_unique<Session>();
    session->context = context;
    run(*context, progress,
        [&](fabvdb_ctx* ctx) { return fabvdb_decomposition_new(ctx, mesh.handle, &o, &session->handle); });
    return session;
}

std::unique_ptr<Session> session_read(std::shared_ptr<Context> context, const Mesh& mesh, const std::string& path,
                                      const py::object& progress) {
    auto session = std::make_unique<Session>();
    session->context = context;
    run(*context, progress, [&](fabvdb_ctx* ctx) {
        return fabvdb_decomposition_read(ctx, mesh.handle, path.c_str(), &session->handle);
    });
    return session;
}

void apply(Session& s, int type, const py::object& points_in, double radius, bool closed,
           const py::object& progress) {
    auto points = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(points_in);
    if (!points || (points.size() && (points.ndim() != 2 || points.shape(1) != 3)))
        raise_invalid("points must be an (k, 3) array of positions (mm)");
    fabvdb_edit edit;
    fabvdb_edit_init(&edit);
    edit.type = fabvdb_edit_type(type);
    edit.points = points.size() ? points.data() : nullptr;
    edit.point_count = size_t(points.size() / 3);
    edit.radius = radius;
    edit.flags = closed ? FABVDB_EDIT_CLOSED : 0u;
    run(*s.context, progress, [&](fabvdb_ctx* ctx) { return fabvdb_decomposition_apply(ctx, s.handle, &edit); });
}

py::dict info(Session& s) {
    fabvdb_decomposition_info i;
    fabvdb_decomposition_info_init(&i);
    run(*s.context, py::none(), [&](fabvdb_ctx* ctx) { return fabvdb_decomposition_get_info(ctx, s.handle, &i); });
    py::dict d;
    d["part_count"] = i.part_count;
    d["total_energy"] = i.total_energy;
    d["gamma"] = i.gamma;
    d["over_gamma"] = bool(i.over_gamma);
    d["draft_degrees"] = i.draft_degrees;
    d["undo_steps"] = i.undo_steps;
    d["redo_steps"] = i.redo_steps;
    d["edit_count"] = i.edit_count;
    d["last_step_seconds"] = i.last_step_seconds;
    return d;
}

py::dict part(Session& s, size_t index) {
    fabvdb_part_info p;
    fabvdb_part_info_init(&p);
    run(*s.context, py::none(),
        [&](fabvdb_ctx* ctx) { return fabvdb_decomposition_get_part(ctx, s.handle, index, &p); });
    py::dict d;
    d["direction"] = py::make_tuple(p.direction[0], p.direction[1], p.direction[2]);
    d["energy"] = p.energy;
    d["overhang_energy"] = p.overhang_energy;
    d["overlap_energy"] = p.overlap_energy;
    d["area"] = p.area;
    d["triangle_count"] = p.triangle_count;
    return d;
}

py::tuple lines(Session& s, int kind) {
    const double* points = nullptr;
    const size_t* starts = nullptr;
    const int32_t* parts = nullptr;
    size_t point_count = 0, line_count = 0;
    run(*s.context, py::none(), [&](fabvdb_ctx* ctx) {
        return fabvdb_decomposition_lines(ctx, s.handle, kind, &points, &point_count, &starts, &parts, &line_count);
    });
    py::array_t<double> p = copy_array(points, point_count, 3);
    if (!point_count) p = py::array_t<double>(std::vector<py::ssize_t>{0, 3});
    std::vector<uint64_t> offsets(starts, starts + (line_count + 1));
    return py::make_tuple(p, copy_array(offsets.data(), offsets.size(), 1), copy_array(parts, line_count, 1));
}

}  // namespace

void bind_session(py::module_& m) {
    py::class_<Session>(m, "_Decomposition")
        .def(py::init(&session_new))
        .def_static("read", &session_read)
        .def("apply", &apply)
        .def("apply_json",
             [](Session& s, const std::string& text, const py::object& progress) {
                 run(*s.context, progress,
                     [&](fabvdb_ctx* ctx) { return fabvdb_decomposition_apply_json(ctx, s.handle, text.c_str()); });
             })
        .def("rerun",
             [](Session& s, const py::dict& options, const py::object& progress) {
                 const fabvdb_decompose_options o = decompose_options_from(options);
                 run(*s.context, progress,
                     [&](fabvdb_ctx* ctx) { return fabvdb_decomposition_rerun(ctx, s.handle, &o); });
             })
        .def("options",
             [](Session& s) {
                 fabvdb_decompose_options o;
                 fabvdb_decompose_options_init(&o);
                 run(*s.context, py::none(),
                     [&](fabvdb_ctx* ctx) { return fabvdb_decomposition_get_options(ctx, s.handle, &o); });
                 return decompose_options_to(o);
             })
        .def("undo",
             [](Session& s) {
                 run(*s.context, py::none(), [&](fabvdb_ctx* ctx) { return fabvdb_decomposition_undo(ctx, s.handle); });
             })
        .def("redo",
             [](Session& s) {
                 run(*s.context, py::none(), [&](fabvdb_ctx* ctx) { return fabvdb_decomposition_redo(ctx, s.handle); });
             })
        .def("info", &info)
        .def("part", &part)
        .def("vertices",
             [](Session& s) {
                 return copy_array(fabvdb_decomposition_vertices(s.handle), fabvdb_decomposition_vertex_count(s.handle), 3);
             })
        .def("triangles",
             [](Session& s) {
                 return copy_array(fabvdb_decomposition_triangles(s.handle),
                                   fabvdb_decomposition_triangle_count(s.handle), 3);
             })
        .def("labels",
             [](Session& s) {
                 return copy_array(fabvdb_decomposition_labels(s.handle), fabvdb_decomposition_triangle_count(s.handle),
                                   1);
             })
        .def("sides",
             [](Session& s) {
                 return copy_array(fabvdb_decomposition_sides(s.handle), fabvdb_decomposition_triangle_count(s.handle),
                                   1);
             })
        .def("deformation",
             [](Session& s) {
                 return copy_array(fabvdb_decomposition_deformation(s.handle),
                                   fabvdb_decomposition_triangle_count(s.handle), 1);
             })
        .def("lines", &lines)
        .def("draft_map",
             [](Session& s, double x, double y, double z, double draft_degrees) {
                 const double direction[3] = {x, y, z};
                 py::array_t<uint8_t> out(py::ssize_t(fabvdb_decomposition_triangle_count(s.handle)));
                 uint8_t* data = out.mutable_data();
                 run(*s.context, py::none(), [&](fabvdb_ctx* ctx) {
                     return fabvdb_decomposition_draft_map(ctx, s.handle, direction, draft_degrees, data);
                 });
                 return out;
             })
        .def("write",
             [](Session& s, const std::string& out_dir) {
                 run(*s.context, py::none(),
                     [&](fabvdb_ctx* ctx) { return fabvdb_decomposition_write(ctx, s.handle, out_dir.c_str()); });
             })
        .def("write_edits", [](Session& s, const std::string& path) {
            run(*s.context, py::none(),
                [&](fabvdb_ctx* ctx) { return fabvdb_decomposition_write_edits(ctx, s.handle, path.c_str()); });
        });
}

}  // namespace fabvdb_python
