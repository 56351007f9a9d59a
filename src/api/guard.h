//! The exception firewall around every exported function body: runs `body`
//! inside the context's thread arena and turns any exception into a status and
//! the context's last-error message. Error keeps its status; std::bad_alloc is
//! out-of-memory; anything else (OpenVDB, CGAL, std) is internal. Clears the
//! cancel request when the call ends, so it applies to one call.
#pragma once

#include <functional>
#include <new>
#include <string>

#include "api/context.h"
#include "core/error.h"

namespace fabvdb::api {

//! Runs `body` with at most ctx->threads worker threads (0: all).
void run_in_arena(int threads, const std::function<void()>& body);

template <class Body>
fabvdb_status guard(fabvdb_ctx* ctx, Body&& body) {
    if (!ctx) return FABVDB_ERR_INVALID_ARGUMENT;
    fabvdb_status status = FABVDB_OK;
    try {
        ctx->last_error.clear();
        run_in_arena(ctx->threads, [&] { body(); });
    } catch (const Error& e) {
        status = e.status();
        ctx->last_error = e.what();
    } catch (const std::bad_alloc&) {
        status = FABVDB_ERR_OUT_OF_MEMORY;
        ctx->last_error = "out of memory";
    } catch (const std::exception& e) {
        status = FABVDB_ERR_INTERNAL;
        ctx->last_error = std::string("internal error: ") + e.what();
    } catch (...) {
        status = FABVDB_ERR_INTERNAL;
        ctx->last_error = "internal error: unknown exception";
    }
    ctx->cancel_requested = false;
    return status;
}

//! Throws Error(INVALID_ARGUMENT) naming `name` when `pointer` is NULL.
inline void require(const void* pointer, const char* name) {
    if (!pointer) throw Error(FABVDB_ERR_INVALID_ARGUMENT, std::string(name) + " is NULL");
}

}  // namespace fabvdb::api
