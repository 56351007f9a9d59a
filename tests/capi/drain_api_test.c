/* drain_api_test.c — drain holes and the powder simulation from C alone: a
 * 40 mm cube hollowed with a 3 mm wall, drained with two holes (each on the
 * cavity surface, drilled outward); the report's holes read back; the
 * simulation (1 mm cells) reads the drain report and leaves less powder than
 * an undrilled hollow cube with no holes (which keeps everything); bad holes JSON is bad input; out-of-range options
 * are invalid arguments; cancellation returns no partial result.
 * The heat maps as data: the cavity surface on the 34 mm cavity's faces
 * within a voxel, facing the powder (its signed volume about -34^3), values
 * in range, and everything the heat-map files of the same call hold, read
 * here byte by byte; a part with no cavity gives none; NULL out_heatmap and
 * unknown kinds are refused; a cancelled call leaves no heat map and no file. */
#define _DEFAULT_SOURCE /* POSIX: mkdtemp */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "box_mesh.h"
#include "check.h"
#include "fabvdb.h"

static const double cube_vertices[] = {0, 0, 0, 40, 0, 0, 0, 40, 0, 40, 40, 0, 0, 0, 40, 40, 0, 40, 0, 40, 40, 40, 40, 40};
static const uint32_t cube_triangles[] = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
                                          2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};

static int cancel_at_once(void* user, const char* stage, double fraction) {
    (void)user;
    (void)stage;
    (void)fraction;
    return 1;
}

/* The length of the array at `pointer` (0 when it is missing). */
static size_t count(fabvdb_ctx* ctx, const fabvdb_report* report, const char* pointer) {
    size_t n = 0;
    return fabvdb_report_count(ctx, report, pointer, &n) == FABVDB_OK ? n : 0;
}

static double number(fabvdb_ctx* ctx, const fabvdb_report* report, const char* pointer) {
    double value = NAN;
    CHECK(fabvdb_report_number(ctx, report, pointer, &value) == FABVDB_OK);
    return value;
}

/* Distance from p to the surface of the box [lo, hi]^3. */
static double box_surface_distance(const double p[3], double lo, double hi) {
    double outside = 0.0, inside = INFINITY;
    for (int k = 0; k < 3; ++k) {
        const double below = lo - p[k], above = p[k] - hi;
        const double gap = fmax(0.0, fmax(below, above));
        outside += gap * gap;
        inside = fmin(inside, fmin(-below, -above));
    }
    return outside > 0.0 ? sqrt(outside) : inside;
}

/* Little-endian values at bytes + *at, moving past them. */
static float take_float(const char* bytes, size_t* at) {
    float value;
    memcpy(&value, bytes + *at, sizeof value);
    *at += sizeof value;
    return value;
}

static int32_t take_int32(const char* bytes, size_t* at) {
    int32_t value;
    memcpy(&value, bytes + *at, sizeof value);
    *at += sizeof value;
    return value;
}

static uint8_t take_byte(const char* bytes, size_t* at) { return (uint8_t)bytes[(*at)++]; }

/* Checks that the heat-map PLY at path holds the surface, the values and the
 * colours of `kind`: positions and values as floats, faces as they are. */
static void check_matches_file(const fabvdb_heatmap* heat, int kind, const char* path) {
    FILE* file = fopen(path, "rb");
    CHECK(file != NULL);
    if (!file) return;
    static char bytes[1 << 22];
    const size_t size = fread(bytes, 1, sizeof bytes, file);
    fclose(file);
    CHECK(size > 0 && size < sizeof bytes);
    bytes[size < sizeof bytes ? size : sizeof bytes - 1] = 0;
    const char* end = strstr(bytes, "end_header\n");
    const char* vertex_line = strstr(bytes, "element vertex ");
    const char* face_line = strstr(bytes, "element face ");
    CHECK(end && vertex_line && face_line);
    if (!end || !vertex_line || !face_line) return;
    const fabvdb_mesh* surface = fabvdb_heatmap_surface(heat);
    const size_t n = fabvdb_mesh_vertex_count(surface), m = fabvdb_mesh_triangle_count(surface);
    CHECK(strtoul(vertex_line + 15, NULL, 10) == n && strtoul(face_line + 13, NULL, 10) == m);
    CHECK(size == (size_t)(end + 11 - bytes) + n * 19 + m * 13);
    if (size != (size_t)(end + 11 - bytes) + n * 19 + m * 13) return;
    const double* v = fabvdb_mesh_vertices(surface);
    const uint32_t* t = fabvdb_mesh_triangles(surface);
    const double* values = fabvdb_heatmap_values(heat, kind);
    const uint8_t* colours = fabvdb_heatmap_colours(heat, kind);
    size_t at = (size_t)(end + 11 - bytes), mismatches = 0;
    for (size_t i = 0; i < n; ++i) {
        for (int k = 0; k < 3; ++k) mismatches += take_float(bytes, &at) != (float)v[3 * i + k];
        for (int k = 0; k < 3; ++k) mismatches += take_byte(bytes, &at) != colours[3 * i + k];
        mismatches += take_float(bytes, &at) != (float)values[i];
    }
    for (size_t i = 0; i < m; ++i) {
        mismatches += take_byte(bytes, &at) != 3;
        for (int k = 0; k < 3; ++k) mismatches += take_int32(bytes, &at) != (int32_t)t[3 * i + k];
    }
    CHECK(mismatches == 0);
}

