//! The state behind the opaque handles of the C API: the context (threads,
//! memory budget, progress callback, cancel flag, last error), and the mesh,
//! volume and report handles, each a thin box around a core value.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "core/mesh.h"
#include "core/progress.h"
#include "fabvdb.h"

struct fabvdb_ctx {
    int threads = 0;
    uint64_t memory_budget = 0;  // 0: the default
    fabvdb_progress_fn progress_fn = nullptr;
    void* progress_user = nullptr;
    std::atomic<bool> cancel_requested{false};
    std::string last_error;

    //! A Progress bound to this context's callback and cancel flag.
    fabvdb::Progress make_progress() { return fabvdb::Progress(progress_fn, progress_user, &cancel_requested); }
    uint64_t budget_bytes() const;
};

struct fabvdb_mesh {
    fabvdb::Mesh mesh;
    //! Made by fabvdb as the boundary of a solid (repair, hollow, drain,
    //! extraction): fabvdb_mesh_write checks it as written (write_solid_mesh.h).
    bool solid = false;
    //! What messages call it: the file it was read from, else "mesh".
    std::string name = "mesh";
    std::vector<double> flat_vertices;
    std::vector<uint32_t> flat_triangles;
    //! Fills the flat arrays the accessors hand out.
    void flatten();
};

struct fabvdb_report {
    nlohmann::json document;
    std::string text;
};

namespace fabvdb::api {

//! Wraps a finished mesh in a new handle (flattened for the accessors);
//! `solid`: fabvdb made it as the boundary of a solid (see fabvdb_mesh).
fabvdb_mesh* new_mesh_handle(Mesh mesh, bool solid = false);
//! Wraps a finished JSON document in a new report handle.
fabvdb_report* new_report_handle(nlohmann::json document);

}  // namespace fabvdb::api
