/* options_test.c — every options struct accepts a caller's older, smaller
 * struct: the caller's first struct_size bytes are read and the fields past
 * them keep their defaults. Each struct is passed truncated before its last
 * fields, in a buffer whose bytes past the prefix are 0xFF (NaN doubles, -1
 * integers, wild pointers): if the library read past struct_size it would
 * reject the options, or crash on the pointers. A struct_size of 0 (never
 * set) or larger than the library's (a newer header) is an invalid argument.
 * The prefix is read: a field set in it shows in the result. The structs a
 * decomposition session fills (info, part, its options) are written only as
 * far as the caller's struct_size. C, fabvdb.h only. */
#define _DEFAULT_SOURCE /* mkdtemp */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "check.h"
#include "fabvdb.h"

/* A 40 mm cube. */
static const double cube_vertices[] = {0, 0, 0, 40, 0, 0, 0, 40, 0, 40, 40, 0, 0, 0, 40, 40, 0, 40, 0, 40, 40, 40, 40, 40};
static const uint32_t cube_triangles[] = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
                                          2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};

/* The caller's older struct: the first `prefix` bytes of `full` with
 * struct_size = prefix, then 0xFF up to the library's size. */
static void* older(const void* full, size_t size, size_t prefix) {
    unsigned char* buffer = malloc(size);
    memset(buffer, 0xFF, size);
    memcpy(buffer, full, prefix);
    memcpy(buffer, &prefix, sizeof prefix); /* struct_size is the first field of every options struct */
    return buffer;
}

static void set_struct_size(void* options, size_t size) { memcpy(options, &size, sizeof size); }

static double number(fabvdb_ctx* ctx, const fabvdb_report* report, const char* pointer) {
    double value = NAN;
    CHECK(fabvdb_report_number(ctx, report, pointer, &value) == FABVDB_OK);
    return value;
}

/* The length of the array at `pointer` (0 when it is missing). */
static size_t count(fabvdb_ctx* ctx, const fabvdb_report* report, const char* pointer) {
    size_t n = 0;
    return fabvdb_report_count(ctx, report, pointer, &n) == FABVDB_OK ? n : 0;
}

static int exists(const char* path) {
    struct stat info;
    return stat(path, &info) == 0;
}

