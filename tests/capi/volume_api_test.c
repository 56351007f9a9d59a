/* volume_api_test.c — volumes and repair through fabvdb.h only, on a 10 mm
 * cube at 0.5 mm voxels, against figures worked out by hand: the documented
 * option defaults; the cube's volume (1000 mm³, within the rounding of its
 * edges by the voxels) in the report and in the extracted mesh (divergence
 * theorem, computed here), which is closed and spans the cube; the voxel from
 * the resolution (10 mm / 20); a 2 mm cube beside it dropped under a 100 mm³
 * minimum; an open 10 × 10 sheet refused unless thickened (then about
 * 10 × 10 × 1 mm³); repair paths: a clean cube back as it is, an unwelded one
 * fixed at mesh level with its exact volume, the volumetric path on request;
 * every invalid option refused naming it; .vdb files round trip, and a file
 * that is not one, a missing one and a missing folder are refused naming the
 * path; a cancelled call gives no volume. */
#define _DEFAULT_SOURCE /* mkdtemp */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "box_mesh.h"
#include "check.h"
#include "fabvdb.h"

static const double lo[3] = {0, 0, 0}, hi[3] = {10, 10, 10};

static fabvdb_volume_options half_mm(void) {
    fabvdb_volume_options options;
    fabvdb_volume_options_init(&options);
    options.voxel_size = 0.5;
    return options;
}

/* The volume and report of `mesh` with `options`; NULL when the call fails. */
static fabvdb_volume* volume_of(fabvdb_ctx* ctx, const fabvdb_mesh* mesh, const fabvdb_volume_options* options,
                                fabvdb_report** report) {
    fabvdb_volume* volume = NULL;
    CHECK(fabvdb_volume_from_mesh(ctx, mesh, options, &volume, report) == FABVDB_OK);
    return volume;
}

static void test_defaults(void) {
    fabvdb_volume_options options;
    memset(&options, 0xFF, sizeof options);
    fabvdb_volume_options_init(&options);
    CHECK(options.struct_size == sizeof options && options.voxel_size == 0.0 && options.resolution == 400);
    CHECK(options.half_band_voxels == 3 && options.adaptivity == 0.0 && options.min_shell_volume == 0.0);
    CHECK(options.thicken == 0.0 && options.flags == 0);
    fabvdb_volume_options_init(NULL);
}

static void test_cube(fabvdb_ctx* ctx) {
    fabvdb_mesh* cube = new_box(ctx, lo, hi, 0);
    const fabvdb_volume_options options = half_mm();
    fabvdb_report* report = NULL;
    fabvdb_volume* volume = volume_of(ctx, cube, &options, &report);
    CHECK(fabvdb_volume_voxel_size(volume) == 0.5);
    CHECK(report_value(ctx, report, "/voxel_size") == 0.5);
    CHECK(fabs(report_value(ctx, report, "/volume") - 1000.0) < 20.0);
    CHECK(report_value(ctx, report, "/shells_kept") == 1 && report_value(ctx, report, "/shells_dropped") == 0);
    CHECK(report_value(ctx, report, "/thickened") == 0 && report_value(ctx, report, "/active_voxels") > 0);
    fabvdb_report_free(report);

    fabvdb_mesh* surface = NULL;
    CHECK(fabvdb_volume_to_mesh(ctx, volume, NULL, &surface) == FABVDB_OK);
    CHECK(fabs(mesh_signed_volume(surface) - 1000.0) < 20.0);
    fabvdb_report* inspection = NULL;
    CHECK(fabvdb_mesh_inspect(ctx, surface, &inspection) == FABVDB_OK);
    CHECK(report_value(ctx, inspection, "/closed") == 1 && report_value(ctx, inspection, "/components") == 1);
    for (int k = 0; k < 3; ++k) {
        char pointer[32];
        snprintf(pointer, sizeof pointer, "/bbox/min/%d", k);
        CHECK(fabs(report_value(ctx, inspection, pointer) - 0.0) < 0.5);
        snprintf(pointer, sizeof pointer, "/bbox/max/%d", k);
        CHECK(fabs(report_value(ctx, inspection, pointer) - 10.0) < 0.5);
    }
    fabvdb_report_free(inspection);
    fabvdb_mesh_free(surface);
    CHECK(fabvdb_volume_to_mesh(ctx, NULL, NULL, &surface) == FABVDB_ERR_INVALID_ARGUMENT);
    fabvdb_volume_free(volume);

    /* Longest side 10 mm over 20 voxels. */
    fabvdb_volume_options by_resolution;
    fabvdb_volume_options_init(&by_resolution);
    by_resolution.resolution = 20;
    volume = volume_of(ctx, cube, &by_resolution, NULL);
    CHECK(fabvdb_volume_voxel_size(volume) == 0.5);
    fabvdb_volume_free(volume);
    fabvdb_mesh_free(cube);
}

