//! The decomposition options of the C API turned into the core's settings,
//! shared by fabvdb_mesh_decompose and the decomposition sessions
//! (implemented in decompose_api.cpp).
#pragma once

#include "api/context.h"
#include "surface/decompose.h"

namespace fabvdb::api {

//! `options`, or the defaults (filled into `defaults`) when it is NULL;
//! throws Error(INVALID_ARGUMENT) when its struct_size is not set.
const fabvdb_decompose_options& decompose_options_or_defaults(const fabvdb_decompose_options* options,
                                                              fabvdb_decompose_options& defaults);

//! Validates every field (Error(INVALID_ARGUMENT) naming it) and fills the
//! settings; the shell thickness default comes from the mesh's longest side.
surface::DecomposeSettings decompose_settings(const fabvdb_ctx* ctx, const Mesh& mesh,
                                              const fabvdb_decompose_options& options);

}  // namespace fabvdb::api
