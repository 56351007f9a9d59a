//! C API: mold decomposition (`fabvdb decompose`) — options, validation, the
//! decomposition pipeline and its output folder.
#include <algorithm>
#include <cmath>

#include "api/decompose_settings.h"
#include "api/fidelity_report.h"
#include "api/guard.h"
#include "api/options.h"
#include "surface/decompose.h"
#include "surface/decomposition_io.h"
#include "volume/input_fidelity.h"

namespace fabvdb::api {

namespace {

void require_range(bool ok, const char* message) {
    if (!ok) throw fabvdb::Error(FABVDB_ERR_INVALID_ARGUMENT, message);
}

}  // namespace

nlohmann::json require_faithful_low_res(const Mesh& input, const Mesh& low_res, const std::string& name,
                                        Progress& progress) {
    double length = 0.0;
    for (const Triangle& t : low_res.triangles)
        for (int k = 0; k < 3; ++k)
            length += std::sqrt(squared_distance(low_res.vertices[t[k]], low_res.vertices[t[(k + 1) % 3]]));
    volume::FidelityLimits limits;
    limits.distance = low_res.triangles.empty() ? 0.0 : 2.0 * length / double(3 * low_res.triangles.size());
    limits.far_share = 0.05;
    const volume::Fidelity fidelity = volume::measure_fidelity(input, low_res, limits, progress);
    volume::require_faithful(fidelity, name, "low-resolution surface the parts are cut from");
    return fidelity_report(fidelity, limits);
}

fabvdb::surface::DecomposeSettings decompose_settings(const fabvdb_ctx* ctx, const fabvdb::Mesh& mesh,
                                                      const fabvdb_decompose_options& o) {
    require_range(std::isfinite(o.shell_thickness) && o.shell_thickness >= 0, "shell_thickness must be >= 0");
    require_range(std::isfinite(o.gamma) && o.gamma > 0, "gamma must be > 0");
    require_range(o.parts >= 0, "parts must be >= 0");
    require_range(o.max_parts >= 2, "max_parts must be >= 2");
    require_range(o.draft_degrees >= 0 && o.draft_degrees <= 30, "draft_degrees must be in [0, 30]");
    require_range(o.w_overhang >= 0 && o.w_overlap >= 0 && o.w_coarse_overlap >= 0,
                  "the weights must be >= 0");
    require_range(o.low_res_triangles >= 100, "low_res_triangles must be >= 100");
    require_range(o.smoothing_iterations >= 0, "smoothing_iterations must be >= 0");
    require_range(std::isfinite(o.w_smooth) && o.w_smooth >= 0, "w_smooth must be >= 0");
    const fabvdb::BoundingBox box = fabvdb::bounding_box(mesh);
    const double longest = std::max({box.max[0] - box.min[0], box.max[1] - box.min[1], box.max[2] - box.min[2]});
    fabvdb::surface::DecomposeSettings s;
    s.shell.target_triangles = size_t(o.low_res_triangles);
    s.shell.thickness = o.shell_thickness > 0 ? o.shell_thickness : 0.03 * longest;
    s.shell.solid = (o.flags & FABVDB_DECOMPOSE_SOLID) != 0;
    s.shell.memory_budget_bytes = ctx->budget_bytes();
    s.draft_radians = o.draft_degrees * M_PI / 180.0;
    s.decomposition.gamma = o.gamma;
    s.decomposition.parts = o.parts;
    s.decomposition.max_parts = std::max(o.max_parts, o.parts);
    s.decomposition.weights.overhang = o.w_overhang;
    s.decomposition.weights.overlap = o.w_overlap;
    s.decomposition.overlap_weight = o.w_coarse_overlap;
    s.decomposition.smoothing_iterations = o.smoothing_iterations;
    s.decomposition.smoothness_weight = o.w_smooth;
    return s;
}

}  // namespace fabvdb::api

extern "C" {

void fabvdb_decompose_options_init(fabvdb_decompose_options* options) {
    if (!options) return;
    *options = fabvdb_decompose_options{};
    options->struct_size = sizeof(fabvdb_decompose_options);
    options->flags = 0;
    options->shell_thickness = 0;
    options->gamma = 0.05;
    options->parts = 0;
    options->max_parts = 16;
    options->draft_degrees = 1;
    options->w_overhang = 1;
    options->w_overlap = 1;
    options->w_coarse_overlap = 1e6;
    options->low_res_triangles = 10000;
    options->smoothing_iterations = 10;
    options->w_smooth = 1;
}

fabvdb_status fabvdb_mesh_decompose(fabvdb_ctx* ctx, const fabvdb_mesh* mesh, const fabvdb_decompose_options* opts,
                                    const char* edits_path, const char* out_dir, fabvdb_report** out_report) {
    return fabvdb::api::guard(ctx, [&] {
        fabvdb::api::require(mesh, "mesh");
        fabvdb::api::require(out_dir, "out_dir");
        const fabvdb_decompose_options options =
            fabvdb::api::options_from(opts, fabvdb_decompose_options_init, "fabvdb_decompose_options");
        fabvdb::surface::DecomposeSettings settings = fabvdb::api::decompose_settings(ctx, mesh->mesh, options);
        settings.shell.input_name = mesh->name;
        const std::vector<fabvdb::surface::Edit> edits =
            edits_path ? fabvdb::surface::read_edits(edits_path) : std::vector<fabvdb::surface::Edit>{};
        fabvdb::Progress progress = ctx->make_progress();
        fabvdb::surface::DecomposeResult result = fabvdb::surface::decompose_mesh(mesh->mesh, settings, edits, progress);
        result.report["fidelity"] =
            fabvdb::api::require_faithful_low_res(mesh->mesh, result.shell.outer, mesh->name, progress);
        progress.stage("write decomposition");
        fabvdb::surface::write_decomposition(out_dir, mesh->mesh, result.shell, result.terms, result.decomposition,
                                             settings.decomposition);
        if (out_report) *out_report = fabvdb::api::new_report_handle(std::move(result.report));
    });
}

}  // extern "C"
