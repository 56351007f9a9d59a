//! The automatic decomposition loop of the thesis (Alg. 1, §3.4.3–§3.4.4):
//! starting from N_P = 2 parts (or the requested count; at least two per
//! connected piece of the surface, as regions are connected; one when the
//! shell is solid, as a solid part has no core to trap), grow N_P regions,
//! compute each part's parting line for the region's direction, and add a
//! part until the total moldability energy Σ E_P is below γ (or the part cap
//! is reached, which keeps the lowest-energy attempt). Also the state a
//! decomposition is carried in through edits and output.
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
};

struct Decomposition {
    std::vector<int> part_of_triangle;  //!< per S_low triangle
    std::vector<PartMolding> parts;
    double total_energy() const;
};

//! Parting lines for every part of `part_of_triangle` with the given directions.
std::vector<PartMolding> parting_lines(const Shell& shell, const MoldabilityTerms& terms,
                                       const std::vector<int>& part_of_triangle, const std::vector<int>& directions,
                                       const MoldabilityWeights& weights);

//! Runs the loop; appends one record per attempt to `log` (parts, iterations,
//! region-growing cost per iteration, Σ E_P, seconds per iteration).
Decomposition coarse_decomposition(const Shell& shell, const MoldabilityTerms& terms,
                                   const DecompositionOptions& options, nlohmann::json& log, Progress& progress);

}  // namespace fabvdb::surface
