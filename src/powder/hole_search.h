//! The drain-hole search: chooses holes among candidate sites to maximise the
//! powder the model drains. Greedy: each step ranks every allowed candidate
//! by the model's first-order gain (DrainabilityModel::estimate_gains) and
//! adds the best of the top few by exact evaluation; first each cavity gets
//! its minimum number of holes, then holes go anywhere, up to `hole_count`
//! (or, with hole_count 0, until the predicted residual is under
//! `target_residual_fraction` or a hole no longer helps). Then local swaps:
//! each hole in turn is replaced by the best candidate if that lowers the
//! predicted residual. Holes keep `min_center_distance` between centres.
//! Cancellable (Error(CANCELLED)).
#pragma once

#include <vector>

#include "core/progress.h"
#include "powder/drainability_model.h"

namespace fabvdb::powder {

struct HoleSearchOptions {
    int hole_count = 0;  //!< 0: automatic
    int min_per_cavity = 2;
    double target_residual_fraction = 0.01;
    int max_holes = 12;  //!< automatic mode's ceiling
    double min_center_distance = 8.0;
    int exact_checks = 3;  //!< top estimates evaluated exactly per step
};

struct HoleSearchResult {
    std::vector<DrainHole> holes;
    DrainEvaluation evaluation;
    int swaps = 0;
};

HoleSearchResult search_drain_holes(const DrainabilityModel& model, const std::vector<DrainHole>& candidates,
                                    uint32_t cavity_count, const HoleSearchOptions& options, Progress& progress);

}  // namespace fabvdb::powder
