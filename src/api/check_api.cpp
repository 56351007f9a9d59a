//! C API: printability (`fabvdb check`): the options, their ranges, and the
//! call into check::check_part.
#include <cmath>
#include <string>

#include "api/guard.h"
#include "api/options.h"
#include "check/check_part.h"

extern "C" {

void fabvdb_check_options_init(fabvdb_check_options* options) {
    if (!options) return;
    *options = fabvdb_check_options{};
    options->struct_size = sizeof(fabvdb_check_options);
    options->process = "sla";
    options->up[2] = 1.0;
    options->resolution = 400;
}

fabvdb_status fabvdb_mesh_check(fabvdb_ctx* ctx, const fabvdb_mesh* mesh, const fabvdb_check_options* options,
                                fabvdb_report** out) {
    return fabvdb::api::guard(ctx, [&] {
        fabvdb::api::require(mesh, "mesh");
        fabvdb::api::require(out, "out");
        const fabvdb_check_options o =
            fabvdb::api::options_from(options, fabvdb_check_options_init, "fabvdb_check_options");
        const auto invalid = [](const std::string& message) {
            return fabvdb::Error(FABVDB_ERR_INVALID_ARGUMENT, message);
        };
        if (!o.process) throw invalid("the process is NULL: give sla, powder, fdm or FILE.json");
        for (int k = 0; k < 3; ++k) {
            if (!std::isfinite(o.up[k])) throw invalid("the build direction (up) must be finite");
            if (!(std::isfinite(o.build_volume[k]) && o.build_volume[k] >= 0.0))
                throw invalid("the build volume must be three sizes >= 0 mm");
        }
        if (!(std::isfinite(o.voxel_size) && o.voxel_size >= 0.0)) throw invalid("the voxel size must be >= 0 mm");
        if (o.resolution < 1) throw invalid("the resolution must be >= 1");
        fabvdb::check::CheckOptions check;
        check.profile = fabvdb::check::read_profile(o.process);
        check.up = {o.up[0], o.up[1], o.up[2]};
        check.build_volume = {o.build_volume[0], o.build_volume[1], o.build_volume[2]};
        check.voxel_size = o.voxel_size;
        check.resolution = o.resolution;
        if (o.thickness_map_path) check.thickness_map = o.thickness_map_path;
        check.memory_budget_bytes = ctx->budget_bytes();
        check.input_name = mesh->name;
        fabvdb::Progress progress = ctx->make_progress();
        *out = fabvdb::api::new_report_handle(fabvdb::check::check_part(mesh->mesh, check, progress));
    });
}

}  // extern "C"
