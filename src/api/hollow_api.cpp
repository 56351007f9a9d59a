//! C API: hollowing (fabvdb hollow) of meshes and level sets, and its report.
#include <algorithm>
#include <cstring>
#include <memory>

#include "api/fidelity_report.h"
#include "api/guard.h"
#include "api/options.h"
#include "api/volume_handle.h"
#include "core/stage_clock.h"
#include "volume/extract_mesh.h"
#include "volume/hollow.h"

namespace {

using fabvdb::volume::HollowOptions;
using fabvdb::volume::HollowResult;

//! The core's options; `name` is what messages call the input.
HollowOptions core_options(const fabvdb_hollow_options* opts, const fabvdb::Mesh& mesh, const std::string& name,
                           fabvdb_ctx* ctx) {
    const fabvdb_hollow_options given =
        fabvdb::api::options_from(opts, fabvdb_hollow_options_init, "fabvdb_hollow_options");
    HollowOptions options;
    options.wall = given.wall;
    options.closing = given.closing;
    options.voxel_size = given.voxel_size;
    if (given.resolution < 0) throw fabvdb::Error(FABVDB_ERR_INVALID_ARGUMENT, "resolution must be >= 0");
    if (given.voxel_size == 0.0 && given.resolution > 0) {
        const fabvdb::BoundingBox box = fabvdb::bounding_box(mesh);
        const double longest =
            std::max({box.max[0] - box.min[0], box.max[1] - box.min[1], box.max[2] - box.min[2]});
        options.voxel_size = longest / given.resolution;
    }
    options.adaptivity = given.adaptivity;
    options.min_cavity_volume = given.min_cavity_volume;
    options.infill.cell = given.infill_cell;
    options.infill.strut = given.infill_strut;
    options.memory_budget_bytes = ctx->budget_bytes();
    options.input_name = name;
    return options;
}

nlohmann::json report_of(const HollowResult& result, const HollowOptions& options, double seconds) {
    nlohmann::json report;
    report["voxel_size"] = result.voxel_size;
    report["wall"] = options.wall;
    report["closing"] = options.closing;
    report["adaptivity"] = options.adaptivity;
    report["min_cavity_volume"] = options.min_cavity_volume;
    report["outer_surface"] = result.outer_surface;
    if (result.outer_surface == "repaired") report["outer_surface_voxel"] = result.outer_surface_voxel;
    report["fidelity"] = result.outer_surface == "input"
                             ? fabvdb::api::fidelity_report_kept()
                             : fabvdb::api::fidelity_report(result.fidelity, result.fidelity_limits);
    report["volume_solid"] = result.volume_solid;
    report["volume_shell"] = result.volume_shell;
    report["material_saved_fraction"] =
        result.volume_solid > 0.0 ? 1.0 - result.volume_shell / result.volume_solid : 0.0;
    report["cavity_count"] = result.cavity_volumes.size();
    report["cavities"] = nlohmann::json::array();
    for (double v : result.cavity_volumes) report["cavities"].push_back({{"volume", v}});
    report["filled_cavities"] = nlohmann::json::array();
    for (double v : result.filled_cavity_volumes) report["filled_cavities"].push_back({{"volume", v}});
    report["min_wall_at_vertices"] =
        result.cavity_volumes.empty() ? nlohmann::json() : nlohmann::json(result.min_wall_at_vertices);
    if (options.infill.cell > 0.0)
        report["infill"] = {{"pattern", "gyroid"}, {"cell", options.infill.cell}, {"strut", options.infill.strut}};
    report["output_vertices"] = result.mesh.vertices.size();
    report["output_triangles"] = result.mesh.triangles.size();
    report["timings"] = result.timings;
    report["timings"]["total"] = seconds;
    report["warnings"] = result.warnings;
    return report;
}

//! Runs the hollowing and hands out the report if asked for.
HollowResult run_hollow(const fabvdb::Mesh& mesh, const HollowOptions& options, fabvdb::Progress& progress,
                        nlohmann::json* report) {
    const auto start = std::chrono::steady_clock::now();
    HollowResult result = fabvdb::volume::hollow(mesh, options, progress);
    if (report)
        *report = report_of(result, options, fabvdb::seconds_since(start));
    return result;
}

}  // namespace

