//! The baseline to beat: drain holes at the lowest points of each cavity in
//! the first (printing) orientation, as tools place them today. Takes the
//! candidate sites, how many holes each cavity gets, gravity and the minimum
//! distance between hole centres; returns per cavity its lowest candidates
//! (indices into `candidates`), lowest first, each spaced from those
//! already taken.
#pragma once

#include <vector>

#include "powder/drain_hole.h"

namespace fabvdb::powder {

std::vector<size_t> baseline_holes(const std::vector<DrainHole>& candidates, const std::vector<int>& per_cavity,
                                      const Vec3& gravity, double min_center_distance);

}  // namespace fabvdb::powder
