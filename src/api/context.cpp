//! C API: context, status strings, version, and the thread arena every call
//! runs in.
#include <unistd.h>

#include <tbb/task_arena.h>

#include "api/guard.h"
#include "fabvdb.h"

uint64_t fabvdb_ctx::budget_bytes() const {
    if (memory_budget) return memory_budget;
    const long pages = sysconf(_SC_PHYS_PAGES), page_size = sysconf(_SC_PAGESIZE);
    if (pages <= 0 || page_size <= 0) return uint64_t(4) << 30;
    return uint64_t(pages) * uint64_t(page_size) / 2;
}

namespace fabvdb::api {

void run_in_arena(int threads, const std::function<void()>& body) {
    if (threads <= 0) {
        body();
        return;
    }
    tbb::task_arena arena(threads);
    arena.execute(body);
}

}  // namespace fabvdb::api

extern "C" {

const char* fabvdb_status_string(fabvdb_status status) {
    switch (status) {
        case FABVDB_OK: return "ok";
        case FABVDB_ERR_INVALID_ARGUMENT: return "invalid argument";
        case FABVDB_ERR_IO: return "input/output error";
        case FABVDB_ERR_BAD_INPUT: return "bad input";
        case FABVDB_ERR_OUT_OF_BUDGET: return "memory budget exceeded";
        case FABVDB_ERR_OUT_OF_MEMORY: return "out of memory";
        case FABVDB_ERR_CANCELLED: return "cancelled";
        case FABVDB_ERR_INTERNAL: return "internal error";
        case FABVDB_ERR_NOT_FOUND: return "not found";
    }
    return "unknown status";
}

int fabvdb_version_number(void) { return FABVDB_VERSION_NUMBER; }
const char* fabvdb_version_string(void) { return FABVDB_VERSION_STRING; }

fabvdb_status fabvdb_ctx_new(fabvdb_ctx** out) {
    if (!out) return FABVDB_ERR_INVALID_ARGUMENT;
    try {
        *out = new fabvdb_ctx();
    } catch (const std::bad_alloc&) {
        return FABVDB_ERR_OUT_OF_MEMORY;
    }
    return FABVDB_OK;
}

void fabvdb_ctx_free(fabvdb_ctx* ctx) { delete ctx; }

fabvdb_status fabvdb_ctx_set_threads(fabvdb_ctx* ctx, int threads) {
    return fabvdb::api::guard(ctx, [&] {
        if (threads < 0) throw fabvdb::Error(FABVDB_ERR_INVALID_ARGUMENT, "threads must be >= 0");
        ctx->threads = threads;
    });
}

fabvdb_status fabvdb_ctx_set_memory_budget(fabvdb_ctx* ctx, uint64_t bytes) {
    return fabvdb::api::guard(ctx, [&] { ctx->memory_budget = bytes; });
}

uint64_t fabvdb_ctx_memory_budget(const fabvdb_ctx* ctx) { return ctx ? ctx->budget_bytes() : 0; }

fabvdb_status fabvdb_ctx_set_progress(fabvdb_ctx* ctx, fabvdb_progress_fn fn, void* user) {
    return fabvdb::api::guard(ctx, [&] {
        ctx->progress_fn = fn;
        ctx->progress_user = user;
    });
}

void fabvdb_ctx_cancel(fabvdb_ctx* ctx) {
    if (ctx) ctx->cancel_requested.store(true);
}

const char* fabvdb_last_error(const fabvdb_ctx* ctx) { return ctx ? ctx->last_error.c_str() : ""; }

}  // extern "C"
