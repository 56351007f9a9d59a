/* mold_api_test.c — fabvdb_mesh_mold from C, through fabvdb.h only: option
 * defaults and validation, a decomposition file of another scale refused with
 * no folder left, a full run on the bundled sphere (decomposed first) whose
 * files and report are there, the same decomposition file read back, and
 * cancellation from the progress callback, which must leave no folder. */
#define _DEFAULT_SOURCE /* POSIX: mkdtemp */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "check.h"
#include "fabvdb.h"

static int exists(const char* path) {
    struct stat info;
    return stat(path, &info) == 0;
}

static int cancel_in_sweep(void* user, const char* stage, double fraction) {
    (void)fraction;
    int* seen = (int*)user;
    if (strncmp(stage, "sweep", 5) == 0) {
        *seen = 1;
        return 1;
    }
    return 0;
}

int main(void) {
    fabvdb_mold_options options;
    fabvdb_mold_options_init(&options);
    CHECK(options.struct_size == sizeof options);
    CHECK(options.margin == 10.0 && options.voxel_size == 0.0 && options.grid_step == 0.0 && options.density == 1.1 &&
          options.flags == 0);
    fabvdb_mold_options_init(NULL);

    fabvdb_ctx* ctx = NULL;
    CHECK(fabvdb_ctx_new(&ctx) == FABVDB_OK);
    fabvdb_mesh *unit = NULL, *mesh = NULL;
    CHECK(fabvdb_mesh_read(ctx, FABVDB_DATA_DIR "/sphere.obj", &unit) == FABVDB_OK);
    CHECK(fabvdb_mesh_scale(ctx, unit, 20.0, &mesh) == FABVDB_OK); /* 40 mm across */
    char base[] = "/tmp/fabvdb_mold_api_XXXXXX";
    CHECK(mkdtemp(base) != NULL);
    char out_dir[256], file[400];
    snprintf(out_dir, sizeof out_dir, "%s/out", base);

    /* Validation: out-parameters untouched, message set. */
    fabvdb_report* report = (fabvdb_report*)&options; /* sentinel */
    options.margin = 0;
    CHECK(fabvdb_mesh_mold(ctx, mesh, NULL, NULL, &options, out_dir, &report) == FABVDB_ERR_INVALID_ARGUMENT);
    CHECK(report == (fabvdb_report*)&options && strlen(fabvdb_last_error(ctx)) > 0);
    CHECK(fabvdb_mesh_mold(ctx, NULL, NULL, NULL, NULL, out_dir, NULL) == FABVDB_ERR_INVALID_ARGUMENT);
    CHECK(fabvdb_mesh_mold(ctx, mesh, NULL, NULL, NULL, NULL, NULL) == FABVDB_ERR_INVALID_ARGUMENT);
    CHECK(!exists(out_dir));

    fabvdb_mold_options_init(&options);
    options.margin = 6.0;
    options.voxel_size = 0.8;
    fabvdb_decompose_options decompose;
    fabvdb_decompose_options_init(&decompose);
    decompose.low_res_triangles = 1500;
    decompose.parts = 2;
    decompose.shell_thickness = 3.0;

    /* Cancelled while sweeping: status, no report, no folder. */
    int seen = 0;
    CHECK(fabvdb_ctx_set_progress(ctx, cancel_in_sweep, &seen) == FABVDB_OK);
    report = NULL;
    CHECK(fabvdb_mesh_mold(ctx, mesh, NULL, &decompose, &options, out_dir, &report) == FABVDB_ERR_CANCELLED);
    CHECK(seen == 1 && report == NULL && !exists(out_dir));
    CHECK(fabvdb_ctx_set_progress(ctx, NULL, NULL) == FABVDB_OK);

    /* A full run, decomposing first. */
    CHECK(fabvdb_mesh_mold(ctx, mesh, NULL, &decompose, &options, out_dir, &report) == FABVDB_OK);
    double parts = 0, mean = -1, hausdorff = -1, volume = 0, weight = 0;
    CHECK(fabvdb_report_number(ctx, report, "/part_count", &parts) == FABVDB_OK && parts == 2);
    CHECK(fabvdb_report_number(ctx, report, "/mean_distance_ratio", &mean) == FABVDB_OK && mean >= 0 && mean < 0.01);
    CHECK(fabvdb_report_number(ctx, report, "/hausdorff_ratio", &hausdorff) == FABVDB_OK && hausdorff >= mean);
    CHECK(fabvdb_report_number(ctx, report, "/parts/0/volume", &volume) == FABVDB_OK && volume > 0);
    CHECK(fabvdb_report_number(ctx, report, "/parts/0/weight", &weight) == FABVDB_OK &&
          weight > 0.99 * volume * 1.1e-3 && weight < 1.01 * volume * 1.1e-3);
    const char* names[] = {"parts/part_00.stl", "parts/part_01.stl", "molds/part_00_top.stl",
                           "molds/part_00_bottom.stl", "molds/part_01_top.stl", "molds/part_01_bottom.stl",
                           "decomposition/decomposition.json"};
    for (int i = 0; i < 7; ++i) {
        snprintf(file, sizeof file, "%s/%s", out_dir, names[i]);
        CHECK(exists(file));
    }
    fabvdb_report_free(report);

    /* The decomposition file it wrote, read back for another folder. */
    char decomposition[320], again[256];
    snprintf(decomposition, sizeof decomposition, "%s/decomposition/decomposition.json", out_dir);
    snprintf(again, sizeof again, "%s/again", base);
    CHECK(fabvdb_mesh_mold(ctx, mesh, decomposition, NULL, &options, again, NULL) == FABVDB_OK);
    snprintf(file, sizeof file, "%s/molds/part_01_bottom.stl", again);
    CHECK(exists(file));

    /* The same file for the model at another scale: bad input, no folder. */
    char other[256];
    snprintf(other, sizeof other, "%s/other", base);
    CHECK(fabvdb_mesh_mold(ctx, unit, decomposition, NULL, &options, other, NULL) == FABVDB_ERR_BAD_INPUT);
    CHECK(strstr(fabvdb_last_error(ctx), "does not belong") != NULL);
    CHECK(!exists(other));

    fabvdb_mesh_free(mesh);
    fabvdb_mesh_free(unit);
    fabvdb_ctx_free(ctx);
    char command[400];
    snprintf(command, sizeof command, "rm -rf '%s'", base);
    CHECK(system(command) == 0);
    return check_summary();
}
