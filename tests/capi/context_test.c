/* context_test.c — the context through fabvdb.h only: the status texts the
 * header quotes, the version number computed here from the version string,
 * the default memory budget (half the physical memory, from sysconf here),
 * a set budget and 0 going back to the default, a budget too small for a
 * volume refused before allocating; thread counts (negative refused naming
 * the field); NULL contexts refused; last-error messages per context, cleared
 * by the next call; the progress callback called on the caller's thread with
 * a stage and a fraction in [0, 1], and no more once cleared; cancellation by
 * the callback or by fabvdb_ctx_cancel for one call only; handles that stay
 * valid after their context is freed. */
#define _DEFAULT_SOURCE
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "box_mesh.h"
#include "check.h"
#include "fabvdb.h"

static const double lo[3] = {0, 0, 0}, hi[3] = {10, 10, 10};

struct progress_log {
    int calls;
    int bad_calls; /* a NULL stage, a fraction outside [0, 1] or another thread */
    int cancel;    /* what the callback returns */
    pthread_t caller;
};

static int log_progress(void* user, const char* stage, double fraction) {
    struct progress_log* log = user;
    ++log->calls;
    if (!stage || !(fraction >= 0.0 && fraction <= 1.0) || !pthread_equal(pthread_self(), log->caller)) ++log->bad_calls;
    return log->cancel;
}

/* fabvdb_volume_from_mesh of the cube at 0.25 mm voxels: a call that reports progress. */
static fabvdb_status volume_call(fabvdb_ctx* ctx, const fabvdb_mesh* cube, fabvdb_volume** out) {
    fabvdb_volume_options options;
    fabvdb_volume_options_init(&options);
    options.voxel_size = 0.25;
    return fabvdb_volume_from_mesh(ctx, cube, &options, out, NULL);
}

static void test_statuses_and_version(void) {
    CHECK(strcmp(fabvdb_status_string(FABVDB_OK), "ok") == 0);
    CHECK(strcmp(fabvdb_status_string(FABVDB_ERR_BAD_INPUT), "bad input") == 0);
    CHECK(fabvdb_status_string((fabvdb_status)99) != NULL);
    int major = -1, minor = -1, patch = -1;
    CHECK(sscanf(fabvdb_version_string(), "%d.%d.%d", &major, &minor, &patch) == 3);
    CHECK(fabvdb_version_number() == major * 10000 + minor * 100 + patch);
}

static void test_budget_and_threads(fabvdb_ctx* ctx) {
    const uint64_t half_memory = (uint64_t)sysconf(_SC_PHYS_PAGES) * (uint64_t)sysconf(_SC_PAGESIZE) / 2;
    CHECK(fabvdb_ctx_memory_budget(ctx) == half_memory);
    CHECK(fabvdb_ctx_set_memory_budget(ctx, 123456789) == FABVDB_OK);
    CHECK(fabvdb_ctx_memory_budget(ctx) == 123456789);
    CHECK(fabvdb_ctx_set_memory_budget(ctx, 0) == FABVDB_OK);
    CHECK(fabvdb_ctx_memory_budget(ctx) == half_memory);
    CHECK(fabvdb_ctx_memory_budget(NULL) == 0);

    fabvdb_mesh* cube = new_box(ctx, lo, hi, 0);
    fabvdb_volume* volume = NULL;
    CHECK(fabvdb_ctx_set_memory_budget(ctx, 1024) == FABVDB_OK);
    CHECK(volume_call(ctx, cube, &volume) == FABVDB_ERR_OUT_OF_BUDGET && volume == NULL);
    CHECK(strstr(fabvdb_last_error(ctx), "voxel") != NULL);
    CHECK(fabvdb_ctx_set_memory_budget(ctx, 0) == FABVDB_OK);

    CHECK(fabvdb_ctx_set_threads(ctx, -2) == FABVDB_ERR_INVALID_ARGUMENT);
    CHECK(strstr(fabvdb_last_error(ctx), "threads") != NULL);
    /* One worker thread, then all: the same volume either way. */
    CHECK(fabvdb_ctx_set_threads(ctx, 1) == FABVDB_OK);
    CHECK(strcmp(fabvdb_last_error(ctx), "") == 0);
    CHECK(volume_call(ctx, cube, &volume) == FABVDB_OK);
    fabvdb_mesh* one = NULL;
    CHECK(fabvdb_volume_to_mesh(ctx, volume, NULL, &one) == FABVDB_OK);
    fabvdb_volume_free(volume);
    CHECK(fabvdb_ctx_set_threads(ctx, 0) == FABVDB_OK);
    volume = NULL;
    CHECK(volume_call(ctx, cube, &volume) == FABVDB_OK);
    fabvdb_mesh* all = NULL;
    CHECK(fabvdb_volume_to_mesh(ctx, volume, NULL, &all) == FABVDB_OK);
    CHECK(fabs(mesh_signed_volume(one) - mesh_signed_volume(all)) < 1e-9);
    CHECK(fabs(mesh_signed_volume(all) - 1000.0) < 10.0);
    fabvdb_mesh_free(one);
    fabvdb_mesh_free(all);
    fabvdb_volume_free(volume);
    fabvdb_mesh_free(cube);
}

