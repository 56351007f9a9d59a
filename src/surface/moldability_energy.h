//! The moldability energy of one part (thesis eq. 3.4):
//!   E_P = w_H·E_H + w_L·E_L,
//! E_H summing U(t, d) over the visible (outer and side) triangles of M⁺ and
//! U(t, −d) over those of M⁻, E_L summing ½|p_d(t₁) ∩ p_d(t₂)| over ordered
//! pairs of outer triangles in the same patch (the precomputed overlaps).
//! Inner triangles are ignored, as the thesis does. Areas are unit-cube areas.
//! Also gives the per-S_low-triangle share of the energy (the deformation
//! estimate shown as a heat map, §3.5).
#pragma once

#include <vector>

#include "surface/moldability_terms.h"
#include "surface/part_surface.h"

namespace fabvdb::surface {

struct MoldabilityWeights {
    double overhang = 1.0;  //!< w_H
    double overlap = 1.0;   //!< w_L
};

struct MoldabilityEnergy {
    double overhang = 0;  //!< E_H
    double overlap = 0;   //!< E_L
    double total = 0;     //!< w_H·E_H + w_L·E_L
};

//! `upper[i]`: surface triangle i is in M⁺. `per_triangle` (may be null; sized
//! to the S_low triangle count by the caller) receives each outer triangle's
//! weighted share; side triangles add to the triangle they border.
MoldabilityEnergy moldability_energy(const MoldabilityTerms& terms, const PartSurface& surface,
                                     const std::vector<char>& upper, int direction,
                                     const MoldabilityWeights& weights, std::vector<double>* per_triangle);

}  // namespace fabvdb::surface
