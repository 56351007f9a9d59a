//! The whole mold decomposition of an input mesh (thesis Alg. 1 up to mold
//! generation): pre-computation (shell, moldability terms), the automatic
//! decomposition loop, boundary smoothing, then the user's edits in order. Returns everything
//! the output files and the report need; a cancelled run throws
//! Error(CANCELLED) and returns nothing.
#pragma once

#include <cmath>
#include <vector>

#include <nlohmann/json.hpp>

#include "surface/coarse_decomposition.h"
#include "surface/decomposition_edits.h"
#include "surface/shell.h"
#include "volume/low_res_shell.h"

namespace fabvdb::surface {

struct DecomposeSettings {
    volume::LowResShellOptions shell;
    double draft_radians = M_PI / 180.0;
    DecompositionOptions decomposition;
};

struct DecomposeResult {
    Shell shell;
    MoldabilityTerms terms;
    Decomposition decomposition;
    nlohmann::json report;  //!< figures and timings (see fabvdb_mesh_decompose)
};

DecomposeResult decompose_mesh(const Mesh& input, const DecomposeSettings& settings, const std::vector<Edit>& edits,
                               Progress& progress);

}  // namespace fabvdb::surface