extern "C" {

void fabvdb_hollow_options_init(fabvdb_hollow_options* options) {
    if (!options) return;
    *options = fabvdb_hollow_options{};
    options->struct_size = sizeof(fabvdb_hollow_options);
    options->wall = 3.0;
    options->closing = 0.0;
    options->voxel_size = 0.0;
    options->resolution = 0;
    options->adaptivity = 0.0;
    options->min_cavity_volume = 0.0;
    options->infill_cell = 0.0;
    options->infill_strut = 1.2;
}

fabvdb_status fabvdb_mesh_hollow(fabvdb_ctx* ctx, const fabvdb_mesh* mesh, const fabvdb_hollow_options* opts,
                                 fabvdb_mesh** out_mesh, fabvdb_report** out_report) {
    return fabvdb::api::guard(ctx, [&] {
        fabvdb::api::require(mesh, "mesh");
        fabvdb::api::require(out_mesh, "out_mesh");
        const HollowOptions options = core_options(opts, mesh->mesh, mesh->name, ctx);
        fabvdb::Progress progress = ctx->make_progress();
        nlohmann::json report;
        HollowResult result = run_hollow(mesh->mesh, options, progress, out_report ? &report : nullptr);
        fabvdb_mesh* handle = fabvdb::api::new_mesh_handle(std::move(result.mesh), true);
        if (out_report) *out_report = fabvdb::api::new_report_handle(std::move(report));
        *out_mesh = handle;
    });
}

fabvdb_status fabvdb_mesh_hollow_volume(fabvdb_ctx* ctx, const fabvdb_mesh* mesh, const fabvdb_hollow_options* opts,
                                        fabvdb_volume** out_shell, fabvdb_report** out_report) {
    return fabvdb::api::guard(ctx, [&] {
        fabvdb::api::require(mesh, "mesh");
        fabvdb::api::require(out_shell, "out_shell");
        const HollowOptions options = core_options(opts, mesh->mesh, mesh->name, ctx);
        fabvdb::Progress progress = ctx->make_progress();
        nlohmann::json report;
        const HollowResult result = run_hollow(mesh->mesh, options, progress, out_report ? &report : nullptr);
        auto shell = std::make_unique<fabvdb_volume>();
        shell->grid = fabvdb::volume::shell_level_set(result.mesh, result.voxel_size, progress);
        shell->name = mesh->name;
        if (out_report) *out_report = fabvdb::api::new_report_handle(std::move(report));
        *out_shell = shell.release();
    });
}

fabvdb_status fabvdb_volume_hollow(fabvdb_ctx* ctx, const fabvdb_volume* solid, const fabvdb_hollow_options* opts,
                                   fabvdb_volume** out_shell, fabvdb_report** out_report) {
    return fabvdb::api::guard(ctx, [&] {
        fabvdb::api::require(solid, "solid");
        fabvdb::api::require(solid->grid.get(), "solid grid");
        fabvdb::api::require(out_shell, "out_shell");
        fabvdb::Progress progress = ctx->make_progress();
        const fabvdb::Mesh outer = fabvdb::volume::extract_mesh(*solid->grid, 0.0, progress);
        HollowOptions options = core_options(opts, outer, solid->name, ctx);
        options.voxel_size = solid->grid->voxelSize()[0];
        nlohmann::json report;
        const HollowResult result = run_hollow(outer, options, progress, out_report ? &report : nullptr);
        auto shell = std::make_unique<fabvdb_volume>();
        shell->grid = fabvdb::volume::shell_level_set(result.mesh, result.voxel_size, progress);
        shell->name = solid->name;
        if (out_report) *out_report = fabvdb::api::new_report_handle(std::move(report));
        *out_shell = shell.release();
    });
}

}  // extern "C"