static void test_small_shell_and_sheet(fabvdb_ctx* ctx) {
    /* The cube and a 2 mm cube (8 mm³) 5 mm beside it. */
    const double small_lo[3] = {15, 0, 0}, small_hi[3] = {17, 2, 2};
    fabvdb_mesh* two = new_two_boxes(ctx, lo, hi, small_lo, small_hi);
    CHECK(two != NULL);
    fabvdb_volume_options options = half_mm();
    options.min_shell_volume = 100.0;
    fabvdb_report* report = NULL;
    fabvdb_volume_free(volume_of(ctx, two, &options, &report));
    CHECK(report_value(ctx, report, "/shells_kept") == 1 && report_value(ctx, report, "/shells_dropped") == 1);
    CHECK(fabs(report_value(ctx, report, "/volume") - 1000.0) < 20.0);
    fabvdb_report_free(report);
    fabvdb_mesh_free(two);

    /* The open square z = 5, 10 × 10: encloses nothing. */
    const double square[] = {0, 0, 5, 10, 0, 5, 10, 10, 5, 0, 10, 5};
    const uint32_t halves[] = {0, 1, 2, 0, 2, 3};
    fabvdb_mesh* sheet = NULL;
    CHECK(fabvdb_mesh_new(ctx, square, 4, halves, 2, &sheet) == FABVDB_OK);
    fabvdb_volume* volume = NULL;
    options = half_mm();
    CHECK(fabvdb_volume_from_mesh(ctx, sheet, &options, &volume, NULL) == FABVDB_ERR_BAD_INPUT && volume == NULL);
    CHECK(strlen(fabvdb_last_error(ctx)) > 0);
    options.thicken = 1.0;
    report = NULL;
    fabvdb_volume_free(volume_of(ctx, sheet, &options, &report));
    CHECK(report_value(ctx, report, "/thickened") == 1);
    CHECK(fabs(report_value(ctx, report, "/volume") - 100.0) < 25.0); /* plus the rounded rim */
    fabvdb_report_free(report);
    fabvdb_mesh_free(sheet);
}

static void test_repair_paths(fabvdb_ctx* ctx) {
    fabvdb_mesh* cube = new_box(ctx, lo, hi, 0);
    const char* path = NULL;
    fabvdb_mesh* repaired = NULL;
    fabvdb_report* report = NULL;
    CHECK(fabvdb_mesh_repair(ctx, cube, NULL, &repaired, &report) == FABVDB_OK);
    CHECK(fabvdb_report_string(ctx, report, "/path", &path) == FABVDB_OK && strcmp(path, "input") == 0);
    CHECK(fabvdb_mesh_vertex_count(repaired) == 8 && fabvdb_mesh_triangle_count(repaired) == 12);
    CHECK(memcmp(fabvdb_mesh_vertices(repaired), fabvdb_mesh_vertices(cube), 24 * sizeof(double)) == 0);
    fabvdb_report_free(report);
    fabvdb_mesh_free(repaired);

    /* The cube unwelded: every triangle on its own three corners. */
    double loose[108];
    uint32_t own[36];
    for (int i = 0; i < 36; ++i) {
        memcpy(loose + 3 * i, fabvdb_mesh_vertices(cube) + 3 * box_triangles[i], 3 * sizeof(double));
        own[i] = (uint32_t)i;
    }
    fabvdb_mesh* unwelded = NULL;
    CHECK(fabvdb_mesh_new(ctx, loose, 36, own, 12, &unwelded) == FABVDB_OK);
    repaired = NULL;
    report = NULL;
    CHECK(fabvdb_mesh_repair(ctx, unwelded, NULL, &repaired, &report) == FABVDB_OK);
    CHECK(fabvdb_report_string(ctx, report, "/path", &path) == FABVDB_OK && strcmp(path, "mesh") == 0);
    CHECK(report_value(ctx, report, "/mesh_level") == 1 && report_value(ctx, report, "/fix_count") >= 1);
    CHECK(fabvdb_mesh_vertex_count(repaired) == 8 && fabvdb_mesh_triangle_count(repaired) == 12);
    CHECK(fabs(mesh_signed_volume(repaired) - 1000.0) < 1e-9);
    fabvdb_report_free(report);
    fabvdb_mesh_free(repaired);
    fabvdb_mesh_free(unwelded);

    fabvdb_volume_options volumetric = half_mm();
    volumetric.flags = FABVDB_REPAIR_VOLUMETRIC;
    repaired = NULL;
    report = NULL;
    CHECK(fabvdb_mesh_repair(ctx, cube, &volumetric, &repaired, &report) == FABVDB_OK);
    CHECK(fabvdb_report_string(ctx, report, "/path", &path) == FABVDB_OK && strcmp(path, "volumetric") == 0);
    CHECK(report_value(ctx, report, "/mesh_level") == 0);
    CHECK(report_value(ctx, report, "/output_triangles") == (double)fabvdb_mesh_triangle_count(repaired));
    CHECK(fabs(mesh_signed_volume(repaired) - 1000.0) < 20.0);
    fabvdb_report_free(report);
    fabvdb_mesh_free(repaired);
    fabvdb_mesh_free(cube);
}

