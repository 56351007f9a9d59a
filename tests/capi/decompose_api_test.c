/* decompose_api_test.c — fabvdb_mesh_decompose from C, through fabvdb.h only:
 * option defaults and validation, a run on the shared torus that writes the
 * output folder and a report, a bad edits file, and cancellation from the
 * progress callback, which must leave no output folder behind. */
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

static int cancel_in_decomposition(void* user, const char* stage, double fraction) {
    (void)fraction;
    int* seen = (int*)user;
    if (strcmp(stage, "coarse decomposition") == 0) {
        *seen = 1;
        return 1;
    }
    return 0;
}

int main(void) {
    fabvdb_decompose_options options;
    fabvdb_decompose_options_init(&options);
    CHECK(options.struct_size == sizeof options);
    CHECK(options.gamma == 0.05 && options.draft_degrees == 1.0 && options.w_overhang == 1.0 &&
          options.w_overlap == 1.0 && options.w_coarse_overlap == 1e6 && options.parts == 0 &&
          options.low_res_triangles == 10000 && options.shell_thickness == 0.0 &&
          options.smoothing_iterations == 10 && options.w_smooth == 1.0);
    fabvdb_decompose_options_init(NULL);

    fabvdb_ctx* ctx = NULL;
    CHECK(fabvdb_ctx_new(&ctx) == FABVDB_OK);
    fabvdb_mesh* mesh = NULL;
    CHECK(fabvdb_mesh_read(ctx, FABVDB_SHARED_DATA "/meshes/torus.obj", &mesh) == FABVDB_OK);
    char base[] = "/tmp/fabvdb_decompose_api_XXXXXX";
    CHECK(mkdtemp(base) != NULL);
    char out_dir[256], file[320];
    snprintf(out_dir, sizeof out_dir, "%s/out", base);

    /* Validation: out-parameters untouched, message set. */
    fabvdb_report* report = (fabvdb_report*)&options; /* sentinel */
    options.gamma = -1;
    CHECK(fabvdb_mesh_decompose(ctx, mesh, &options, NULL, out_dir, &report) == FABVDB_ERR_INVALID_ARGUMENT);
    CHECK(report == (fabvdb_report*)&options && strlen(fabvdb_last_error(ctx)) > 0);
    CHECK(fabvdb_mesh_decompose(ctx, mesh, NULL, NULL, NULL, NULL) == FABVDB_ERR_INVALID_ARGUMENT);
    fabvdb_decompose_options_init(&options);
    options.smoothing_iterations = -1;
    CHECK(fabvdb_mesh_decompose(ctx, mesh, &options, NULL, out_dir, &report) == FABVDB_ERR_INVALID_ARGUMENT);
    fabvdb_decompose_options_init(&options);
    options.w_smooth = -0.5;
    CHECK(fabvdb_mesh_decompose(ctx, mesh, &options, NULL, out_dir, &report) == FABVDB_ERR_INVALID_ARGUMENT);
    CHECK(report == (fabvdb_report*)&options);
    fabvdb_decompose_options_init(&options);
    options.low_res_triangles = 1200;

    /* A malformed edits file is bad input and writes nothing. */
    snprintf(file, sizeof file, "%s/edits.json", base);
    FILE* edits = fopen(file, "w");
    fputs("{\"edits\": [{\"type\": \"fold\", \"points\": [[0,0,0]]}]}", edits);
    fclose(edits);
    CHECK(fabvdb_mesh_decompose(ctx, mesh, &options, file, out_dir, NULL) == FABVDB_ERR_BAD_INPUT);
    CHECK(strstr(fabvdb_last_error(ctx), "fold") != NULL);
    CHECK(!exists(out_dir));

    /* Cancelled during the decomposition: status, and no folder. */
    int seen = 0;
    CHECK(fabvdb_ctx_set_progress(ctx, cancel_in_decomposition, &seen) == FABVDB_OK);
    report = NULL;
    CHECK(fabvdb_mesh_decompose(ctx, mesh, &options, NULL, out_dir, &report) == FABVDB_ERR_CANCELLED);
    CHECK(seen == 1 && report == NULL && !exists(out_dir));
    CHECK(fabvdb_ctx_set_progress(ctx, NULL, NULL) == FABVDB_OK);

    /* A full run. */
    CHECK(fabvdb_mesh_decompose(ctx, mesh, &options, NULL, out_dir, &report) == FABVDB_OK);
    double parts = 0, energy = -1, gamma = 0;
    CHECK(fabvdb_report_number(ctx, report, "/part_count", &parts) == FABVDB_OK && parts >= 2);
    CHECK(fabvdb_report_number(ctx, report, "/total_moldability_energy", &energy) == FABVDB_OK && energy >= 0);
    CHECK(fabvdb_report_number(ctx, report, "/gamma", &gamma) == FABVDB_OK && gamma == 0.05);
    const char* names[] = {"decomposition.json", "decomposition.ply", "deformation.ply"};
    for (int i = 0; i < 3; ++i) {
        snprintf(file, sizeof file, "%s/%s", out_dir, names[i]);
        CHECK(exists(file));
    }
    fabvdb_report_free(report);
    fabvdb_mesh_free(mesh);
    fabvdb_ctx_free(ctx);
    char command[400];
    snprintf(command, sizeof command, "rm -rf '%s'", base);
    CHECK(system(command) == 0);
    return check_summary();
}
