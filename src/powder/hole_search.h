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
//! residual.
//! The residuals the greedy phase compares are the model's with the
//! crater's cone in the later turns (DrainabilityModel::Crater::cone; see
//! hole_search.cpp for why). The prediction (the surface of repose, powder
//! sliding between turns) then judges and polishes the result: it starts from
//! whichever of the greedy holes and the lowest-point holes (as many per
//! cavity, baseline_holes.h) it predicts to leave less, moves each hole to
//! the best site within half of `min_center_distance` while the prediction
//! drops. So the holes returned are never predicted to leave more than the
//! lowest-point holes, by the prediction the result reports (its random
//! routines' mean). In automatic mode the hole count is the fewest for
//! which the prediction under the cleaning routine for the holes
//! (DrainabilityModel::best_routine) meets the target: holes are added
//! while it is over, then dropped while it stays under.
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
    //! The cleaning routine for the holes (later turns, indices into the
    //! orientation set), the prediction under it, and the prediction's
    //! residual (mm³) under each of its random routines.
    DrainabilityModel::Routine routine;
    DrainEvaluation routine_evaluation;
    std::vector<double> random_residuals;
    //! The lowest-point holes, as many per cavity as `holes`, their
    //! prediction (random routines), and the residual under their own
    //! cleaning routine (mm³).
    std::vector<DrainHole> baseline;
    DrainEvaluation baseline_evaluation;
    double baseline_routine_residual = 0.0;
    int swaps = 0;
};

//! `first_gravity`: gravity as printed, which the lowest-point holes are lowest along.
HoleSearchResult search_drain_holes(const DrainabilityModel& model, const std::vector<DrainHole>& candidates,
                                    uint32_t cavity_count, const Vec3& first_gravity, const HoleSearchOptions& options,
                                    Progress& progress);

}  // namespace fabvdb::powder
