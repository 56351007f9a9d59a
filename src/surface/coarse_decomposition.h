//! The automatic decomposition loop of the thesis (Alg. 1, §3.4.3–§3.4.4):
//! starting from N_P = 2 parts (or the requested count; at least two per
//! connected piece of the surface, as regions are connected; one when the
//! shell is solid, as a solid part has no core to trap), grow N_P regions,
//! compute each part's parting line for the region's direction, and add a
//! part until the total moldability energy Σ E_P is below γ and every part's
//! undercut depth along its direction (undercut_depth.h) is within a bound
//! (the mold fills or half-trims such a gap, so a deep one leaves the input
//! far from the cast part even when its area, and so E_P, is small). Past the
//! first attempt under γ, at most `depth_attempts` more parts are tried for
//! depth; then the attempt under γ with the shallowest deepest undercut is kept
//! (the one with fewer parts on a tie). When no attempt gets under γ (the part
//! cap), the lowest-energy attempt is kept. Also the state a decomposition is
//! carried in through edits and output.
#pragma once

#include <vector>

#include <nlohmann/json.hpp>

#include "core/progress.h"
#include "surface/parting_line.h"
#include "surface/region_growing.h"

namespace fabvdb::surface {

struct DecompositionOptions {
    double gamma = 0.05;              //!< γ, unit-cube area
    int parts = 0;                    //!< 0: automatic (from 2 until Σ E_P < γ)
    int max_parts = 16;               //!< cap of the automatic search
    double overlap_weight = 1e6;      //!< w_O
    MoldabilityWeights weights;       //!< w_H, w_L
    int max_iterations = 20;          //!< region-growing iterations
    double smoothness_weight = 1.0;   //!< w_l of the boundary smoothing (eq. 3.3)
    int smoothing_iterations = 10;    //!< boundary-smoothing iterations (0: none)
    //! Bound on each part's undercut depth, unit-cube lengths (fraction of the
    //! longest side): 0.02 keeps half of it, what trimming may leave, within
    //! 1% of the diagonal. Infinity: no bound (the γ-only search).
    double max_undercut_depth = 0.02;
    int depth_attempts = 3;           //!< parts added past the first attempt under γ, for depth
};

struct Decomposition {
    std::vector<int> part_of_triangle;  //!< per S_low triangle
    std::vector<PartMolding> parts;
    double total_energy() const;
};

//! Spacing of the lines undercut depths are measured on: 1/200 of the longest side.
double undercut_line_spacing(const Shell& shell);

//! How deep undercuts are measured (deeper ones count as that deep): twice
//! the bound, and no less than 4% of the longest side, mm.
double undercut_reach(const Shell& shell, const DecompositionOptions& options);

//! The deepest undercut over the parts of `d` (undercut_depth.h), millimetres,
//! measured up to `reach`.
double deepest_undercut(const Shell& shell, const MoldabilityTerms& terms, const Decomposition& d, double reach);

//! Parting lines for every part of `part_of_triangle` with the given directions.
std::vector<PartMolding> parting_lines(const Shell& shell, const MoldabilityTerms& terms,
                                       const std::vector<int>& part_of_triangle, const std::vector<int>& directions,
                                       const MoldabilityWeights& weights);

//! Runs the loop; appends one record per attempt to `log` (parts, iterations,
//! region-growing cost per iteration, Σ E_P, seconds per iteration).
Decomposition coarse_decomposition(const Shell& shell, const MoldabilityTerms& terms,
                                   const DecompositionOptions& options, nlohmann::json& log, Progress& progress);

}  // namespace fabvdb::surface
