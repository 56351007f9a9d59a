//! A cleaning routine of `length` later turns that leaves little powder by
//! the prediction (drain_prediction.h): the turns chosen one after the
//! other, each the one that leaves the least after it, or the best of the
//! `random` routines if that leaves less (so never more than their mean),
//! then each turn in turn changed to the best one while that leaves less
//! (two passes). Among turns within a millionth of the cavity volume of the
//! least, the one with the smallest tilt from the previous gravity (the
//! first turn's: as printed). Costs about turns × length² turns of the
//! prediction, the candidate turns in parallel; polls `progress` between
//! them and throws Error(CANCELLED).
#pragma once

#include <vector>

#include "core/progress.h"
#include "powder/drain_prediction.h"
#include "powder/hole_set_drain.h"
#include "powder/turn_samples.h"

namespace fabvdb::powder {

Routine best_cleaning_routine(const TurnSamples& samples, const HoleSetDrain& drained, int length,
                              const std::vector<Routine>& random, const Progress& progress);

}  // namespace fabvdb::powder
