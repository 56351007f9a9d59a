/* api_test.c — the C API from C, through fabvdb.h only: context, statuses,
 * version, meshes in and out, errors with messages, reports, cancellation. */
#define _DEFAULT_SOURCE /* POSIX: sigaction, mkdtemp, chdir, getcwd */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "fabvdb.h"

/* A unit cube, outward-oriented. */
static const double cube_vertices[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1};
static const uint32_t cube_triangles[] = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
                                          2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};

static void test_statuses_and_version(void) {
    const fabvdb_status all[] = {FABVDB_OK, FABVDB_ERR_INVALID_ARGUMENT, FABVDB_ERR_IO, FABVDB_ERR_BAD_INPUT,
                                 FABVDB_ERR_OUT_OF_BUDGET, FABVDB_ERR_OUT_OF_MEMORY, FABVDB_ERR_CANCELLED,
                                 FABVDB_ERR_INTERNAL, FABVDB_ERR_NOT_FOUND};
    for (size_t i = 0; i < sizeof all / sizeof all[0]; ++i) {
        const char* text = fabvdb_status_string(all[i]);
        CHECK(text != NULL && strlen(text) > 0 && strcmp(text, "unknown status") != 0);
        for (size_t k = 0; k < i; ++k) CHECK(strcmp(text, fabvdb_status_string(all[k])) != 0);
    }
    /* The numbers are part of the ABI: never renumbered. */
    CHECK(FABVDB_OK == 0 && FABVDB_ERR_INVALID_ARGUMENT == 1 && FABVDB_ERR_IO == 2 && FABVDB_ERR_BAD_INPUT == 3 &&
          FABVDB_ERR_OUT_OF_BUDGET == 4 && FABVDB_ERR_OUT_OF_MEMORY == 5 && FABVDB_ERR_CANCELLED == 6 &&
          FABVDB_ERR_INTERNAL == 7 && FABVDB_ERR_NOT_FOUND == 8);
    CHECK(fabvdb_version_number() == FABVDB_VERSION_NUMBER);
    CHECK(strcmp(fabvdb_version_string(), FABVDB_VERSION_STRING) == 0);
}

static void test_context(void) {
    CHECK(fabvdb_ctx_new(NULL) == FABVDB_ERR_INVALID_ARGUMENT);
    fabvdb_ctx* ctx = NULL;
    CHECK(fabvdb_ctx_new(&ctx) == FABVDB_OK && ctx != NULL);
    CHECK(strcmp(fabvdb_last_error(ctx), "") == 0);
    CHECK(strcmp(fabvdb_last_error(NULL), "") == 0);
    CHECK(fabvdb_ctx_set_threads(ctx, -1) == FABVDB_ERR_INVALID_ARGUMENT);
    CHECK(strlen(fabvdb_last_error(ctx)) > 0);
    CHECK(fabvdb_ctx_set_threads(ctx, 1) == FABVDB_OK);
    CHECK(strcmp(fabvdb_last_error(ctx), "") == 0); /* cleared by the next call */
    CHECK(fabvdb_ctx_memory_budget(ctx) > 0);       /* the default is resolved */
    CHECK(fabvdb_ctx_set_memory_budget(ctx, 12345) == FABVDB_OK);
    CHECK(fabvdb_ctx_memory_budget(ctx) == 12345);
    CHECK(fabvdb_ctx_set_threads(NULL, 1) == FABVDB_ERR_INVALID_ARGUMENT);
    fabvdb_ctx_free(ctx);
    fabvdb_ctx_free(NULL);
    fabvdb_mesh_free(NULL);
    fabvdb_report_free(NULL);
    fabvdb_volume_free(NULL);
}

