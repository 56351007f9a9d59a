//! C API: mold generation (`fabvdb mold`) — options, the decomposition (read
//! from a file, or run first through fabvdb_mesh_decompose), mold generation
//! and its output folder and report.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>

#include "api/fidelity_report.h"
#include "api/guard.h"
#include "api/options.h"
#include "core/atomic_output.h"
#include "core/stage_clock.h"
#include "surface/decomposition_parts.h"
#include "surface/mold_generation.h"
#include "surface/write_solid_mesh.h"

namespace {

fabvdb_mold_options checked_options(const fabvdb_mold_options* given) {
    const fabvdb_mold_options options = fabvdb::api::options_from(given, fabvdb_mold_options_init, "fabvdb_mold_options");
    const auto require = [](bool ok, const char* message) {
        if (!ok) throw fabvdb::Error(FABVDB_ERR_INVALID_ARGUMENT, message);
    };
    require(std::isfinite(options.margin) && options.margin > 0, "margin must be > 0");
    require(std::isfinite(options.voxel_size) && options.voxel_size >= 0, "voxel_size must be >= 0");
    require(std::isfinite(options.grid_step) && options.grid_step >= 0, "grid_step must be >= 0");
    require(std::isfinite(options.density) && options.density > 0, "density must be > 0");
    return options;
}

std::string numbered(const char* folder, int id, const char* suffix) {
    char name[64];
    std::snprintf(name, sizeof name, "%s/part_%02d%s.stl", folder, id, suffix);
    return name;
}

nlohmann::json mold_entry(const fabvdb::surface::MoldPair& mold) {
    return {{"size", mold.block_size},
            {"center", mold.block_center},
            {"up", mold.up},
            {"gates", mold.gates},
            {"vents", mold.vents}};
}

nlohmann::json part_entry(const fabvdb::surface::CastPart& part, double diagonal, double density, bool common) {
    nlohmann::json entry = {{"id", part.id},
            {"file", numbered("parts", part.id, "")},
            {"parting_direction", part.direction},
            {"volume", part.volume},
            {"weight", part.volume * 1e-3 * density},
            {"restored_volume", part.restored_volume},
            {"deformation",
             {{"handles", part.deformation_handles},
              {"max_displacement", part.deformation_max},
              {"mean_displacement", part.deformation_mean},
              {"volume_change", part.deformed_volume_change}}},
            {"added_volume", part.added_volume},
            {"added_volume_ratio", part.restored_volume > 0 ? part.added_volume / part.restored_volume : 0.0},
            {"removed_by_keep_out", part.removed_by_keep_out},
            {"columns_trimmed", part.columns_trimmed},
            {"handed_over", {{"given", part.given_volume}, {"received", part.received_volume}}},
            {"mean_distance_ratio", part.mean_distance / diagonal},
            {"hausdorff_ratio", part.max_distance / diagonal}};
    if (common) {
        entry["common_mold_offset"] = part.common_mold_offset;
    } else {
        entry["top_file"] = numbered("molds", part.id, "_top");
        entry["bottom_file"] = numbered("molds", part.id, "_bottom");
        entry["mold"] = mold_entry(part.mold);
    }
    return entry;
}

}  // namespace