static void test_invalid_options(fabvdb_ctx* ctx) {
    fabvdb_mesh* cube = new_box(ctx, lo, hi, 0);
    struct {
        const char* field;
        fabvdb_volume_options options;
    } cases[6];
    for (int i = 0; i < 6; ++i) cases[i].options = half_mm();
    cases[0].field = "voxel_size", cases[0].options.voxel_size = -0.5;
    cases[1].field = "voxel_size", cases[1].options.voxel_size = NAN;
    cases[2].field = "adaptivity", cases[2].options.adaptivity = 1.5;
    cases[3].field = "min_shell_volume", cases[3].options.min_shell_volume = -1.0;
    cases[4].field = "thicken", cases[4].options.thicken = -1.0;
    cases[5].field = "struct_size", cases[5].options.struct_size = 0;
    for (int i = 0; i < 6; ++i) {
        fabvdb_volume* volume = NULL;
        CHECK(fabvdb_volume_from_mesh(ctx, cube, &cases[i].options, &volume, NULL) == FABVDB_ERR_INVALID_ARGUMENT);
        CHECK(volume == NULL);
        CHECK(strstr(fabvdb_last_error(ctx), cases[i].field) != NULL);
        fabvdb_mesh* repaired = NULL;
        CHECK(fabvdb_mesh_repair(ctx, cube, &cases[i].options, &repaired, NULL) == FABVDB_ERR_INVALID_ARGUMENT);
        CHECK(repaired == NULL);
    }
    fabvdb_mesh_free(cube);
}

static void test_files(fabvdb_ctx* ctx) {
    char folder[] = "/tmp/fabvdb_volume_api_XXXXXX";
    CHECK(mkdtemp(folder) != NULL);
    char path[256], text_path[256], missing[256];
    snprintf(path, sizeof path, "%s/cube.vdb", folder);
    snprintf(text_path, sizeof text_path, "%s/notes.vdb", folder);
    snprintf(missing, sizeof missing, "%s/no/folder/cube.vdb", folder);

    fabvdb_mesh* cube = new_box(ctx, lo, hi, 0);
    const fabvdb_volume_options options = half_mm();
    fabvdb_volume* volume = volume_of(ctx, cube, &options, NULL);
    CHECK(fabvdb_volume_write(ctx, volume, path) == FABVDB_OK);
    fabvdb_volume* back = NULL;
    CHECK(fabvdb_volume_read(ctx, path, &back) == FABVDB_OK);
    CHECK(fabvdb_volume_voxel_size(back) == 0.5);
    fabvdb_mesh* surface = NULL;
    CHECK(fabvdb_volume_to_mesh(ctx, back, NULL, &surface) == FABVDB_OK);
    CHECK(fabs(mesh_signed_volume(surface) - 1000.0) < 20.0);
    fabvdb_mesh_free(surface);
    fabvdb_volume_free(back);

    FILE* text = fopen(text_path, "w");
    if (text) {
        fputs("not a VDB file\n", text);
        fclose(text);
    }
    back = NULL;
    CHECK(fabvdb_volume_read(ctx, text_path, &back) == FABVDB_ERR_BAD_INPUT && back == NULL);
    CHECK(strstr(fabvdb_last_error(ctx), text_path) != NULL);
    CHECK(fabvdb_volume_read(ctx, missing, &back) == FABVDB_ERR_IO && back == NULL);
    CHECK(strstr(fabvdb_last_error(ctx), missing) != NULL);
    CHECK(fabvdb_volume_write(ctx, volume, missing) == FABVDB_ERR_IO);
    CHECK(strstr(fabvdb_last_error(ctx), missing) != NULL);
    CHECK(fabvdb_volume_write(ctx, NULL, path) == FABVDB_ERR_INVALID_ARGUMENT);
    fabvdb_volume_free(volume);
    fabvdb_mesh_free(cube);
    remove(path);
    remove(text_path);
    rmdir(folder);
}

static void test_cancel(fabvdb_ctx* ctx) {
    fabvdb_mesh* cube = new_box(ctx, lo, hi, 0);
    const fabvdb_volume_options options = half_mm();
    fabvdb_volume* volume = NULL;
    fabvdb_ctx_cancel(ctx);
    CHECK(fabvdb_volume_from_mesh(ctx, cube, &options, &volume, NULL) == FABVDB_ERR_CANCELLED && volume == NULL);
    volume = volume_of(ctx, cube, &options, NULL); /* the request applied to one call */
    CHECK(volume != NULL);
    fabvdb_volume_free(volume);
    fabvdb_mesh_free(cube);
}

int main(void) {
    fabvdb_ctx* ctx = NULL;
    if (fabvdb_ctx_new(&ctx) != FABVDB_OK) return 1;
    test_defaults();
    test_cube(ctx);
    test_small_shell_and_sheet(ctx);
    test_repair_paths(ctx);
    test_invalid_options(ctx);
    test_files(ctx);
    test_cancel(ctx);
    fabvdb_ctx_free(ctx);
    return check_summary();
}
