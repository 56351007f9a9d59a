//! The parting line of one part (thesis §3.4.4): a graph cut over the part's
//! closed surface (Boykov–Kolmogorov max-flow) labels each triangle M⁺ (top
//! mold) or M⁻ (bottom mold) with the unary costs 1 + n·d (for M⁻) and
//! 1 − n·d (for M⁺), zero on inner triangles, and the binary cost
//! max(0, n₀·n₁) across each edge. The connectivity fix-up then splits the
//! labels by overlap, builds the graph of their connected components with the
//! asymmetric cost |p_d(c)| of relabelling a component, fixes the largest M⁺
//! and M⁻ components (projected area), and in decreasing projected area joins
//! every other component to the nearer of the two along the cheapest path,
//! relabelling and fixing the path — so M⁺ and M⁻ are each one connected piece.
#pragma once

#include <memory>
#include <vector>

#include "core/progress.h"
#include "surface/moldability_energy.h"
#include "surface/part_surface.h"

namespace fabvdb::surface {

struct PartMolding {
    int direction = 0;        //!< parting direction d (index into terms.directions)
    PartSurface surface;
    std::vector<char> upper;  //!< per surface triangle: in M⁺
    MoldabilityEnergy energy;
};

//! Parting line of `part` for the given direction.
PartMolding parting_line(const Shell& shell, const MoldabilityTerms& terms, const std::vector<int>& part_of_triangle,
                         int part, int direction, const MoldabilityWeights& weights);

//! The flow network of a part's surface, kept while the part keeps its
//! triangles but S_low's vertices move (boundary smoothing): after
//! update_part_surface, only the capacities of the changed triangles' edges
//! are set again. relabel gives what parting_line gives for the part as it
//! is now. The surface must stay in place while the network lives.
class PartNetwork {
public:
    explicit PartNetwork(const PartSurface& surface);
    ~PartNetwork();
    PartNetwork(const PartNetwork&) = delete;
    PartNetwork& operator=(const PartNetwork&) = delete;
    //! After the normals of these surface triangles changed.
    void update(const std::vector<uint32_t>& triangles);
    //! Sets molding.upper and molding.energy for molding.direction;
    //! molding.surface must be the network's surface.
    void relabel(const Shell& shell, const MoldabilityTerms& terms, const MoldabilityWeights& weights,
                 PartMolding& molding);

private:
    class Network;
    std::unique_ptr<Network> network_;
};

//! argmin_{d∈D} E_P(P, d) with the part fixed (used after cut and merge edits,
//! §3.5). d and −d give the same E_P, so the 81 axes are ranked by the E_P
//! of the labelling M⁺ = {n·d ≥ 0} (cheap: precomputed terms only) and the
//! parting line (graph cut, fix-up, energy) is computed, in parallel, for the
//! `candidates_checked` best ranked (81: all of them, the exact argmin) and
//! for the axes of the `hints` (e.g. the directions the part's triangles had
//! before a cut or merge).
PartMolding best_parting_line(const Shell& shell, const MoldabilityTerms& terms,
                              const std::vector<int>& part_of_triangle, int part, const MoldabilityWeights& weights,
                              const std::vector<int>& hints, Progress& progress, size_t candidates_checked = 12);

}  // namespace fabvdb::surface
