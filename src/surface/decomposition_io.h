//! Writing a mold decomposition into a folder (atomically: the files are
//! written into a new folder beside it, which is renamed into place at the
//! end, replacing an older one):
//!  - decomposition.json: γ, ω, draft, weights, total energy; S_low with its
//!    inner vertices and thin labels; per part its id, parting direction,
//!    moldability energy (E_H, E_L), area, prisms (S_low triangles), its
//!    closed surface with the M⁺/M⁻ label of each triangle, the parting-line
//!    polylines and the part-boundary polylines (world mm) — all that mold
//!    generation needs;
//!  - decomposition.ply: the input surface coloured by part, M⁻ a darker
//!    shade of M⁺ so the parting lines show;
//!  - deformation.ply: S_low coloured by the estimated deformation (the
//!    energy share per area, blue low to red high, §3.5), with the value as a
//!    face property.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "surface/coarse_decomposition.h"

namespace fabvdb::surface {

//! The parting lines (edges between M⁺ and M⁻ triangles of the part's
//! closed surface) and the part boundaries (outer edges of its prisms whose
//! neighbour is in another part) of part `p`, chained into polylines (world
//! mm; a closed loop repeats its first point).
struct PartLines {
    std::vector<std::vector<Vec3>> parting;
    std::vector<std::vector<Vec3>> boundaries;
};
PartLines part_lines(const Shell& shell, const Decomposition& decomposition, size_t p);

//! Per S_low triangle: whether its outer face is in M⁺ of its part.
std::vector<char> outer_upper(const Shell& shell, const Decomposition& decomposition);

//! Per S_low triangle: the estimated deformation (§3.5), its share of the
//! weighted moldability energy per unit-cube area.
std::vector<float> deformation_density(const Shell& shell, const MoldabilityTerms& terms,
                                       const Decomposition& decomposition, const DecompositionOptions& options);

//! The decomposition.json document.
nlohmann::json decomposition_document(const Shell& shell, const MoldabilityTerms& terms,
                                      const Decomposition& decomposition, const DecompositionOptions& options);

//! Writes the three files into `folder`; throws Error(IO) naming the path.
void write_decomposition(const std::string& folder, const Mesh& input, const Shell& shell,
                         const MoldabilityTerms& terms, const Decomposition& decomposition,
                         const DecompositionOptions& options);

}  // namespace fabvdb::surface
