//! What a set of drain holes drains together, turn by turn, from what each
//! drains alone (hole_reach.h), and the hole search's objective on it: the
//! expected residual per cavity when the powder the first turn leaves is
//! gathered into one pile before each later turn (pile_residual.h), for
//! `later_turns` turns drawn uniformly from the orientation set.
//! residual_with evaluates one hole more without building the set again
//! (thread-safe). Costs O(holes × turns × samples / 64) to combine, and
//! O(turns × kPileLevels × later_turns) per cavity for the objective.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "powder/drain_hole.h"
#include "powder/hole_reach.h"
#include "powder/turn_samples.h"

namespace fabvdb::powder {

struct HoleSetDrain {
    std::vector<DrainHole> holes;
    //! Per cavity: bits of the first-turn samples drained, lowest first.
    std::vector<std::vector<uint64_t>> first;
    //! Per turn and cavity: bits of the drained samples, lowest first
    //! (empty: none), and the set bits before each word.
    std::vector<std::vector<std::vector<uint64_t>>> later;
    std::vector<std::vector<std::vector<uint32_t>>> later_before;
    //! What each hole drains alone (`holes[h]`'s is `reaches[h]`), shared
    //! with whoever computed it.
    std::vector<std::shared_ptr<const HoleReach>> reaches;
    std::vector<uint32_t> retained_first;  //!< per cavity: samples left after the first turn
    std::vector<double> residual_per_cavity;  //!< mm³, by the search's objective
    double drained_first_volume = 0.0;
};

//! `reaches[h]` is `holes[h]`'s.
HoleSetDrain hole_set_drain(const TurnSamples& samples, const std::vector<DrainHole>& holes,
                            const std::vector<std::shared_ptr<const HoleReach>>& reaches, int later_turns);

//! The objective's residual volume (mm³) of `drain`'s holes plus the hole
//! that reaches `extra`, without changing `drain`.
double residual_with(const TurnSamples& samples, const HoleSetDrain& drain, const HoleReach& extra, int later_turns);

}  // namespace fabvdb::powder
