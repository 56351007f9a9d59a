//! C API: volume handles (level sets) — robust conversion from meshes
//! (`fabvdb repair`), extraction, .vdb files.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <string>

#include <openvdb/io/File.h>

#include "api/fidelity_report.h"
#include "api/guard.h"
#include "api/options.h"
#include "api/volume_handle.h"
#include "core/atomic_output.h"
#include "core/float_coordinates.h"
#include "core/stage_clock.h"
#include "surface/float_rounding.h"
#include "surface/inspect.h"
#include "surface/mesh_repair.h"
#include "volume/extract_mesh.h"
#include "volume/faithful_repair.h"
#include "volume/input_fidelity.h"
#include "volume/level_set_volume.h"
#include "volume/mesh_shells.h"
#include "volume/repair.h"

namespace {

//! Halvings of the automatic voxel a volumetric repair that lost the model
//! gets (faithful_repair.h): 0.15 mm becomes at most 0.0375 mm.
constexpr int kRepairRefinements = 2;

fabvdb_volume_options options_or_defaults(const fabvdb_volume_options* options) {
    return fabvdb::api::options_from(options, fabvdb_volume_options_init, "fabvdb_volume_options");
}

fabvdb::volume::RepairOptions repair_options(const fabvdb_ctx* ctx, const fabvdb_mesh& mesh,
                                             const fabvdb_volume_options& options) {
    if (options.voxel_size < 0.0 || !std::isfinite(options.voxel_size))
        throw fabvdb::Error(FABVDB_ERR_INVALID_ARGUMENT, "voxel_size must be >= 0");
    if (!(options.adaptivity >= 0.0 && options.adaptivity <= 1.0))
        throw fabvdb::Error(FABVDB_ERR_INVALID_ARGUMENT, "adaptivity must be in [0, 1]");
    if (!(options.min_shell_volume >= 0.0))
        throw fabvdb::Error(FABVDB_ERR_INVALID_ARGUMENT, "min_shell_volume must be >= 0");
    if (!(options.thicken >= 0.0)) throw fabvdb::Error(FABVDB_ERR_INVALID_ARGUMENT, "thicken must be >= 0");
    fabvdb::volume::RepairOptions repair;
    repair.distance.voxel_size =
        options.voxel_size > 0.0 ? options.voxel_size
                                 : fabvdb::volume::voxel_size_for_resolution(mesh.mesh, options.resolution, mesh.name);
    repair.distance.input_name = mesh.name;
    repair.distance.half_band_voxels = options.half_band_voxels;
    repair.distance.memory_budget_bytes = ctx->budget_bytes();
    repair.distance.thicken = options.thicken;
    repair.adaptivity = options.adaptivity;
    repair.min_shell_volume = options.min_shell_volume;
    repair.snap = !(options.flags & FABVDB_REPAIR_NO_SNAP);
    return repair;
}

//! The report's figures; `timings` gets the stages' seconds and `total`.
nlohmann::json repair_report(const fabvdb::volume::RepairResult& result, double total_seconds) {
    nlohmann::json report;
    report["voxel_size"] = result.grid->voxelSize()[0];
    report["active_voxels"] = result.distance.active_voxels;
    report["estimated_bytes"] = result.distance.estimated_bytes;
    report["rebuilt"] = result.distance.rebuilt;
    report["thickened"] = result.distance.thickened;
    report["enclosed_share"] = result.distance.enclosed_share;
    report["shells_kept"] = result.shells_kept;
    report["shells_dropped"] = result.shells_dropped;
    report["timings"] = result.distance.timings;
    report["timings"]["total"] = total_seconds;
    return report;
}

}  // namespace

