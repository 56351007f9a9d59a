//! The powder a routine has left, slid down when the part is turned: at the
//! start of a later turn, from the lowest sample up, each later-turn
//! sample's powder slides down the slopes steeper than the angle of repose
//! (TurnSamples::later_slides), each step to the deepest neighbour with
//! room, and fills the sample where that path ends; what finds no room
//! stays. So powder falls and runs down steep walls into the pits below,
//! piles up at about the angle of repose, and stays on floors and in flat
//! tubes. Takes and gives `fill` as drain_prediction.h does (powder per
//! later-turn sample of `cavity`, 0 to 1, in TurnSamples::later_local's
//! order); keeps its sum. Costs O(samples with powder × path length × 26);
//! thread-safe.
#pragma once

#include <cstdint>
#include <vector>

#include "powder/turn_samples.h"

namespace fabvdb::powder {

void settle_powder(const TurnSamples& samples, uint32_t turn, uint32_t cavity, std::vector<double>& fill);

}  // namespace fabvdb::powder