static void test_mesh_round_trip(fabvdb_ctx* ctx) {
    fabvdb_mesh* mesh = NULL;
    CHECK(fabvdb_mesh_new(ctx, cube_vertices, 8, cube_triangles, 12, &mesh) == FABVDB_OK);
    CHECK(fabvdb_mesh_vertex_count(mesh) == 8 && fabvdb_mesh_triangle_count(mesh) == 12);
    CHECK(memcmp(fabvdb_mesh_vertices(mesh), cube_vertices, sizeof cube_vertices) == 0);
    CHECK(memcmp(fabvdb_mesh_triangles(mesh), cube_triangles, sizeof cube_triangles) == 0);

    char dir[] = "/tmp/fabvdb_capi_XXXXXX";
    CHECK(mkdtemp(dir) != NULL);
    const char* extensions[] = {"stl", "obj", "ply", "off", "3mf"};
    for (size_t e = 0; e < sizeof extensions / sizeof extensions[0]; ++e) {
        char path[256];
        snprintf(path, sizeof path, "%s/cube.%s", dir, extensions[e]);
        CHECK(fabvdb_mesh_write(ctx, mesh, path) == FABVDB_OK);
        fabvdb_mesh* back = NULL;
        fabvdb_status status = fabvdb_mesh_read(ctx, path, &back);
        CHECK(status == FABVDB_OK);
        if (status != FABVDB_OK) {
            fprintf(stderr, "  %s: %s\n", path, fabvdb_last_error(ctx));
            continue;
        }
        CHECK(fabvdb_mesh_triangle_count(back) == 12);
        /* Geometry, not bytes: the same set of corner positions and the same volume. */
        const double* v = fabvdb_mesh_vertices(back);
        const uint32_t* t = fabvdb_mesh_triangles(back);
        double six_volume = 0;
        for (size_t i = 0; i < fabvdb_mesh_triangle_count(back); ++i) {
            const double* a = v + 3 * t[3 * i];
            const double* b = v + 3 * t[3 * i + 1];
            const double* c = v + 3 * t[3 * i + 2];
            six_volume += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                          a[2] * (b[0] * c[1] - b[1] * c[0]);
        }
        CHECK(fabs(six_volume / 6.0 - 1.0) < 1e-9);
        fabvdb_mesh_free(back);
        remove(path);
    }
    rmdir(dir);
    fabvdb_mesh_free(mesh);
}

static void test_bad_meshes(fabvdb_ctx* ctx) {
    fabvdb_mesh* mesh = NULL;
    const uint32_t out_of_range[] = {0, 1, 8};
    CHECK(fabvdb_mesh_new(ctx, cube_vertices, 8, out_of_range, 1, &mesh) == FABVDB_ERR_BAD_INPUT);
    CHECK(mesh == NULL);
    CHECK(strstr(fabvdb_last_error(ctx), "index") != NULL);
    double with_nan[24];
    memcpy(with_nan, cube_vertices, sizeof with_nan);
    with_nan[4] = NAN;
    CHECK(fabvdb_mesh_new(ctx, with_nan, 8, cube_triangles, 12, &mesh) == FABVDB_ERR_BAD_INPUT);
    CHECK(fabvdb_mesh_new(ctx, NULL, 8, cube_triangles, 12, &mesh) == FABVDB_ERR_INVALID_ARGUMENT);
    CHECK(fabvdb_mesh_new(ctx, cube_vertices, 8, cube_triangles, 12, NULL) == FABVDB_ERR_INVALID_ARGUMENT);

    CHECK(fabvdb_mesh_read(ctx, "/nonexistent/model.stl", &mesh) == FABVDB_ERR_IO);
    CHECK(strstr(fabvdb_last_error(ctx), "/nonexistent/model.stl") != NULL);
    CHECK(fabvdb_mesh_read(ctx, "/tmp", &mesh) == FABVDB_ERR_IO || fabvdb_mesh_read(ctx, "/tmp", &mesh) == FABVDB_ERR_BAD_INPUT);
    CHECK(fabvdb_mesh_read(ctx, FABVDB_SHARED_DATA "/meshes/README.md", &mesh) == FABVDB_ERR_BAD_INPUT);
    CHECK(strstr(fabvdb_last_error(ctx), "README.md") != NULL);
    CHECK(mesh == NULL);
}