int main(void) {
    fabvdb_ctx* ctx = NULL;
    CHECK(fabvdb_ctx_new(&ctx) == FABVDB_OK);
    fabvdb_mesh* cube = NULL;
    CHECK(fabvdb_mesh_new(ctx, cube_vertices, 8, cube_triangles, 12, &cube) == FABVDB_OK);
    char base[] = "/tmp/fabvdb_options_XXXXXX";
    CHECK(mkdtemp(base) != NULL);

    /* Volumes: a caller without thicken and flags; voxel_size from its prefix. */
    {
        fabvdb_volume_options full;
        fabvdb_volume_options_init(&full);
        full.voxel_size = 2.0;
        fabvdb_volume_options* old = older(&full, sizeof full, offsetof(fabvdb_volume_options, thicken));
        fabvdb_volume* volume = NULL;
        CHECK(fabvdb_volume_from_mesh(ctx, cube, old, &volume, NULL) == FABVDB_OK);
        CHECK(fabvdb_volume_voxel_size(volume) == 2.0);
        fabvdb_volume_free(volume);
        volume = NULL;
        set_struct_size(old, 0);
        CHECK(fabvdb_volume_from_mesh(ctx, cube, old, &volume, NULL) == FABVDB_ERR_INVALID_ARGUMENT);
        CHECK(strstr(fabvdb_last_error(ctx), "struct_size") != NULL);
        full.struct_size = sizeof full + 8;
        CHECK(fabvdb_volume_from_mesh(ctx, cube, &full, &volume, NULL) == FABVDB_ERR_INVALID_ARGUMENT);
        CHECK(strstr(fabvdb_last_error(ctx), "newer") != NULL);
        CHECK(volume == NULL);
        free(old);
    }

    /* Hollowing: a caller without the infill fields; wall from its prefix. */
    fabvdb_mesh* hollow = NULL;
    {
        fabvdb_hollow_options full;
        fabvdb_hollow_options_init(&full);
        full.wall = 2.5;
        full.voxel_size = 1.0;
        fabvdb_hollow_options* old = older(&full, sizeof full, offsetof(fabvdb_hollow_options, infill_cell));
        fabvdb_report* report = NULL;
        CHECK(fabvdb_mesh_hollow(ctx, cube, old, &hollow, &report) == FABVDB_OK);
        CHECK(number(ctx, report, "/wall") == 2.5);
        double strut = 0;
        CHECK(fabvdb_report_number(ctx, report, "/infill/strut", &strut) == FABVDB_ERR_NOT_FOUND);
        fabvdb_report_free(report);
        full.struct_size = sizeof full + 1;
        fabvdb_mesh* none = NULL;
        CHECK(fabvdb_mesh_hollow(ctx, cube, &full, &none, NULL) == FABVDB_ERR_INVALID_ARGUMENT && none == NULL);
        free(old);
    }

    /* Drain: a caller without keep_out_path and heatmap_path (0xFF pointers
     * past its struct); hole count and patches from its prefix. */
    fabvdb_report* drain_report = NULL;
    fabvdb_mesh* drilled = NULL;
    {
        fabvdb_drain_options full;
        fabvdb_drain_options_init(&full);
        full.hole_count = 2;
        full.patch_count = 300;
        fabvdb_drain_options* old = older(&full, sizeof full, offsetof(fabvdb_drain_options, keep_out_path));
        CHECK(fabvdb_mesh_drain(ctx, hollow, old, &drilled, &drain_report) == FABVDB_OK);
        CHECK(count(ctx, drain_report, "/holes") == 2);
        set_struct_size(old, 0);
        fabvdb_mesh* none = NULL;
        CHECK(fabvdb_mesh_drain(ctx, hollow, old, &none, NULL) == FABVDB_ERR_INVALID_ARGUMENT && none == NULL);
        free(old);
    }

    /* Powder simulation: a caller without slope_window; turns from its prefix. */
    {
        fabvdb_powder_options full;
        fabvdb_powder_options_init(&full);
        full.turns = 2;
        fabvdb_powder_options* old = older(&full, sizeof full, offsetof(fabvdb_powder_options, slope_window));
        fabvdb_report* report = NULL;
        CHECK(fabvdb_powder_simulate(ctx, drilled, fabvdb_report_json(drain_report), old, &report) == FABVDB_OK);
        CHECK(number(ctx, report, "/turns") == 2.0);
        CHECK(count(ctx, report, "/routine") == 2);
        fabvdb_report_free(report);
        report = NULL;
        full.struct_size = sizeof full + 8;
        CHECK(fabvdb_powder_simulate(ctx, drilled, fabvdb_report_json(drain_report), &full, &report) ==
                  FABVDB_ERR_INVALID_ARGUMENT &&
              report == NULL);
        free(old);
    }

    /* Decomposition: a caller without w_smooth; low_res and smoothing from its prefix. */
    {
        fabvdb_mesh *unit = NULL, *sphere = NULL;
        CHECK(fabvdb_mesh_read(ctx, FABVDB_DATA_DIR "/sphere.obj", &unit) == FABVDB_OK);
        CHECK(fabvdb_mesh_scale(ctx, unit, 20.0, &sphere) == FABVDB_OK);
        fabvdb_decompose_options full;
        fabvdb_decompose_options_init(&full);
        full.low_res_triangles = 800;
        full.smoothing_iterations = 0;
        fabvdb_decompose_options* old = older(&full, sizeof full, offsetof(fabvdb_decompose_options, w_smooth));
        char out_dir[256];
        snprintf(out_dir, sizeof out_dir, "%s/decomposition", base);
        fabvdb_report* report = NULL;
        CHECK(fabvdb_mesh_decompose(ctx, sphere, old, NULL, out_dir, &report) == FABVDB_OK);
        CHECK(number(ctx, report, "/smoothing/iterations") == 0.0);
        CHECK(count(ctx, report, "/parts") >= 1);
        fabvdb_report_free(report);
        report = NULL;

        /* A session from the older options; the structs it fills are
         * written only as far as the caller's struct_size (the bytes past
         * it stay 0xFF), and an older edit or rerun struct is read. */
        fabvdb_decomposition* session = NULL;
        CHECK(fabvdb_decomposition_new(ctx, sphere, old, &session) == FABVDB_OK);
        const unsigned char untouched[sizeof(double)] = {0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF};
        fabvdb_decomposition_info full_info;
        fabvdb_decomposition_info_init(&full_info);
        fabvdb_decomposition_info* info =
            older(&full_info, sizeof full_info, offsetof(fabvdb_decomposition_info, undo_steps));
        CHECK(fabvdb_decomposition_get_info(ctx, session, info) == FABVDB_OK);
        CHECK(info->struct_size == offsetof(fabvdb_decomposition_info, undo_steps) && info->part_count >= 1);
        CHECK(memcmp(&info->last_step_seconds, untouched, sizeof untouched) == 0);
        fabvdb_part_info full_part;
        fabvdb_part_info_init(&full_part);
        fabvdb_part_info* part = older(&full_part, sizeof full_part, offsetof(fabvdb_part_info, area));
        CHECK(fabvdb_decomposition_get_part(ctx, session, 0, part) == FABVDB_OK);
        CHECK(part->energy > 0 && memcmp(&part->area, untouched, sizeof untouched) == 0);
        fabvdb_decompose_options* now = older(&full, sizeof full, offsetof(fabvdb_decompose_options, w_smooth));
        CHECK(fabvdb_decomposition_get_options(ctx, session, now) == FABVDB_OK);
        CHECK(now->low_res_triangles == 800 && memcmp(&now->w_smooth, untouched, sizeof untouched) == 0);
        CHECK(fabvdb_decomposition_rerun(ctx, session, old) == FABVDB_OK);
        fabvdb_edit full_edit;
        fabvdb_edit_init(&full_edit);
        const double point[3] = {20, 0, 0};
        full_edit.points = point;
        full_edit.point_count = 1;
        full_edit.radius = 0; /* in the prefix: refused for a brush */
        fabvdb_edit* edit = older(&full_edit, sizeof full_edit, offsetof(fabvdb_edit, flags));
        CHECK(fabvdb_decomposition_apply(ctx, session, edit) == FABVDB_ERR_BAD_INPUT);
        CHECK(strstr(fabvdb_last_error(ctx), "radius") != NULL);
        set_struct_size(edit, 0);
        CHECK(fabvdb_decomposition_apply(ctx, session, edit) == FABVDB_ERR_INVALID_ARGUMENT);
        set_struct_size(info, sizeof full_info + 8);
        CHECK(fabvdb_decomposition_get_info(ctx, session, info) == FABVDB_ERR_INVALID_ARGUMENT);
        free(edit);
        free(now);
        free(part);
        free(info);
        fabvdb_decomposition_free(session);

        set_struct_size(old, 0);
        snprintf(out_dir, sizeof out_dir, "%s/not_written", base);
        CHECK(fabvdb_mesh_decompose(ctx, sphere, old, NULL, out_dir, &report) == FABVDB_ERR_INVALID_ARGUMENT);
        CHECK(report == NULL && !exists(out_dir));
        free(old);
        fabvdb_mesh_free(sphere);
        fabvdb_mesh_free(unit);
    }

    /* Molds: a caller without density. The prefix is read (a margin of -1 in
     * it is refused); with a good margin the options pass and the missing
     * decomposition file is what fails. */
    {
        fabvdb_mold_options full;
        fabvdb_mold_options_init(&full);
        full.margin = -1.0;
        fabvdb_mold_options* old = older(&full, sizeof full, offsetof(fabvdb_mold_options, density));
        char out_dir[256], missing[256];
        snprintf(out_dir, sizeof out_dir, "%s/molds", base);
        snprintf(missing, sizeof missing, "%s/no_such_decomposition.json", base);
        CHECK(fabvdb_mesh_mold(ctx, cube, missing, NULL, old, out_dir, NULL) == FABVDB_ERR_INVALID_ARGUMENT);
        CHECK(strstr(fabvdb_last_error(ctx), "margin") != NULL);
        free(old);
        full.margin = 5.0;
        old = older(&full, sizeof full, offsetof(fabvdb_mold_options, density));
        const fabvdb_status status = fabvdb_mesh_mold(ctx, cube, missing, NULL, old, out_dir, NULL);
        CHECK(status == FABVDB_ERR_BAD_INPUT || status == FABVDB_ERR_IO);
        CHECK(strstr(fabvdb_last_error(ctx), "no_such_decomposition") != NULL);
        CHECK(!exists(out_dir));
        set_struct_size(old, 0);
        CHECK(fabvdb_mesh_mold(ctx, cube, missing, NULL, old, out_dir, NULL) == FABVDB_ERR_INVALID_ARGUMENT);
        free(old);
    }

    fabvdb_report_free(drain_report);
    fabvdb_mesh_free(drilled);
    fabvdb_mesh_free(hollow);
    fabvdb_mesh_free(cube);
    fabvdb_ctx_free(ctx);
    char remove[320];
    snprintf(remove, sizeof remove, "rm -rf '%s'", base);
    CHECK(system(remove) == 0);
    return check_summary();
}
