/* check_api_test.c — the printability C API from C alone: defaults, a plate
 * thinner than the resin minimum fails with its thickness near the plate's
 * (the figure against the construction, 0.3 mm), a thick plate passes, a
 * JSON profile, the build volume, bad arguments (NULLs, an unknown process,
 * a missing profile, options out of range, struct_size unset) and
 * cancellation leaving the out-parameter untouched. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "box_mesh.h"
#include "check.h"
#include "fabvdb.h"

static int cancel_at_once(void* user, const char* stage, double fraction) {
    (void)user;
    (void)stage;
    (void)fraction;
    return 1;
}

static int verdict_is(fabvdb_ctx* ctx, const fabvdb_report* report, const char* pointer, const char* want) {
    const char* text = NULL;
    return fabvdb_report_string(ctx, report, pointer, &text) == FABVDB_OK && strcmp(text, want) == 0;
}

int main(void) {
    fabvdb_ctx* ctx = NULL;
    CHECK(fabvdb_ctx_new(&ctx) == FABVDB_OK);
    const double lo[3] = {0, 0, 0}, thin_hi[3] = {20, 15, 0.3}, thick_hi[3] = {20, 15, 1.5};
    fabvdb_mesh* thin = new_box(ctx, lo, thin_hi, 0);
    fabvdb_mesh* thick = new_box(ctx, lo, thick_hi, 0);
    CHECK(thin && thick);

    fabvdb_check_options options;
    fabvdb_check_options_init(&options);
    CHECK(options.struct_size == sizeof(options));
    CHECK(strcmp(options.process, "sla") == 0);
    CHECK(options.up[0] == 0 && options.up[1] == 0 && options.up[2] == 1);
    CHECK(options.build_volume[0] == 0 && options.voxel_size == 0 && options.resolution == 400);
    CHECK(options.thickness_map_path == NULL);
    fabvdb_check_options_init(NULL);

    options.voxel_size = 0.08;
    fabvdb_report* report = NULL;
    CHECK(fabvdb_mesh_check(ctx, thin, &options, &report) == FABVDB_OK);
    CHECK(verdict_is(ctx, report, "/verdict", "fail"));
    CHECK(verdict_is(ctx, report, "/checks/wall_thickness/status", "fail"));
    CHECK(fabs(report_value(ctx, report, "/checks/wall_thickness/min_thickness") - 0.3) <= 0.04);
    CHECK(report_value(ctx, report, "/process/min_wall") == 0.5);
    fabvdb_report_free(report);

    report = NULL;
    options.build_volume[0] = options.build_volume[1] = options.build_volume[2] = 100.0;
    CHECK(fabvdb_mesh_check(ctx, thick, &options, &report) == FABVDB_OK);
    CHECK(verdict_is(ctx, report, "/verdict", "pass"));
    CHECK(verdict_is(ctx, report, "/checks/build_volume/status", "pass"));
    fabvdb_report_free(report);

    /* A farm's profile with a thinner minimum lets the thin plate pass its walls. */
    const char* profile_path = "check_api_test_profile.json";
    FILE* file = fopen(profile_path, "w");
    CHECK(file != NULL);
    if (file) {
        fputs("{\"name\": \"fine\", \"min_wall\": 0.2, \"min_pin\": 0.2}", file);
        fclose(file);
    }
    options.process = profile_path;
    report = NULL;
    CHECK(fabvdb_mesh_check(ctx, thin, &options, &report) == FABVDB_OK);
    CHECK(verdict_is(ctx, report, "/process/name", "fine"));
    CHECK(verdict_is(ctx, report, "/checks/wall_thickness/status", "pass"));
    fabvdb_report_free(report);
    remove(profile_path);

    /* Bad arguments: the status, a message, and *out untouched. */
    fabvdb_report* untouched = (fabvdb_report*)&options;
    report = untouched;
    fabvdb_check_options_init(&options);
    CHECK(fabvdb_mesh_check(NULL, thin, &options, &report) == FABVDB_ERR_INVALID_ARGUMENT);
    CHECK(fabvdb_mesh_check(ctx, NULL, &options, &report) == FABVDB_ERR_INVALID_ARGUMENT);
    CHECK(fabvdb_mesh_check(ctx, thin, &options, NULL) == FABVDB_ERR_INVALID_ARGUMENT);
    options.process = "laser";
    CHECK(fabvdb_mesh_check(ctx, thin, &options, &report) == FABVDB_ERR_INVALID_ARGUMENT);
    CHECK(strstr(fabvdb_last_error(ctx), "laser") != NULL);
    options.process = "no_such_profile.json";
    CHECK(fabvdb_mesh_check(ctx, thin, &options, &report) == FABVDB_ERR_IO);
    CHECK(strstr(fabvdb_last_error(ctx), "no_such_profile.json") != NULL);
    options.process = NULL;
    CHECK(fabvdb_mesh_check(ctx, thin, &options, &report) == FABVDB_ERR_INVALID_ARGUMENT);
    fabvdb_check_options_init(&options);
    options.up[2] = 0.0;
    CHECK(fabvdb_mesh_check(ctx, thin, &options, &report) == FABVDB_ERR_INVALID_ARGUMENT);
    fabvdb_check_options_init(&options);
    options.build_volume[1] = -1.0;
    CHECK(fabvdb_mesh_check(ctx, thin, &options, &report) == FABVDB_ERR_INVALID_ARGUMENT);
    fabvdb_check_options_init(&options);
    options.voxel_size = NAN;
    CHECK(fabvdb_mesh_check(ctx, thin, &options, &report) == FABVDB_ERR_INVALID_ARGUMENT);
    fabvdb_check_options_init(&options);
    options.resolution = 0;
    CHECK(fabvdb_mesh_check(ctx, thin, &options, &report) == FABVDB_ERR_INVALID_ARGUMENT);
    fabvdb_check_options_init(&options);
    options.struct_size = 0;
    CHECK(fabvdb_mesh_check(ctx, thin, &options, &report) == FABVDB_ERR_INVALID_ARGUMENT);
    CHECK(report == untouched);

    /* Cancelled: no report. */
    CHECK(fabvdb_ctx_set_progress(ctx, cancel_at_once, NULL) == FABVDB_OK);
    CHECK(fabvdb_mesh_check(ctx, thin, NULL, &report) == FABVDB_ERR_CANCELLED);
    CHECK(report == untouched);

    fabvdb_mesh_free(thin);
    fabvdb_mesh_free(thick);
    fabvdb_ctx_free(ctx);
    return check_summary();
}
