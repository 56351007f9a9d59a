//! The drain-hole search: chooses holes among candidate sites to minimise
//! the residual powder the model predicts. The candidates are grouped around
//! representatives at least `min_center_distance` apart. Greedy: each step
//! evaluates representatives exactly (DrainabilityModel::residual_with, in
//! parallel) in the order of their last gain, lazily — a gain found is kept
//! as the bound of later steps, and the step stops once the best fresh gain
//! beats every bound left — then the best site among the chosen group's
//! members. First each cavity gets its minimum number of holes, then holes
//! go anywhere, up to `hole_count` (or, with hole_count 0, until the
//! predicted residual is under `target_residual_fraction` or a hole no longer
//! helps). Then local swaps: each hole in turn moves to the best candidate
//! within half of `min_center_distance` of it if that lowers the predicted
//! residual. In automatic mode, holes are then added while the prediction
//! (the evaluation below) is still over the target.
//! The residuals the search compares are the model's with the crater's
//! cone in the later turns (DrainabilityModel::Crater::cone; see
//! hole_search.cpp for why); the result's evaluation is the model's
//! prediction (the surface of repose).
//! Holes keep `min_center_distance` between centres. Cancellable
//! (Error(CANCELLED)).
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
};

struct HoleSearchResult {
    std::vector<DrainHole> holes;
    DrainEvaluation evaluation;
    int swaps = 0;
};

HoleSearchResult search_drain_holes(const DrainabilityModel& model, const std::vector<DrainHole>& candidates,
                                    uint32_t cavity_count, const HoleSearchOptions& options, Progress& progress);

}  // namespace fabvdb::powder