extern "C" {

void fabvdb_volume_free(fabvdb_volume* volume) { delete volume; }

void fabvdb_volume_options_init(fabvdb_volume_options* options) {
    if (!options) return;
    *options = fabvdb_volume_options{};
    options->struct_size = sizeof(fabvdb_volume_options);
    options->voxel_size = 0.0;
    options->resolution = 400;
    options->half_band_voxels = 3;
    options->adaptivity = 0.0;
    options->min_shell_volume = 0.0;
    options->thicken = 0.0;
    options->flags = 0;
}

fabvdb_status fabvdb_volume_from_mesh(fabvdb_ctx* ctx, const fabvdb_mesh* mesh, const fabvdb_volume_options* options,
                                      fabvdb_volume** out, fabvdb_report** report) {
    return fabvdb::api::guard(ctx, [&] {
        fabvdb::api::require(mesh, "mesh");
        fabvdb::api::require(out, "out");
        std::map<std::string, double> stages;
        const fabvdb::StageClock clock(stages);
        fabvdb::volume::RepairOptions repair = repair_options(ctx, *mesh, options_or_defaults(options));
        repair.extract = false;
        fabvdb::Progress progress = ctx->make_progress();
        fabvdb::volume::RepairResult result = fabvdb::volume::repair(mesh->mesh, repair, progress);
        nlohmann::json document = repair_report(result, clock.total());
        document["volume"] = fabvdb::volume::level_set_volume(*result.grid);
        auto volume = std::make_unique<fabvdb_volume>();
        volume->grid = result.grid;
        volume->name = mesh->name;
        if (report) *report = fabvdb::api::new_report_handle(std::move(document));
        *out = volume.release();
    });
}

fabvdb_status fabvdb_volume_to_mesh(fabvdb_ctx* ctx, const fabvdb_volume* volume, const fabvdb_volume_options* options,
                                    fabvdb_mesh** out) {
    return fabvdb::api::guard(ctx, [&] {
        fabvdb::api::require(volume, "volume");
        fabvdb::api::require(out, "out");
        const fabvdb_volume_options chosen = options_or_defaults(options);
        fabvdb::Progress progress = ctx->make_progress();
        *out = fabvdb::api::new_mesh_handle(fabvdb::volume::extract_mesh(*volume->grid, chosen.adaptivity, progress),
                                            true);
    });
}

fabvdb_status fabvdb_mesh_repair(fabvdb_ctx* ctx, const fabvdb_mesh* mesh, const fabvdb_volume_options* options,
                                 fabvdb_mesh** out, fabvdb_report** report) {
    return fabvdb::api::guard(ctx, [&] {
        fabvdb::api::require(mesh, "mesh");
        fabvdb::api::require(out, "out");
        std::map<std::string, double> stages;
        fabvdb::StageClock clock(stages);
        const fabvdb_volume_options chosen = options_or_defaults(options);
        fabvdb::volume::RepairOptions repair = repair_options(ctx, *mesh, chosen);
        fabvdb::Progress progress = ctx->make_progress();
        nlohmann::json input;
        if (report) input = fabvdb::surface::inspect_mesh(mesh->mesh, progress);
        const double inspect_seconds = clock.lap("inspect input");
        // Mesh level first, unless asked for voxels or what only voxels do
        // (thicken a sheet, drop small shells).
        const bool volumetric = (chosen.flags & FABVDB_REPAIR_VOLUMETRIC) || repair.distance.thicken > 0.0 ||
                                repair.min_shell_volume > 0.0;
        std::optional<fabvdb::surface::MeshRepair> fixed;
        fabvdb::Mesh oriented;  // the input oriented, when the mesh level did so and failed
        if (!volumetric) fixed = fabvdb::surface::repair_at_mesh_level(mesh->mesh, progress, &oriented);
        nlohmann::json rest_report;
        if (fixed && !fixed->rest.triangles.empty()) {
            // Some shells need voxels: those alone, then united with the others.
            std::optional<fabvdb::Mesh> united;
            try {
                std::map<std::string, double> rest_stages;
                const fabvdb::StageClock rest_clock(rest_stages);
                fabvdb::volume::RepairResult rest = fabvdb::volume::repair(fixed->rest, repair, progress);
                rest_report = repair_report(rest, rest_clock.total());
                united = fabvdb::surface::unite_shells(fixed->mesh, rest.mesh, fixed->fixes, progress);
            } catch (const fabvdb::Error& e) {
                if (e.status() != FABVDB_ERR_BAD_INPUT) throw;  // the rest alone encloses nothing
            }
            if (united) {
                fixed->mesh = std::move(*united);
                fixed->path = "mixed";
            } else {
                fixed.reset();
            }
        }
        // New vertices (crossings resolved, holes filled, shells united) lie
        // off the float grid an STL or 3MF stores; where rounding them makes
        // triangles cross that no nudge clears, voxels repair the input.
        if (fixed && !fabvdb::on_float_grid(fixed->mesh)) {
            try {
                fixed->mesh = fabvdb::surface::round_to_float(fixed->mesh, mesh->name);
            } catch (const fabvdb::Error& e) {
                if (e.status() != FABVDB_ERR_INTERNAL) throw;
                fixed.reset();
            }
        }
        const double mesh_level_seconds = volumetric ? 0.0 : clock.lap("mesh level");
        // The mesh level's result must still be the input's model (a resolved
        // union of an inside-out shell can be a sliver of it); else voxels
        // repair the input afresh.
        nlohmann::json fidelity, mesh_level_rejected;
        if (fixed) {
            if (fixed->path == "input") {
                fidelity = fabvdb::api::fidelity_report_kept();
            } else {
                const fabvdb::volume::FidelityLimits limits =
                    fixed->path == "mixed" ? fabvdb::volume::voxel_limits(repair.distance.voxel_size)
                                           : fabvdb::volume::exact_limits(mesh->mesh);
                const fabvdb::volume::Fidelity measured =
                    fabvdb::volume::measure_fidelity(mesh->mesh, fixed->mesh, limits, progress);
                fidelity = fabvdb::api::fidelity_report(measured, limits);
                if (!measured.passed) {
                    mesh_level_rejected = {{"path", fixed->path}, {"fixes", fixed->fixes}, {"fidelity", fidelity}};
                    fixed.reset();
                    oriented = fabvdb::Mesh{};
                }
            }
            clock.lap("fidelity");
        }
        if (fixed) {
            nlohmann::json document;
            document["path"] = fixed->path;
            document["mesh_level"] = true;
            document["fixes"] = fixed->fixes;
            document["fix_count"] = fixed->fixes.size();
            document["shell_paths"] = fixed->shell_paths;
            document["volumetric_shell_count"] =
                std::count(fixed->shell_paths.begin(), fixed->shell_paths.end(), "volumetric");
            document["voxel_size"] = rest_report.is_null() ? nlohmann::json() : rest_report["voxel_size"];
            if (!rest_report.is_null()) document["volumetric_rest"] = std::move(rest_report);
            document["shells_kept"] = fabvdb::volume::split_shells(fixed->mesh).size();
            document["shells_dropped"] = 0;
            document["input"] = std::move(input);
            document["output_triangles"] = fixed->mesh.triangles.size();
            document["volume"] = signed_volume(fixed->mesh);
            document["fidelity"] = std::move(fidelity);
            document["timings"] = stages;
            document["timings"]["total"] = clock.total();
            if (report) *report = fabvdb::api::new_report_handle(std::move(document));
            *out = fabvdb::api::new_mesh_handle(std::move(fixed->mesh), true);
            return;
        }
        repair.distance.oriented = !oriented.triangles.empty();
        // What voxels made must still be the input's model, unless shells
        // were dropped on purpose. At the automatic voxel, a repair that lost
        // the model is refined.
        const bool gated = repair.min_shell_volume == 0.0;
        const int refinements = gated && chosen.voxel_size == 0.0 ? kRepairRefinements : 0;
        fabvdb::volume::FaithfulRepair faithful = fabvdb::volume::faithful_repair(
            mesh->mesh, repair.distance.oriented ? oriented : mesh->mesh, repair, refinements, nullptr, progress);
        if (gated) fabvdb::volume::require_faithful(faithful.fidelity, mesh->name, "repaired solid");
        fabvdb::volume::RepairResult& result = faithful.repaired;
        clock.lap("volumetric");
        nlohmann::json document = repair_report(result, clock.total());
        document["fidelity"] = fabvdb::api::fidelity_report(faithful.fidelity, faithful.limits);
        document["timings"]["fidelity"] = faithful.fidelity_seconds;
        document["voxels_tried"] = faithful.voxels;
        nlohmann::json warnings = faithful.warnings;
        if (!mesh_level_rejected.is_null()) {
            warnings.insert(warnings.begin(), mesh->name + ": the mesh-level repair (" +
                                                  mesh_level_rejected["path"].get<std::string>() +
                                                  ") was not the input's model (" +
                                                  mesh_level_rejected["fidelity"]["defect"].get<std::string>() +
                                                  "), so voxels repaired it");
            document["mesh_level_rejected"] = std::move(mesh_level_rejected);
        }
        if (!warnings.empty()) document["warnings"] = std::move(warnings);
        if (report) document["timings"]["inspect input"] = inspect_seconds;
        if (!volumetric) document["timings"]["mesh level"] = mesh_level_seconds;
        document["path"] = "volumetric";
        document["mesh_level"] = false;
        document["input"] = std::move(input);
        document["output_triangles"] = result.mesh.triangles.size();
        document["snapped_vertices"] = result.snapped_vertices;
        document["volume"] = signed_volume(result.mesh);
        if (report) *report = fabvdb::api::new_report_handle(std::move(document));
        *out = fabvdb::api::new_mesh_handle(std::move(result.mesh), true);
    });
}

fabvdb_status fabvdb_volume_read(fabvdb_ctx* ctx, const char* path, fabvdb_volume** out) {
    return fabvdb::api::guard(ctx, [&] {
        fabvdb::api::require(path, "path");
        fabvdb::api::require(out, "out");
        openvdb::initialize();
        if (!std::ifstream(path)) throw fabvdb::Error(FABVDB_ERR_IO, std::string(path) + ": cannot be opened");
        openvdb::GridPtrVecPtr grids;
        try {
            openvdb::io::File file(path);
            file.open(false);
            grids = file.getGrids();
            file.close();
        } catch (const openvdb::Exception& e) {
            throw fabvdb::Error(FABVDB_ERR_BAD_INPUT, std::string(path) + ": not a readable VDB file (" + e.what() + ")");
        }
        for (const openvdb::GridBase::Ptr& grid : *grids) {
            auto level_set = openvdb::gridPtrCast<openvdb::FloatGrid>(grid);
            if (level_set && level_set->getGridClass() == openvdb::GRID_LEVEL_SET) {
                auto volume = std::make_unique<fabvdb_volume>();
                volume->grid = level_set;
                volume->name = path;
                *out = volume.release();
                return;
            }
        }
        throw fabvdb::Error(FABVDB_ERR_BAD_INPUT, std::string(path) + ": holds no float level set grid");
    });
}

fabvdb_status fabvdb_volume_write(fabvdb_ctx* ctx, const fabvdb_volume* volume, const char* path) {
    return fabvdb::api::guard(ctx, [&] {
        fabvdb::api::require(volume, "volume");
        fabvdb::api::require(path, "path");
        fabvdb::AtomicOutput output(path);
        try {
            openvdb::io::File file(output.temp_path());
            file.write({volume->grid});
            file.close();
        } catch (const openvdb::Exception& e) {
            throw fabvdb::Error(FABVDB_ERR_IO, std::string(path) + ": cannot be written (" + e.what() + ")");
        }
        output.commit();
    });
}

double fabvdb_volume_voxel_size(const fabvdb_volume* volume) {
    return volume && volume->grid ? volume->grid->voxelSize()[0] : 0.0;
}

}  // extern "C"