static void check_heat_maps(fabvdb_ctx* ctx, const fabvdb_mesh* cube, fabvdb_drain_options options) {
    char dir[] = "/tmp/fabvdb_drain_heat_XXXXXX";
    CHECK(mkdtemp(dir) != NULL);
    char path[128], left_path[128];
    snprintf(path, sizeof path, "%s/heat.ply", dir);
    snprintf(left_path, sizeof left_path, "%s/heat_left.ply", dir);
    options.heatmap_path = path;
    fabvdb_mesh* drilled = NULL;
    fabvdb_report* report = NULL;
    fabvdb_heatmap* heat = NULL;
    CHECK(fabvdb_mesh_drain_heatmap(ctx, cube, &options, &drilled, &report, &heat) == FABVDB_OK);
    CHECK(drilled != NULL && report != NULL && heat != NULL);
    const fabvdb_mesh* surface = fabvdb_heatmap_surface(heat);
    const size_t n = fabvdb_mesh_vertex_count(surface);
    CHECK(n > 100 && fabvdb_mesh_triangle_count(surface) > 100);
    /* Wall 3 mm, voxel 0.75 mm: the cavity is the box [3, 37]^3. */
    const double* v = fabvdb_mesh_vertices(surface);
    double farthest = 0.0;
    for (size_t i = 0; i < n; ++i) farthest = fmax(farthest, box_surface_distance(v + 3 * i, 3.0, 37.0));
    CHECK(farthest < 0.75);
    CHECK(fabs(mesh_signed_volume(surface) + 34.0 * 34.0 * 34.0) < 0.05 * 34.0 * 34.0 * 34.0);
    const double* drained = fabvdb_heatmap_values(heat, FABVDB_HEATMAP_DRAINED);
    const double* left = fabvdb_heatmap_values(heat, FABVDB_HEATMAP_LEFT);
    size_t out_of_range = 0;
    double most_left = 0.0;
    for (size_t i = 0; i < n; ++i) {
        out_of_range += !(drained[i] >= 0.0 && drained[i] <= 1.0) + !(left[i] >= 0.0);
        most_left = fmax(most_left, left[i]);
    }
    CHECK(out_of_range == 0);
    CHECK(number(ctx, report, "/heatmap/powder_left/max") == (most_left > 0.0 ? most_left : 1.0));
    check_matches_file(heat, FABVDB_HEATMAP_DRAINED, path);
    check_matches_file(heat, FABVDB_HEATMAP_LEFT, left_path);
    CHECK(fabvdb_heatmap_values(heat, 2) == NULL && fabvdb_heatmap_colours(heat, -1) == NULL);
    CHECK(fabvdb_heatmap_surface(NULL) == NULL && fabvdb_heatmap_values(NULL, 0) == NULL &&
          fabvdb_heatmap_colours(NULL, 0) == NULL);
    fabvdb_heatmap_free(heat);
    fabvdb_heatmap_free(NULL);
    fabvdb_report_free(report);
    fabvdb_mesh_free(drilled);
    const char* legends[] = {"heat.png", "heat_left.png"};
    for (int i = 0; i < 2; ++i) {
        char file[160];
        snprintf(file, sizeof file, "%s/%s", dir, legends[i]);
        remove(file);
    }
    remove(path);
    remove(left_path);

    /* Without a path: the same data, no file, the report's ranges. */
    options.heatmap_path = NULL;
    CHECK(fabvdb_mesh_drain_heatmap(ctx, cube, &options, &drilled, &report, &heat) == FABVDB_OK);
    CHECK(heat != NULL && fabvdb_mesh_vertex_count(fabvdb_heatmap_surface(heat)) == n);
    CHECK(number(ctx, report, "/heatmap/drained_share/max") == 1.0);
    const char* text = NULL;
    CHECK(fabvdb_report_string(ctx, report, "/heatmap/drained_share/path", &text) == FABVDB_ERR_NOT_FOUND);
    fabvdb_heatmap_free(heat);
    fabvdb_report_free(report);
    fabvdb_mesh_free(drilled);

    /* A plate thinner than two walls stays solid: no cavity, no heat map. */
    const double lo[3] = {0, 0, 0}, hi[3] = {40, 40, 4};
    fabvdb_mesh* plate = new_box(ctx, lo, hi, 0);
    static char not_a_heat_map;
    heat = (fabvdb_heatmap*)&not_a_heat_map; /* the call must set it to NULL */
    CHECK(fabvdb_mesh_drain_heatmap(ctx, plate, &options, &drilled, NULL, &heat) == FABVDB_OK);
    CHECK(heat == NULL && drilled != NULL);
    fabvdb_mesh_free(drilled);
    fabvdb_mesh_free(plate);

    /* Refused and cancelled calls make nothing. */
    drilled = NULL;
    CHECK(fabvdb_mesh_drain_heatmap(ctx, cube, &options, &drilled, NULL, NULL) == FABVDB_ERR_INVALID_ARGUMENT);
    CHECK(strstr(fabvdb_last_error(ctx), "out_heatmap") != NULL && drilled == NULL);
    options.heatmap_path = path;
    CHECK(fabvdb_ctx_set_progress(ctx, cancel_at_once, NULL) == FABVDB_OK);
    CHECK(fabvdb_mesh_drain_heatmap(ctx, cube, &options, &drilled, &report, &heat) == FABVDB_ERR_CANCELLED);
    CHECK(drilled == NULL && heat == NULL);
    CHECK(fabvdb_ctx_set_progress(ctx, NULL, NULL) == FABVDB_OK);
    CHECK(access(path, F_OK) != 0);
    CHECK(rmdir(dir) == 0); /* empty: nothing was left behind */
}

