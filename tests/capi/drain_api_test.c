/* drain_api_test.c — drain holes and the powder simulation from C alone: a
 * 40 mm cube hollowed with a 3 mm wall, drained with two holes (each on the
 * cavity surface, drilled outward); the report's holes read back; the
 * simulation (1 mm cells) reads the drain report and leaves less powder than
 * an undrilled hollow cube with no holes (which keeps everything); bad holes JSON is bad input; out-of-range options
 * are invalid arguments; cancellation returns no partial result. */
#define _DEFAULT_SOURCE /* POSIX: mkdtemp */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

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

    fabvdb_report_free(report);
    fabvdb_mesh_free(drilled);
    fabvdb_mesh_free(cube);
    fabvdb_ctx_free(ctx);
    return check_summary();
}