static void test_null_contexts_and_messages(void) {
    CHECK(fabvdb_ctx_new(NULL) == FABVDB_ERR_INVALID_ARGUMENT);
    CHECK(fabvdb_ctx_set_threads(NULL, 1) == FABVDB_ERR_INVALID_ARGUMENT);
    CHECK(fabvdb_ctx_set_memory_budget(NULL, 1) == FABVDB_ERR_INVALID_ARGUMENT);
    CHECK(fabvdb_ctx_set_progress(NULL, log_progress, NULL) == FABVDB_ERR_INVALID_ARGUMENT);
    CHECK(strcmp(fabvdb_last_error(NULL), "") == 0);
    fabvdb_ctx_cancel(NULL);
    fabvdb_ctx_free(NULL);

    fabvdb_ctx *a = NULL, *b = NULL;
    CHECK(fabvdb_ctx_new(&a) == FABVDB_OK && fabvdb_ctx_new(&b) == FABVDB_OK);
    CHECK(fabvdb_ctx_set_threads(a, -1) == FABVDB_ERR_INVALID_ARGUMENT);
    CHECK(strlen(fabvdb_last_error(a)) > 0);
    CHECK(strcmp(fabvdb_last_error(b), "") == 0); /* each context has its own */
    fabvdb_ctx_free(a);
    fabvdb_ctx_free(b);
}

static void test_progress_and_cancel(fabvdb_ctx* ctx) {
    fabvdb_mesh* cube = new_box(ctx, lo, hi, 0);
    struct progress_log log = {0, 0, 0, pthread_self()};
    CHECK(fabvdb_ctx_set_progress(ctx, log_progress, &log) == FABVDB_OK);
    fabvdb_volume* volume = NULL;
    CHECK(volume_call(ctx, cube, &volume) == FABVDB_OK);
    CHECK(log.calls > 0 && log.bad_calls == 0);
    fabvdb_volume_free(volume);

    /* The callback asks to cancel: no result. */
    log.cancel = 1;
    log.calls = 0;
    volume = NULL;
    CHECK(volume_call(ctx, cube, &volume) == FABVDB_ERR_CANCELLED && volume == NULL);
    CHECK(log.calls >= 1);

    /* Cleared: no more calls. */
    CHECK(fabvdb_ctx_set_progress(ctx, NULL, NULL) == FABVDB_OK);
    log.calls = 0;
    CHECK(volume_call(ctx, cube, &volume) == FABVDB_OK && log.calls == 0);
    fabvdb_volume_free(volume);

    /* A request before a call cancels that call only. */
    fabvdb_ctx_cancel(ctx);
    volume = NULL;
    CHECK(volume_call(ctx, cube, &volume) == FABVDB_ERR_CANCELLED && volume == NULL);
    CHECK(volume_call(ctx, cube, &volume) == FABVDB_OK && volume != NULL);
    fabvdb_volume_free(volume);
    fabvdb_mesh_free(cube);
}

static void test_handles_outlive_their_context(void) {
    fabvdb_ctx* first = NULL;
    CHECK(fabvdb_ctx_new(&first) == FABVDB_OK);
    fabvdb_mesh* cube = new_box(first, lo, hi, 0);
    fabvdb_report* report = NULL;
    CHECK(fabvdb_mesh_inspect(first, cube, &report) == FABVDB_OK);
    fabvdb_ctx_free(first);
    fabvdb_ctx* second = NULL;
    CHECK(fabvdb_ctx_new(&second) == FABVDB_OK);
    CHECK(fabvdb_mesh_triangle_count(cube) == 12 && fabs(mesh_signed_volume(cube) - 1000.0) < 1e-9);
    CHECK(fabs(report_value(second, report, "/volume") - 1000.0) < 1e-9);
    fabvdb_report* again = NULL;
    CHECK(fabvdb_mesh_inspect(second, cube, &again) == FABVDB_OK);
    CHECK(fabs(report_value(second, again, "/volume") - 1000.0) < 1e-9);
    fabvdb_report_free(again);
    fabvdb_report_free(report);
    fabvdb_mesh_free(cube);
    fabvdb_ctx_free(second);
}

int main(void) {
    test_statuses_and_version();
    test_null_contexts_and_messages();
    fabvdb_ctx* ctx = NULL;
    if (fabvdb_ctx_new(&ctx) != FABVDB_OK) return 1;
    test_budget_and_threads(ctx);
    test_progress_and_cancel(ctx);
    fabvdb_ctx_free(ctx);
    test_handles_outlive_their_context();
    return check_summary();
}