int main(void) {
    fabvdb_ctx* ctx = NULL;
    CHECK(fabvdb_ctx_new(&ctx) == FABVDB_OK);
    fabvdb_mesh* cube = NULL;
    CHECK(fabvdb_mesh_new(ctx, cube_vertices, 8, cube_triangles, 12, &cube) == FABVDB_OK);

    fabvdb_drain_options options;
    fabvdb_drain_options_init(&options);
    CHECK(options.struct_size == sizeof options && options.wall == 3.0 && options.hole_diameter == 4.0 &&
          options.repose_degrees == 35.0 && options.effort == 0.9 && options.patch_count == 2000 &&
          options.hole_count == 0 && options.first_gravity[2] == -1.0);
    options.hole_count = 2;
    options.patch_count = 400;

    fabvdb_mesh* drilled = NULL;
    fabvdb_report* report = NULL;
    CHECK(fabvdb_mesh_drain(ctx, cube, &options, &drilled, &report) == FABVDB_OK);
    CHECK(drilled != NULL && report != NULL);
    const size_t holes = count(ctx, report, "/holes");
    CHECK(holes == 2);
    for (size_t h = 0; h < holes; ++h) {
        char pointer[64];
        double c[3], a[3];
        for (int k = 0; k < 3; ++k) {
            snprintf(pointer, sizeof pointer, "/holes/%zu/center/%d", h, k);
            c[k] = number(ctx, report, pointer) - 20.0;
            snprintf(pointer, sizeof pointer, "/holes/%zu/axis/%d", h, k);
            a[k] = number(ctx, report, pointer);
        }
        /* On the surface of the 34 mm cavity (17 mm from the centre in the
         * farthest coordinate), drilled outward. */
        const double farthest = fmax(fabs(c[0]), fmax(fabs(c[1]), fabs(c[2])));
        CHECK(fabs(farthest - 17.0) < 1.0);
        CHECK(c[0] * a[0] + c[1] * a[1] + c[2] * a[2] > 0.0);
        CHECK(fabs(a[0] * a[0] + a[1] * a[1] + a[2] * a[2] - 1.0) < 1e-6);
        snprintf(pointer, sizeof pointer, "/holes/%zu/diameter", h);
        CHECK(number(ctx, report, pointer) == 4.0);
    }
    CHECK(count(ctx, report, "/baseline_holes") == 2);
    const double cavity = number(ctx, report, "/cavity_volume");
    /* The powder samples' volume: a grid inside the cavity, a few % under it. */
    CHECK(cavity > 0.9 * 34.0 * 34.0 * 34.0 && cavity < 34.0 * 34.0 * 34.0);
    const double predicted = number(ctx, report, "/predicted_residual_fraction");
    CHECK(predicted >= 0.0 && predicted < 0.5);
    CHECK(number(ctx, report, "/timings/total") > 0.0);

    /* The reference simulation with the drain report's holes, and with none. */
    fabvdb_powder_options powder;
    fabvdb_powder_options_init(&powder);
    CHECK(powder.turns == 10 && powder.seed == 1 && powder.slope_window == 4);
    powder.turns = 3;
    powder.voxel_size = 1.0;
    fabvdb_report* simulated = NULL;
    CHECK(fabvdb_powder_simulate(ctx, drilled, fabvdb_report_json(report), &powder, &simulated) == FABVDB_OK);
    const double left = number(ctx, simulated, "/residual_fraction");
    CHECK(left >= 0.0 && left < 0.5);
    CHECK(count(ctx, simulated, "/routine") == 3);
    CHECK(fabs(number(ctx, simulated, "/routine/0/2") + 1.0) < 1e-12);
    fabvdb_report_free(simulated);
    simulated = NULL;
    fabvdb_hollow_options hollow;
    fabvdb_hollow_options_init(&hollow);
    fabvdb_mesh* undrilled = NULL;
    CHECK(fabvdb_mesh_hollow(ctx, cube, &hollow, &undrilled, NULL) == FABVDB_OK);
    CHECK(fabvdb_powder_simulate(ctx, undrilled, "{\"holes\": []}", &powder, &simulated) == FABVDB_OK);
    CHECK(number(ctx, simulated, "/residual_fraction") > 0.99);
    fabvdb_report_free(simulated);
    fabvdb_mesh_free(undrilled);

    /* Bad input and bad options leave the out-parameters untouched. */
    simulated = NULL;
    CHECK(fabvdb_powder_simulate(ctx, drilled, "{\"holes\": [{\"center\": [0, 0]}]}", &powder, &simulated) ==
          FABVDB_ERR_BAD_INPUT);
    CHECK(strstr(fabvdb_last_error(ctx), "holes[0]") != NULL && simulated == NULL);
    powder.turns = 0;
    CHECK(fabvdb_powder_simulate(ctx, drilled, fabvdb_report_json(report), &powder, &simulated) ==
          FABVDB_ERR_INVALID_ARGUMENT);
    CHECK(strstr(fabvdb_last_error(ctx), "turns") != NULL && simulated == NULL);
    fabvdb_mesh* untouched = NULL;
    fabvdb_report* untouched_report = NULL;
    options.patch_count = 5;
    CHECK(fabvdb_mesh_drain(ctx, cube, &options, &untouched, &untouched_report) == FABVDB_ERR_INVALID_ARGUMENT);
    CHECK(strstr(fabvdb_last_error(ctx), "patch_count") != NULL);
    options.patch_count = 400;
    options.repose_degrees = 90.0;
    CHECK(fabvdb_mesh_drain(ctx, cube, &options, &untouched, &untouched_report) == FABVDB_ERR_INVALID_ARGUMENT);
    options.repose_degrees = 35.0;
    CHECK(fabvdb_mesh_drain(ctx, NULL, &options, &untouched, &untouched_report) == FABVDB_ERR_INVALID_ARGUMENT);
    CHECK(untouched == NULL && untouched_report == NULL);

    CHECK(fabvdb_ctx_set_progress(ctx, cancel_at_once, NULL) == FABVDB_OK);
    CHECK(fabvdb_mesh_drain(ctx, cube, &options, &untouched, &untouched_report) == FABVDB_ERR_CANCELLED);
    CHECK(untouched == NULL && untouched_report == NULL);
    powder.turns = 3;
    powder.voxel_size = 1.0;
    CHECK(fabvdb_powder_simulate(ctx, drilled, fabvdb_report_json(report), &powder, &simulated) ==
          FABVDB_ERR_CANCELLED);
    CHECK(simulated == NULL);
    CHECK(fabvdb_ctx_set_progress(ctx, NULL, NULL) == FABVDB_OK);

    check_heat_maps(ctx, cube, options);

    fabvdb_report_free(report);
    fabvdb_mesh_free(drilled);
    fabvdb_mesh_free(cube);
    fabvdb_ctx_free(ctx);
    return check_summary();
}
