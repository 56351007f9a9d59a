//! The prediction reported to the user (docs/design/drainability.md): after
//! the first (as printed) turn drains what the holes drain, each later turn
//! of a routine first lets the powder left slide down for its gravity
//! (settle_powder.h), then each open hole takes the powder above its surface
//! of repose (a sample two holes drain goes to the lower), and that powder
//! first fills the empty rim of its crater, lowest first, before leaving. The routines are drawn once with a
//! fixed seed (prediction_routines), or given (a cleaning routine).
//! Takes what the holes drain by Crater::surface (hole_set_drain.h).
//! Thread-safe; costs O(routines × later turns × (drained samples + the
//! slides)) per cavity, the routines in parallel.
#pragma once

#include <cstdint>
#include <vector>

#include "powder/hole_set_drain.h"
#include "powder/turn_samples.h"

namespace fabvdb::powder {

//! The later turns of a routine: indices into the orientation set.
using Routine = std::vector<uint32_t>;

//! The prediction's routines: 64 routines of `later_turns` turns drawn
//! uniformly from `turns` orientations (a fixed seed, the same on every machine).
std::vector<Routine> prediction_routines(size_t turns, int later_turns);

//! One cavity's powder as the first turn leaves it for the later turns: its
//! later-turn samples (powder samples, in the order TurnSamples::later_local
//! indexes), 1 on each the first turn left, how many, the volume they stand
//! for, and per turn the cavity's holes that drain anything, lowest first.
struct CavityPowder {
    uint32_t cavity = 0;
    const std::vector<uint32_t>* samples = nullptr;
    std::vector<double> start;
    double count = 0.0, retained = 0.0;
    std::vector<std::vector<size_t>> open;
    //! The volume (mm³) `fill` (powder per later-turn sample) stands for.
    double left(const std::vector<double>& fill) const;
};

CavityPowder cavity_powder(const TurnSamples& samples, const HoleSetDrain& drained, uint32_t cavity);

//! Later turn `k` on `fill` (powder per sample of `cavity`, 0 to 1): the slide, then the drain.
void predicted_turn(const TurnSamples& samples, const HoleSetDrain& drained, const CavityPowder& cavity, uint32_t k,
                    std::vector<double>& fill);

//! The expected residual (mm³) per cavity after the later turns of
//! `routines` (their mean). `left` (if not null) receives the mean powder
//! left on each powder sample at the end (mm³; zero on samples the later
//! turns skip); `per_routine` (if not null) each routine's residual summed
//! over the cavities (mm³).
std::vector<double> residual_after_routines(const TurnSamples& samples, const HoleSetDrain& drained,
                                            const std::vector<Routine>& routines, std::vector<double>* left,
                                            std::vector<double>* per_routine);

}  // namespace fabvdb::powder
