/* repair_api_test.c — the repair part of the C API from C, through fabvdb.h
 * only: a box with an open side repaired to a closed solid (checked by
 * fabvdb_mesh_inspect), volumes to meshes and to .vdb files and back, option
 * checks, the memory budget, and cancellation leaving the out-parameter untouched. */
#define _DEFAULT_SOURCE /* POSIX: mkdtemp */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "fabvdb.h"

/* A 10 mm box without its bottom face (z = 0): 10 triangles. */
static const double box_vertices[] = {0, 0, 0, 10, 0, 0, 0, 10, 0, 10, 10, 0, 0, 0, 10, 10, 0, 10, 0, 10, 10, 10, 10, 10};
static const uint32_t open_box_triangles[] = {4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4, 2, 6, 7,
                                              2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};

static double number(fabvdb_ctx* ctx, const fabvdb_report* report, const char* pointer) {
    double value = NAN;
    CHECK(fabvdb_report_number(ctx, report, pointer, &value) == FABVDB_OK);
    return value;
}

static int cancel_at_once(void* user, const char* stage, double fraction) {
    (void)user, (void)stage, (void)fraction;
    return 1;
}

int main(void) {
    fabvdb_ctx* ctx = NULL;
    CHECK(fabvdb_ctx_new(&ctx) == FABVDB_OK);
    fabvdb_mesh* open_box = NULL;
    CHECK(fabvdb_mesh_new(ctx, box_vertices, 8, open_box_triangles, 10, &open_box) == FABVDB_OK);

    fabvdb_volume_options options;
    fabvdb_volume_options_init(&options);
    CHECK(options.struct_size == sizeof options && options.resolution == 400 && options.half_band_voxels == 3);
    options.voxel_size = 0.25;

    /* One call: a closed solid of the box's volume. */
    fabvdb_mesh* repaired = NULL;
    fabvdb_report* report = NULL;
    CHECK(fabvdb_mesh_repair(ctx, open_box, &options, &repaired, &report) == FABVDB_OK);
    CHECK(repaired != NULL && report != NULL);
    CHECK(number(ctx, report, "/voxel_size") == 0.25);
    CHECK(number(ctx, report, "/input/boundary_edges") > 0);
    CHECK(number(ctx, report, "/shells_kept") == 1 && number(ctx, report, "/shells_dropped") == 0);
    CHECK(number(ctx, report, "/output_triangles") == (double)fabvdb_mesh_triangle_count(repaired));
    fabvdb_report* inspection = NULL;
    CHECK(fabvdb_mesh_inspect(ctx, repaired, &inspection) == FABVDB_OK);
    CHECK(number(ctx, inspection, "/closed") == 1 && number(ctx, inspection, "/non_manifold_edges") == 0);
    CHECK(number(ctx, inspection, "/self_intersecting_pairs") == 0);
    CHECK(fabs(number(ctx, inspection, "/volume") - 1000.0) < 20.0); /* edges are rounded by the voxels */
    fabvdb_report_free(inspection);
    fabvdb_report_free(report);
    fabvdb_mesh_free(repaired);

    /* Volume, .vdb round trip, extraction. */
    fabvdb_volume* volume = NULL;
    CHECK(fabvdb_volume_from_mesh(ctx, open_box, &options, &volume, NULL) == FABVDB_OK);
    CHECK(fabvdb_volume_voxel_size(volume) == 0.25 && fabvdb_volume_voxel_size(NULL) == 0.0);
    char folder[] = "/tmp/fabvdb_repair_api_XXXXXX";
    CHECK(mkdtemp(folder) != NULL);
    char path[256];
    snprintf(path, sizeof path, "%s/box.vdb", folder);
    CHECK(fabvdb_volume_write(ctx, volume, path) == FABVDB_OK);
    fabvdb_volume* read_back = NULL;
    CHECK(fabvdb_volume_read(ctx, path, &read_back) == FABVDB_OK);
    fabvdb_mesh* surface = NULL;
    CHECK(fabvdb_volume_to_mesh(ctx, read_back, NULL, &surface) == FABVDB_OK);
    CHECK(fabvdb_mesh_inspect(ctx, surface, &inspection) == FABVDB_OK);
    CHECK(number(ctx, inspection, "/closed") == 1);
    CHECK(fabs(number(ctx, inspection, "/volume") - 1000.0) < 20.0);
    fabvdb_report_free(inspection);
    fabvdb_mesh_free(surface);
    fabvdb_volume_free(read_back);
    remove(path);
    snprintf(path, sizeof path, "%s/missing.vdb", folder);
    read_back = NULL;
    CHECK(fabvdb_volume_read(ctx, path, &read_back) == FABVDB_ERR_IO && read_back == NULL);
    rmdir(folder);

    /* Bad options and the memory budget. */
    fabvdb_volume_options bad = options;
    bad.adaptivity = 2.0;
    fabvdb_volume* untouched = NULL;
    CHECK(fabvdb_volume_from_mesh(ctx, open_box, &bad, &untouched, NULL) == FABVDB_ERR_INVALID_ARGUMENT);
    bad = options;
    bad.struct_size = 0;
    CHECK(fabvdb_volume_from_mesh(ctx, open_box, &bad, &untouched, NULL) == FABVDB_ERR_INVALID_ARGUMENT);
    CHECK(fabvdb_volume_from_mesh(ctx, NULL, &options, &untouched, NULL) == FABVDB_ERR_INVALID_ARGUMENT);
    CHECK(fabvdb_ctx_set_memory_budget(ctx, 1 << 20) == FABVDB_OK);
    bad = options;
    bad.voxel_size = 0.001;
    CHECK(fabvdb_volume_from_mesh(ctx, open_box, &bad, &untouched, NULL) == FABVDB_ERR_OUT_OF_BUDGET);
    CHECK(strstr(fabvdb_last_error(ctx), "--voxel") != NULL);
    CHECK(untouched == NULL);
    CHECK(fabvdb_ctx_set_memory_budget(ctx, 0) == FABVDB_OK);

    /* Cancelled: no result. */
    CHECK(fabvdb_ctx_set_progress(ctx, cancel_at_once, NULL) == FABVDB_OK);
    fabvdb_mesh* cancelled = NULL;
    CHECK(fabvdb_mesh_repair(ctx, open_box, &options, &cancelled, NULL) == FABVDB_ERR_CANCELLED);
    CHECK(cancelled == NULL);
    CHECK(fabvdb_ctx_set_progress(ctx, NULL, NULL) == FABVDB_OK);

    fabvdb_volume_free(volume);
    fabvdb_mesh_free(open_box);
    fabvdb_ctx_free(ctx);
    return check_summary();
}
