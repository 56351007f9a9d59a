//! The pre-computation of the mold decomposition from an input mesh (thesis
//! §3.4.2): the low-resolution shell from the volume pipeline
//! (volume::low_res_shell: robust signed distance, S_low, prism inner
//! vertices along −∇φ), checked and indexed as a Shell, with the input and
//! its nearest S_low triangles (undercuts are measured on the input) and the
//! thin-feature segments from the medial depths (none when solid).
//! Cancellable.
#pragma once

#include <nlohmann/json.hpp>

#include "core/progress.h"
#include "surface/shell.h"
#include "volume/low_res_shell.h"

namespace fabvdb::surface {

//! `stats` (may be null) receives voxel size, band, triangle counts, thin
//! segment count and seconds per stage.
Shell shell_from_mesh(const Mesh& input, const volume::LowResShellOptions& options, Progress& progress,
                      nlohmann::json* stats);

}  // namespace fabvdb::surface
