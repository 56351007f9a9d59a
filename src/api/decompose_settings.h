//! The decomposition options of the C API turned into the core's settings,
//! and the fidelity gate on the surface the parts are cut from, shared by
//! fabvdb_mesh_decompose and the decomposition sessions (implemented in
//! decompose_api.cpp). Callers read the caller's struct with
//! api::options_from (options.h).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "api/context.h"
#include "core/progress.h"
#include "surface/decompose.h"

namespace fabvdb::api {

//! Validates every field (Error(INVALID_ARGUMENT) naming it) and fills the
//! settings; the shell thickness default comes from the mesh's longest side.
surface::DecomposeSettings decompose_settings(const fabvdb_ctx* ctx, const Mesh& mesh,
                                              const fabvdb_decompose_options& options);

//! S_low must still be the input's model (volume/input_fidelity.h): far is
//! twice its mean edge, and at most 5% of the input's surface may be
//! (features under an edge's length are not in it). Returns the report's
//! section; throws Error(INTERNAL) naming `name` when it fails.
nlohmann::json require_faithful_low_res(const Mesh& input, const Mesh& low_res, const std::string& name,
                                        Progress& progress);

}  // namespace fabvdb::api
