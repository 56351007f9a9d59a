//! The coarse shell decomposition of the thesis (§3.4.3): VSA-like region
//! growing over the elements with the cost
//!   C(t, r) = −|n_t·d_r| + δ (thin feature) or −n_t·d_r + δ (otherwise),
//!   δ = w_O if t's projection along d_r overlaps a triangle already in r,
//! summed over the triangles of a no-cut element. Each iteration grows all
//! regions from their seeds (cheapest element first), then moves each region's
//! direction to argmin_{d∈D} Σ_{t∈r} C(t, r) and its seed to the cheapest
//! element, until the seeds stop changing or `max_iterations` is reached.
//! Regions are edge-connected by construction; every domain element reachable
//! from a seed is assigned.
#pragma once

#include <vector>

#include "core/progress.h"
#include "surface/elements.h"
#include "surface/moldability_terms.h"

namespace fabvdb::surface {

struct Regions {
    std::vector<int> region_of_triangle;  //!< −1 outside the domain
    std::vector<int> direction;           //!< per region: index into terms.directions
    int iterations = 0;
    std::vector<double> cost_per_iteration;  //!< Σ_r Σ_{t∈r} C(t, r) after each growth
};

//! Grows regions from `seeds` (elements) with initial `directions`.
Regions grow_regions(const Shell& shell, const MoldabilityTerms& terms, const Elements& elements,
                     std::vector<int> seeds, std::vector<int> directions, double overlap_weight,
                     int max_iterations, Progress& progress);

//! The connected pieces of the domain: elements joined by adjacency, each
//! piece's elements in the order they are reached.
std::vector<std::vector<int>> connected_pieces(const Elements& elements);

//! `count` seed elements drawn with a fixed-seed generator (reproducible runs),
//! at least one in each connected piece of the domain while count allows (two
//! when there are several pieces: a closed piece needs two parts); the
//! initial direction of each is the candidate closest to its triangle normal.
void random_seeds(const Shell& shell, const MoldabilityTerms& terms, const Elements& elements, int count,
                  std::vector<int>& seeds, std::vector<int>& directions);

//! The candidate direction closest to `v`.
int closest_direction(const MoldabilityTerms& terms, const Vec3& v);

}  // namespace fabvdb::surface