static void test_inspect_report(fabvdb_ctx* ctx) {
    fabvdb_mesh* mesh = NULL;
    CHECK(fabvdb_mesh_new(ctx, cube_vertices, 8, cube_triangles, 12, &mesh) == FABVDB_OK);
    fabvdb_report* report = NULL;
    CHECK(fabvdb_mesh_inspect(ctx, mesh, &report) == FABVDB_OK);
    double value = -1;
    CHECK(fabvdb_report_number(ctx, report, "/closed", &value) == FABVDB_OK && value == 1);
    CHECK(fabvdb_report_number(ctx, report, "/volume", &value) == FABVDB_OK && fabs(value - 1.0) < 1e-12);
    CHECK(fabvdb_report_number(ctx, report, "/genus", &value) == FABVDB_OK && value == 0);
    CHECK(fabvdb_report_number(ctx, report, "/bbox/max/2", &value) == FABVDB_OK && value == 1);
    CHECK(fabvdb_report_number(ctx, report, "/no_such_key", &value) == FABVDB_ERR_NOT_FOUND);
    CHECK(fabvdb_report_number(ctx, report, "not a pointer", &value) == FABVDB_ERR_INVALID_ARGUMENT);
    /* Element counts: an array's length, an object's keys (bbox: min and max;
     * bbox/min: three coordinates); a number has none. */
    size_t count = 0;
    CHECK(fabvdb_report_count(ctx, report, "/bbox", &count) == FABVDB_OK && count == 2);
    CHECK(fabvdb_report_count(ctx, report, "/bbox/min", &count) == FABVDB_OK && count == 3);
    CHECK(fabvdb_report_count(ctx, report, "/volume", &count) == FABVDB_ERR_NOT_FOUND);
    CHECK(fabvdb_report_count(ctx, report, "/no_such_key", &count) == FABVDB_ERR_NOT_FOUND);
    CHECK(fabvdb_report_count(ctx, report, "no slash", &count) == FABVDB_ERR_INVALID_ARGUMENT);
    CHECK(fabvdb_report_count(ctx, report, "/bbox", NULL) == FABVDB_ERR_INVALID_ARGUMENT);
    CHECK(count == 3); /* untouched by the failures */
    /* Strings: none in an inspection report but the timings' keys, so a
     * number is not one. */
    const char* text = "untouched";
    CHECK(fabvdb_report_string(ctx, report, "/volume", &text) == FABVDB_ERR_NOT_FOUND);
    CHECK(strcmp(text, "untouched") == 0);
    CHECK(fabvdb_report_string(ctx, NULL, "/volume", &text) == FABVDB_ERR_INVALID_ARGUMENT);
    CHECK(strstr(fabvdb_report_json(report), "\"self_intersecting_pairs\"") != NULL);
    CHECK(fabvdb_report_write(ctx, report, "/nonexistent/dir/r.json") == FABVDB_ERR_IO);
    fabvdb_report_free(report);
    fabvdb_mesh_free(mesh);
}

static int cancel_at_first_call(void* user, const char* stage, double fraction) {
    (void)stage;
    (void)fraction;
    ++*(int*)user;
    return 1;
}

static void test_cancel(fabvdb_ctx* ctx) {
    int calls = 0;
    CHECK(fabvdb_ctx_set_progress(ctx, cancel_at_first_call, &calls) == FABVDB_OK);
    fabvdb_mesh* mesh = NULL;
    CHECK(fabvdb_mesh_read(ctx, FABVDB_SHARED_DATA "/meshes/armadillo_86k.obj", &mesh) == FABVDB_ERR_CANCELLED);
    CHECK(calls >= 1);
    CHECK(mesh == NULL);
    /* fabvdb_ctx_cancel before a call cancels that call; the request then clears. */
    CHECK(fabvdb_ctx_set_progress(ctx, NULL, NULL) == FABVDB_OK);
    fabvdb_ctx_cancel(ctx);
    CHECK(fabvdb_mesh_read(ctx, FABVDB_SHARED_DATA "/meshes/bunny.off", &mesh) == FABVDB_ERR_CANCELLED);
    CHECK(mesh == NULL);
    CHECK(fabvdb_mesh_read(ctx, FABVDB_SHARED_DATA "/meshes/bunny.off", &mesh) == FABVDB_OK);
    fabvdb_mesh_free(mesh);
}

int main(void) {
    test_statuses_and_version();
    test_context();
    fabvdb_ctx* ctx = NULL;
    if (fabvdb_ctx_new(&ctx) != FABVDB_OK) return 1;
    test_mesh_round_trip(ctx);
    test_bad_meshes(ctx);
    test_inspect_report(ctx);
    test_cancel(ctx);
    fabvdb_ctx_free(ctx);
    return check_summary();
}