extern "C" {

void fabvdb_mold_options_init(fabvdb_mold_options* options) {
    if (!options) return;
    *options = fabvdb_mold_options{};
    options->struct_size = sizeof(fabvdb_mold_options);
    options->flags = 0;
    options->margin = 10.0;
    options->voxel_size = 0.0;
    options->grid_step = 0.0;
    options->density = 1.1;
}

fabvdb_status fabvdb_mesh_mold(fabvdb_ctx* ctx, const fabvdb_mesh* mesh, const char* decomposition_path,
                               const fabvdb_decompose_options* decompose_opts, const fabvdb_mold_options* opts,
                               const char* out_dir, fabvdb_report** out_report) {
    return fabvdb::api::guard(ctx, [&] {
        fabvdb::api::require(mesh, "mesh");
        fabvdb::api::require(out_dir, "out_dir");
        const fabvdb_mold_options options = checked_options(opts);
        std::map<std::string, double> own_stages;
        fabvdb::StageClock clock(own_stages);
        fabvdb::AtomicOutput folder(out_dir, fabvdb::AtomicOutput::Kind::folder);
        const std::filesystem::path root(folder.temp_path());
        nlohmann::json report;

        std::string decomposition_file;
        if (decomposition_path) {
            decomposition_file = decomposition_path;
            report["decomposition_file"] = decomposition_file;
        } else {
            // The decomposition through its own C entry point, into the output
            // folder; its guard reports a failure as a status and message.
            fabvdb_report* decomposition_report = nullptr;
            const std::string decomposition_dir = (root / "decomposition").string();
            const fabvdb_status status =
                fabvdb_mesh_decompose(ctx, mesh, decompose_opts, nullptr, decomposition_dir.c_str(),
                                      &decomposition_report);
            if (status != FABVDB_OK) throw fabvdb::Error(status, "decomposition: " + ctx->last_error);
            report["decomposition"] = decomposition_report->document;
            fabvdb_report_free(decomposition_report);
            decomposition_file = decomposition_dir + "/decomposition.json";
        }
        clock.lap("decomposition");
        fabvdb::Progress progress = ctx->make_progress();
        progress.stage("mold: read the decomposition");
        const fabvdb::surface::DecomposedModel model =
            fabvdb::surface::read_decomposed_parts(decomposition_file, mesh->mesh);

        fabvdb::surface::MoldGenerationOptions settings;
        settings.voxel_size = options.voxel_size;
        settings.mold.margin = options.margin;
        settings.mold.grid_step = options.grid_step;
        settings.memory_budget_bytes = ctx->budget_bytes();
        const bool common = (options.flags & FABVDB_MOLD_COMMON) != 0;
        settings.common_mold = common;
        settings.input_name = mesh->name;
        const fabvdb::surface::MoldGeneration result =
            fabvdb::surface::generate_molds(mesh->mesh, model, settings, progress);

        clock.lap("generation");
        progress.stage("mold: write");
        std::filesystem::create_directory(root / "parts");
        std::filesystem::create_directory(root / "molds");
        report["voxel_size"] = result.voxel_size;
        report["margin"] = options.margin;
        report["density"] = options.density;
        report["diagonal"] = result.diagonal;
        report["part_count"] = result.parts.size();
        report["parts"] = nlohmann::json::array();
        for (size_t p = 0; p < result.parts.size(); ++p) {
            const fabvdb::surface::CastPart& part = result.parts[p];
            nlohmann::json entry = part_entry(part, result.diagonal, options.density, common);
            const auto write = [&](const fabvdb::Mesh& piece, const char* key) {
                fabvdb::surface::write_solid_mesh(piece, (root / entry[key].get<std::string>()).string(), progress);
            };
            write(part.part, "file");
            if (!common) {
                write(part.mold.top, "top_file");
                write(part.mold.bottom, "bottom_file");
            }
            report["parts"].push_back(std::move(entry));
            progress.update(double(p + 1) / double(result.parts.size()));
        }
        if (common) {
            nlohmann::json entry = mold_entry(result.common_mold);
            entry["top_file"] = "molds/common_top.stl";
            entry["bottom_file"] = "molds/common_bottom.stl";
            fabvdb::surface::write_solid_mesh(result.common_mold.top, (root / "molds/common_top.stl").string(),
                                              progress);
            fabvdb::surface::write_solid_mesh(result.common_mold.bottom, (root / "molds/common_bottom.stl").string(),
                                              progress);
            report["common_mold"] = std::move(entry);
        }
        report["mean_distance_ratio"] = result.mean_distance / result.diagonal;
        report["hausdorff_ratio"] = result.max_distance / result.diagonal;
        report["fidelity"] = fabvdb::api::fidelity_report(result.fidelity, result.fidelity_limits);
        report["lost_triangles"] = result.lost_triangles;
        report["vanished_parts"] = result.vanished_parts;
        report["warnings"] = nlohmann::json::array();
        for (int id : result.vanished_parts)
            report["warnings"].push_back(mesh->name + ": part " + std::to_string(id) +
                                         " vanished in the sweep (the other parts took all of it): no mold for it");
        report["timings"] = result.seconds;
        if (!decomposition_path) report["timings"]["decomposition"] = own_stages["decomposition"];
        report["timings"]["write"] = clock.lap("write");
        report["timings"]["total"] = clock.total();
        progress.check();
        folder.commit();
        if (out_report) *out_report = fabvdb::api::new_report_handle(std::move(report));
    });
}

}  // extern "C"
