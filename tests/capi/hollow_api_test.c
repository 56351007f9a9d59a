/* hollow_api_test.c — the hollowing C API from C alone: defaults, a hollowed
 * 40 mm cube (volumes checked by the divergence theorem here, not by the
 * library), the report, the shell level set, a solid given as a level set
 * (fabvdb_volume_hollow), bad arguments and cancellation leaving the
 * out-parameters untouched. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "fabvdb.h"

static const double cube_vertices[] = {0, 0, 0, 40, 0, 0, 0, 40, 0, 40, 40, 0, 0, 0, 40, 40, 0, 40, 0, 40, 40, 40, 40, 40};
static const uint32_t cube_triangles[] = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
                                          2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};

static double signed_volume(const fabvdb_mesh* mesh) {
    const double* v = fabvdb_mesh_vertices(mesh);
    const uint32_t* t = fabvdb_mesh_triangles(mesh);
    double volume = 0;
    for (size_t i = 0; i < fabvdb_mesh_triangle_count(mesh); ++i) {
        const double* a = v + 3 * t[3 * i];
        const double* b = v + 3 * t[3 * i + 1];
        const double* c = v + 3 * t[3 * i + 2];
        volume += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                  a[2] * (b[0] * c[1] - b[1] * c[0]);
    }
    return volume / 6.0;
}

static int cancel_on_second_stage(void* user, const char* stage, double fraction) {
    int* calls = (int*)user;
    (void)stage;
    (void)fraction;
    return ++*calls >= 2;
}

int main(void) {
    fabvdb_ctx* ctx = NULL;
    CHECK(fabvdb_ctx_new(&ctx) == FABVDB_OK);
    fabvdb_mesh* cube = NULL;
    CHECK(fabvdb_mesh_new(ctx, cube_vertices, 8, cube_triangles, 12, &cube) == FABVDB_OK);

    fabvdb_hollow_options options;
    fabvdb_hollow_options_init(&options);
    CHECK(options.struct_size == sizeof(options));
    CHECK(options.wall == 3.0 && options.closing == 0.0 && options.voxel_size == 0.0);
    CHECK(options.infill_cell == 0.0 && options.infill_strut == 1.2);

    fabvdb_mesh* hollowed = NULL;
    fabvdb_report* report = NULL;
    options.voxel_size = 1.0;
    CHECK(fabvdb_mesh_hollow(ctx, cube, &options, &hollowed, &report) == FABVDB_OK);
    CHECK(hollowed != NULL && report != NULL);
    /* 40^3 - 34^3: the cavity of a box is the box offset by the wall. */
    const double shell = signed_volume(hollowed);
    CHECK(fabs(shell - (64000.0 - 39304.0)) < 0.02 * 39304.0);
    double number = 0;
    CHECK(fabvdb_report_number(ctx, report, "/volume_shell", &number) == FABVDB_OK && fabs(number - shell) < 1e-6 * shell);
    CHECK(fabvdb_report_number(ctx, report, "/cavity_count", &number) == FABVDB_OK && number == 1);
    CHECK(fabvdb_report_number(ctx, report, "/material_saved_fraction", &number) == FABVDB_OK && number > 0.5);
    /* A clean closed cube keeps its own outer surface; the report says so as text. */
    const char* outer = NULL;
    CHECK(fabvdb_report_string(ctx, report, "/outer_surface", &outer) == FABVDB_OK && strcmp(outer, "input") == 0);
    size_t cavities = 0;
    CHECK(fabvdb_report_count(ctx, report, "/cavities", &cavities) == FABVDB_OK && cavities == 1);
    CHECK(fabvdb_report_number(ctx, report, "/output_triangles", &number) == FABVDB_OK &&
          number == (double)fabvdb_mesh_triangle_count(hollowed));
    fabvdb_report_free(report);
    fabvdb_mesh_free(hollowed);

    /* The shell level set, written and read back, encloses the shell. */
    fabvdb_volume* shell_volume = NULL;
    CHECK(fabvdb_mesh_hollow_volume(ctx, cube, &options, &shell_volume, NULL) == FABVDB_OK);
    CHECK(shell_volume != NULL);
    const char* vdb_path = "hollow_api_test_shell.vdb";
    CHECK(fabvdb_volume_write(ctx, shell_volume, vdb_path) == FABVDB_OK);
    fabvdb_volume_free(shell_volume);
    shell_volume = NULL;
    CHECK(fabvdb_volume_read(ctx, vdb_path, &shell_volume) == FABVDB_OK);
    remove(vdb_path);
    fabvdb_mesh* shell_surface = NULL;
    CHECK(fabvdb_volume_to_mesh(ctx, shell_volume, NULL, &shell_surface) == FABVDB_OK);
    CHECK(fabs(signed_volume(shell_surface) - shell) < 0.03 * shell);
    fabvdb_mesh_free(shell_surface);
    fabvdb_volume_free(shell_volume);

    /* Gyroid infill adds material inside the cavity and is reported. */
    options.infill_cell = 10.0;
    options.infill_strut = 2.0;
    CHECK(fabvdb_mesh_hollow(ctx, cube, &options, &hollowed, &report) == FABVDB_OK);
    CHECK(signed_volume(hollowed) > shell + 0.03 * 39304.0);
    CHECK(fabvdb_report_number(ctx, report, "/infill/strut", &number) == FABVDB_OK && number == 2.0);
    fabvdb_report_free(report);
    fabvdb_mesh_free(hollowed);
    hollowed = NULL;
    options.infill_strut = 3.0; /* over a quarter of the cell */
    CHECK(fabvdb_mesh_hollow(ctx, cube, &options, &hollowed, NULL) == FABVDB_ERR_INVALID_ARGUMENT);
    CHECK(hollowed == NULL);
    options.infill_cell = 0.0;

    /* A wall thicker than half the part: the part comes back solid, with
     * cavity_count 0 and a warning. */
    options.wall = 25;
    fabvdb_report* thin = NULL;
    CHECK(fabvdb_mesh_hollow(ctx, cube, &options, &hollowed, &thin) == FABVDB_OK);
    CHECK(hollowed != NULL && fabvdb_mesh_triangle_count(hollowed) == fabvdb_mesh_triangle_count(cube));
    double cavity_count = -1;
    CHECK(fabvdb_report_number(ctx, thin, "/cavity_count", &cavity_count) == FABVDB_OK && cavity_count == 0);
    CHECK(strstr(fabvdb_report_json(thin), "leaves no cavity") != NULL);
    fabvdb_report_free(thin);
    fabvdb_mesh_free(hollowed);
    options.wall = 3;
    /* A solid given as a level set is hollowed at its own voxel size (the
     * options' voxel is ignored); the shell it returns encloses 40^3 - 34^3. */
    fabvdb_volume_options solid_options;
    fabvdb_volume_options_init(&solid_options);
    solid_options.voxel_size = 1.0;
    fabvdb_volume* solid = NULL;
    CHECK(fabvdb_volume_from_mesh(ctx, cube, &solid_options, &solid, NULL) == FABVDB_OK);
    options.voxel_size = 0.25;
    fabvdb_volume* solid_shell = NULL;
    CHECK(fabvdb_volume_hollow(ctx, solid, &options, &solid_shell, &report) == FABVDB_OK);
    CHECK(solid_shell != NULL && fabvdb_volume_voxel_size(solid_shell) == 1.0);
    CHECK(fabvdb_report_number(ctx, report, "/voxel_size", &number) == FABVDB_OK && number == 1.0);
    CHECK(fabvdb_report_number(ctx, report, "/cavity_count", &number) == FABVDB_OK && number == 1);
    fabvdb_report_free(report);
    report = NULL;
    fabvdb_mesh* solid_shell_surface = NULL;
    CHECK(fabvdb_volume_to_mesh(ctx, solid_shell, NULL, &solid_shell_surface) == FABVDB_OK);
    CHECK(fabs(signed_volume(solid_shell_surface) - (64000.0 - 39304.0)) < 0.03 * (64000.0 - 39304.0));
    fabvdb_mesh_free(solid_shell_surface);
    fabvdb_volume_free(solid_shell);
    solid_shell = NULL;
    CHECK(fabvdb_volume_hollow(ctx, NULL, &options, &solid_shell, NULL) == FABVDB_ERR_INVALID_ARGUMENT);
    options.wall = 25; /* no cavity fits in a 40 mm cube: the solid comes back */
    CHECK(fabvdb_volume_hollow(ctx, solid, &options, &solid_shell, &report) == FABVDB_OK);
    CHECK(fabvdb_report_number(ctx, report, "/cavity_count", &number) == FABVDB_OK && number == 0);
    fabvdb_report_free(report);
    report = NULL;
    fabvdb_volume_free(solid_shell);
    solid_shell = NULL;
    options.wall = 3;
    int solid_calls = 0;
    CHECK(fabvdb_ctx_set_progress(ctx, cancel_on_second_stage, &solid_calls) == FABVDB_OK);
    CHECK(fabvdb_volume_hollow(ctx, solid, &options, &solid_shell, &report) == FABVDB_ERR_CANCELLED);
    CHECK(fabvdb_ctx_set_progress(ctx, NULL, NULL) == FABVDB_OK);
    CHECK(solid_shell == NULL && report == NULL);
    fabvdb_volume_free(solid);
    options.voxel_size = 1.0;

    /* Bad arguments leave the out-parameters untouched. */
    hollowed = NULL;
    CHECK(fabvdb_mesh_hollow(ctx, NULL, &options, &hollowed, NULL) == FABVDB_ERR_INVALID_ARGUMENT);
    options.wall = 0;
    CHECK(fabvdb_mesh_hollow(ctx, cube, &options, &hollowed, NULL) == FABVDB_ERR_INVALID_ARGUMENT);
    options.wall = 3;
    options.voxel_size = 0.001;
    CHECK(fabvdb_ctx_set_memory_budget(ctx, 64u << 20) == FABVDB_OK);
    CHECK(fabvdb_mesh_hollow(ctx, cube, &options, &hollowed, NULL) == FABVDB_ERR_OUT_OF_BUDGET);
    CHECK(fabvdb_ctx_set_memory_budget(ctx, 0) == FABVDB_OK);
    CHECK(hollowed == NULL);

    /* A mesh read from a file is called by its path in messages, a level set
       hollowed from one too (the budget refusal: before any work). */
    const char* path = FABVDB_SHARED_DATA "/meshes/sphere.obj";
    fabvdb_mesh* sphere = NULL;
    CHECK(fabvdb_mesh_read(ctx, path, &sphere) == FABVDB_OK);
    fabvdb_volume* sphere_shell = NULL;
    CHECK(fabvdb_ctx_set_memory_budget(ctx, 64u << 20) == FABVDB_OK);
    CHECK(fabvdb_mesh_hollow_volume(ctx, sphere, &options, &sphere_shell, NULL) == FABVDB_ERR_OUT_OF_BUDGET);
    CHECK(strncmp(fabvdb_last_error(ctx), path, strlen(path)) == 0 && sphere_shell == NULL);
    CHECK(fabvdb_ctx_set_memory_budget(ctx, 0) == FABVDB_OK);
    fabvdb_mesh_free(sphere);

    int calls = 0;
    options.voxel_size = 1.0;
    CHECK(fabvdb_ctx_set_progress(ctx, cancel_on_second_stage, &calls) == FABVDB_OK);
    CHECK(fabvdb_mesh_hollow(ctx, cube, &options, &hollowed, &report) == FABVDB_ERR_CANCELLED);
    CHECK(hollowed == NULL);
    CHECK(fabvdb_ctx_set_progress(ctx, NULL, NULL) == FABVDB_OK);

    fabvdb_mesh_free(cube);
    fabvdb_ctx_free(ctx);
    return check_summary();
}
