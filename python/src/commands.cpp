// commands.cpp — the library's operations for the Python layer: inspect,
// check, repair, level sets, hollow, drain, powder simulation, decompose, mold. Each
// takes a Context, its inputs and its options as a dict keyed by the C
// struct's field names (the Python layer maps the CLI's names and units onto
// them), and returns the result and the report's JSON text. An unknown option
// is InvalidArgumentError. Binds fabvdb.h only.
// Copyright (C) 2026 the fabvdb developers. GPL-3.0-or-later.
#include <set>
#include <tuple>
#include <vector>

#include "binding.h"

namespace fabvdb_python {

namespace {

// Reads the options of one struct from a dict, refusing keys it does not know.
class Fields {
public:
    Fields(const py::dict& dict, const char* what) : dict_(dict), what_(what) {}
    template <class T>
    void get(const char* name, T& field) {
        known_.insert(name);
        if (!dict_.contains(name)) return;
        py::object value = dict_[name];
        if (value.is_none()) return;
        try {
            field = value.cast<T>();
        } catch (const py::cast_error&) {
            raise_invalid(std::string(what_) + ": option " + name + " has the wrong type");
        }
    }
    void flag(const char* name, unsigned bit, unsigned& flags) {
        bool on = false;
        get(name, on);
        if (on) flags |= bit;
    }
    // 3*k doubles from an (k, 3) array-like (None or absent: empty).
    void rows(const char* name, std::vector<double>& out) {
        known_.insert(name);
        if (!dict_.contains(name) || dict_[name].is_none()) return;
        auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(dict_[name]);
        if (!a || a.ndim() != 2 || a.shape(1) != 3)
            raise_invalid(std::string(what_) + ": option " + name + " must be an (k, 3) array of directions");
        out.assign(a.data(), a.data() + a.size());
    }
    void done() const {
        for (auto item : dict_) {
            const std::string key = py::str(item.first);
            if (!known_.count(key)) raise_invalid(std::string(what_) + ": unknown option " + key);
        }
    }

private:
    py::dict dict_;
    const char* what_;
    std::set<std::string> known_;
};

fabvdb_volume_options volume_options(const py::dict& dict) {
    fabvdb_volume_options o;
    fabvdb_volume_options_init(&o);
    Fields f(dict, "repair");
    f.get("voxel_size", o.voxel_size);
    f.get("resolution", o.resolution);
    f.get("half_band_voxels", o.half_band_voxels);
    f.get("adaptivity", o.adaptivity);
    f.get("min_shell_volume", o.min_shell_volume);
    f.get("thicken", o.thicken);
    unsigned flags = 0;
    f.flag("no_snap", FABVDB_REPAIR_NO_SNAP, flags);
    f.flag("volumetric", FABVDB_REPAIR_VOLUMETRIC, flags);
    o.flags = flags;
    f.done();
    return o;
}

fabvdb_hollow_options hollow_options(const py::dict& dict) {
    fabvdb_hollow_options o;
    fabvdb_hollow_options_init(&o);
    Fields f(dict, "hollow");
    f.get("wall", o.wall);
    f.get("closing", o.closing);
    f.get("voxel_size", o.voxel_size);
    f.get("resolution", o.resolution);
    f.get("adaptivity", o.adaptivity);
    f.get("min_cavity_volume", o.min_cavity_volume);
    f.get("infill_cell", o.infill_cell);
    f.get("infill_strut", o.infill_strut);
    f.done();
    return o;
}

fabvdb_decompose_options decompose_options(const py::dict& dict, const char* what) {
    fabvdb_decompose_options o;
    fabvdb_decompose_options_init(&o);
    Fields f(dict, what);
    f.flag("solid", FABVDB_DECOMPOSE_SOLID, o.flags);
    f.get("shell_thickness", o.shell_thickness);
    f.get("gamma", o.gamma);
    f.get("parts", o.parts);
    f.get("max_parts", o.max_parts);
    f.get("draft_degrees", o.draft_degrees);
    f.get("w_overhang", o.w_overhang);
    f.get("w_overlap", o.w_overlap);
    f.get("w_coarse_overlap", o.w_coarse_overlap);
    f.get("low_res_triangles", o.low_res_triangles);
    f.get("smoothing_iterations", o.smoothing_iterations);
    f.get("w_smooth", o.w_smooth);
    f.done();
    return o;
}

}  // namespace

fabvdb_decompose_options decompose_options_from(const py::dict& dict) { return decompose_options(dict, "decompose"); }

py::dict decompose_options_to(const fabvdb_decompose_options& o) {
    py::dict d;
    d["solid"] = bool(o.flags & FABVDB_DECOMPOSE_SOLID);
    d["shell_thickness"] = o.shell_thickness;
    d["gamma"] = o.gamma;
    d["parts"] = o.parts;
    d["max_parts"] = o.max_parts;
    d["draft_degrees"] = o.draft_degrees;
    d["w_overhang"] = o.w_overhang;
    d["w_overlap"] = o.w_overlap;
    d["w_coarse_overlap"] = o.w_coarse_overlap;
    d["low_res_triangles"] = o.low_res_triangles;
    d["smoothing_iterations"] = o.smoothing_iterations;
    d["w_smooth"] = o.w_smooth;
    return d;
}

void bind_commands(py::module_& m) {
    m.def("_inspect", [](Context& context, const Mesh& mesh, const py::object& progress) {
        fabvdb_report* report = nullptr;
        run(context, progress, [&](fabvdb_ctx* ctx) { return fabvdb_mesh_inspect(ctx, mesh.handle, &report); });
        return take_report(report);
    });

    m.def("_check", [](Context& context, const Mesh& mesh, const py::dict& options, const py::object& progress) {
        fabvdb_check_options o;
        fabvdb_check_options_init(&o);
        Fields f(options, "check");
        std::string process, thickness_map;
        std::vector<double> up, build_volume;
        f.get("process", process);
        f.rows("up", up);
        f.rows("build_volume", build_volume);
        f.get("voxel_size", o.voxel_size);
        f.get("resolution", o.resolution);
        f.get("thickness_map_path", thickness_map);
        f.done();
        if (!process.empty()) o.process = process.c_str();
        if (up.size() == 3) std::copy(up.begin(), up.end(), o.up);
        if (build_volume.size() == 3) std::copy(build_volume.begin(), build_volume.end(), o.build_volume);
        o.thickness_map_path = thickness_map.empty() ? nullptr : thickness_map.c_str();
        fabvdb_report* report = nullptr;
        run(context, progress, [&](fabvdb_ctx* ctx) { return fabvdb_mesh_check(ctx, mesh.handle, &o, &report); });
        return take_report(report);
    });

    m.def("_repair", [](Context& context, const Mesh& mesh, const py::dict& options, bool want_report,
                        const py::object& progress) {
        const fabvdb_volume_options o = volume_options(options);
        fabvdb_mesh* out = nullptr;
        fabvdb_report* report = nullptr;
        run(context, progress, [&](fabvdb_ctx* ctx) {
            return fabvdb_mesh_repair(ctx, mesh.handle, &o, &out, want_report ? &report : nullptr);
        });
        return std::make_tuple(std::make_unique<Mesh>(out), take_report(report));
    });

    m.def("_volume_from_mesh",
          [](Context& context, const Mesh& mesh, const py::dict& options, const py::object& progress) {
              const fabvdb_volume_options o = volume_options(options);
              fabvdb_volume* out = nullptr;
              fabvdb_report* report = nullptr;
              run(context, progress,
                  [&](fabvdb_ctx* ctx) { return fabvdb_volume_from_mesh(ctx, mesh.handle, &o, &out, &report); });
              return std::make_tuple(std::make_unique<Volume>(out), take_report(report));
          });

    m.def("_volume_to_mesh", [](Context& context, const Volume& volume, double adaptivity, const py::object& progress) {
        fabvdb_volume_options o;
        fabvdb_volume_options_init(&o);
        o.adaptivity = adaptivity;
        fabvdb_mesh* out = nullptr;
        run(context, progress, [&](fabvdb_ctx* ctx) { return fabvdb_volume_to_mesh(ctx, volume.handle, &o, &out); });
        return std::make_unique<Mesh>(out);
    });

    m.def("_hollow", [](Context& context, const Mesh& mesh, const py::dict& options, const py::object& progress) {
        const fabvdb_hollow_options o = hollow_options(options);
        fabvdb_mesh* out = nullptr;
        fabvdb_report* report = nullptr;
        run(context, progress, [&](fabvdb_ctx* ctx) { return fabvdb_mesh_hollow(ctx, mesh.handle, &o, &out, &report); });
        return std::make_tuple(std::make_unique<Mesh>(out), take_report(report));
    });

    m.def("_hollow_volume",
          [](Context& context, const Mesh& mesh, const py::dict& options, const py::object& progress) {
              const fabvdb_hollow_options o = hollow_options(options);
              fabvdb_volume* out = nullptr;
              fabvdb_report* report = nullptr;
              run(context, progress, [&](fabvdb_ctx* ctx) {
                  return fabvdb_mesh_hollow_volume(ctx, mesh.handle, &o, &out, &report);
              });
              return std::make_tuple(std::make_unique<Volume>(out), take_report(report));
          });

    m.def("_volume_hollow",
          [](Context& context, const Volume& solid, const py::dict& options, const py::object& progress) {
              const fabvdb_hollow_options o = hollow_options(options);
              fabvdb_volume* out = nullptr;
              fabvdb_report* report = nullptr;
              run(context, progress,
                  [&](fabvdb_ctx* ctx) { return fabvdb_volume_hollow(ctx, solid.handle, &o, &out, &report); });
              return std::make_tuple(std::make_unique<Volume>(out), take_report(report));
          });

    // With want_heatmap, the heat maps come back as (surface Mesh, drained share, powder left, colours of the
    // share as (n, 3) uint8), copied out of the library's fabvdb_heatmap; None when there is no cavity.
    m.def("_drain", [](Context& context, const Mesh& mesh, const py::dict& options, bool want_heatmap,
                       const py::object& progress) {
        fabvdb_drain_options o;
        fabvdb_drain_options_init(&o);
        Fields f(options, "drain");
        std::vector<double> orientations, first;
        std::string keep_out, heatmap;
        f.get("wall", o.wall);
        f.get("voxel_size", o.voxel_size);
        f.get("hole_count", o.hole_count);
        f.get("hole_diameter", o.hole_diameter);
        f.get("repose_degrees", o.repose_degrees);
        f.get("effort", o.effort);
        f.get("target_residual", o.target_residual);
        f.rows("orientations", orientations);
        f.rows("first_gravity", first);
        f.get("patch_count", o.patch_count);
        f.get("keep_out_path", keep_out);
        f.get("heatmap_path", heatmap);
        f.done();
        if (!orientations.empty()) {
            o.orientations = orientations.data();
            o.orientation_count = orientations.size() / 3;
        }
        if (first.size() == 3) std::copy(first.begin(), first.end(), o.first_gravity);
        o.keep_out_path = keep_out.empty() ? nullptr : keep_out.c_str();
        o.heatmap_path = heatmap.empty() ? nullptr : heatmap.c_str();
        fabvdb_mesh* out = nullptr;
        fabvdb_report* report = nullptr;
        fabvdb_heatmap* heat = nullptr;
        run(context, progress, [&](fabvdb_ctx* ctx) {
            return want_heatmap ? fabvdb_mesh_drain_heatmap(ctx, mesh.handle, &o, &out, &report, &heat)
                                : fabvdb_mesh_drain(ctx, mesh.handle, &o, &out, &report);
        });
        std::unique_ptr<fabvdb_heatmap, void (*)(fabvdb_heatmap*)> heat_owner(heat, fabvdb_heatmap_free);
        py::object drilled = py::cast(std::make_unique<Mesh>(out));
        const std::string text = take_report(report);
        py::object heat_maps = py::none();
        if (heat) {
            const fabvdb_mesh* cavity = fabvdb_heatmap_surface(heat);
            const size_t n = fabvdb_mesh_vertex_count(cavity);
            fabvdb_mesh* surface = nullptr;
            run(context, py::none(), [&](fabvdb_ctx* ctx) {
                return fabvdb_mesh_new(ctx, fabvdb_mesh_vertices(cavity), n, fabvdb_mesh_triangles(cavity),
                                       fabvdb_mesh_triangle_count(cavity), &surface);
            });
            heat_maps = py::make_tuple(py::cast(std::make_unique<Mesh>(surface)),
                                       copy_array(fabvdb_heatmap_values(heat, FABVDB_HEATMAP_DRAINED), n, 1),
                                       copy_array(fabvdb_heatmap_values(heat, FABVDB_HEATMAP_LEFT), n, 1),
                                       copy_array(fabvdb_heatmap_colours(heat, FABVDB_HEATMAP_DRAINED), n, 3));
        }
        return py::make_tuple(drilled, text, heat_maps);
    });

    m.def("_powder_simulate", [](Context& context, const Mesh& part, const std::string& holes_json,
                                 const py::dict& options, const py::object& progress) {
        fabvdb_powder_options o;
        fabvdb_powder_options_init(&o);
        Fields f(options, "powder_sim");
        std::vector<double> orientations, first;
        std::string routine;
        f.get("voxel_size", o.voxel_size);
        f.get("repose_degrees", o.repose_degrees);
        f.rows("orientations", orientations);
        f.rows("first_gravity", first);
        f.get("turns", o.turns);
        f.get("seed", o.seed);
        f.get("slope_window", o.slope_window);
        f.get("routine_json", routine);
        f.done();
        if (!orientations.empty()) {
            o.orientations = orientations.data();
            o.orientation_count = orientations.size() / 3;
        }
        if (first.size() == 3) std::copy(first.begin(), first.end(), o.first_gravity);
        o.routine_json = routine.empty() ? nullptr : routine.c_str();
        fabvdb_report* report = nullptr;
        run(context, progress, [&](fabvdb_ctx* ctx) {
            return fabvdb_powder_simulate(ctx, part.handle, holes_json.c_str(), &o, &report);
        });
        return take_report(report);
    });

    m.def("_decompose", [](Context& context, const Mesh& mesh, const py::dict& options, const py::object& edits_path,
                           const std::string& out_dir, const py::object& progress) {
        const fabvdb_decompose_options o = decompose_options(options, "decompose");
        std::string edits = edits_path.is_none() ? "" : edits_path.cast<std::string>();
        fabvdb_report* report = nullptr;
        run(context, progress, [&](fabvdb_ctx* ctx) {
            return fabvdb_mesh_decompose(ctx, mesh.handle, &o, edits.empty() ? nullptr : edits.c_str(),
                                         out_dir.c_str(), &report);
        });
        return take_report(report);
    });

    m.def("_mold", [](Context& context, const Mesh& mesh, const py::object& decomposition_path,
                      const py::dict& decompose, const py::dict& options, const std::string& out_dir,
                      const py::object& progress) {
        const fabvdb_decompose_options d = decompose_options(decompose, "mold");
        fabvdb_mold_options o;
        fabvdb_mold_options_init(&o);
        Fields f(options, "mold");
        f.flag("common", FABVDB_MOLD_COMMON, o.flags);
        f.get("margin", o.margin);
        f.get("voxel_size", o.voxel_size);
        f.get("grid_step", o.grid_step);
        f.get("density", o.density);
        f.done();
        std::string path = decomposition_path.is_none() ? "" : decomposition_path.cast<std::string>();
        fabvdb_report* report = nullptr;
        run(context, progress, [&](fabvdb_ctx* ctx) {
            return fabvdb_mesh_mold(ctx, mesh.handle, path.empty() ? nullptr : path.c_str(), &d, &o, out_dir.c_str(),
                                    &report);
        });
        return take_report(report);
    });
}

}  // namespace fabvdb_python
