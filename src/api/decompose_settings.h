//! The decomposition options of the C API turned into the core's settings,
//! shared by fabvdb_mesh_decompose and the decomposition sessions
//! (implemented in decompose_api.cpp). Callers read the caller's struct with
//! api::options_from (options.h).
#pragma once

#include "api/context.h"
#include "surface/decompose.h"

namespace fabvdb::api {

//! Validates every field (Error(INVALID_ARGUMENT) naming it) and fills the
//! settings; the shell thickness default comes from the mesh's longest side.
surface::DecomposeSettings decompose_settings(const fabvdb_ctx* ctx, const Mesh& mesh,
                                              const fabvdb_decompose_options& options);

}  // namespace fabvdb::api
