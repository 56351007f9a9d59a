//! Candidate drain-hole sites: one per patch, at the patch's site, drilled
//! along the patch normal out of the cavity. A site is kept when every line
//! of the drill (its axis and six lines on its rim) leaves the cavity, crosses
//! the wall once — not thinner than half the nominal wall (a thin region), not
//! longer than twice it (a solid region the hollowing left) — and then stays
//! outside the part for one diameter; and when neither end of the hole touches
//! a keep-out region. Parallel; cancellable (Error(CANCELLED)).
#pragma once

#include <vector>

#include <openvdb/openvdb.h>

#include "core/progress.h"
#include "powder/cavity_patches.h"
#include "powder/drain_hole.h"
#include "powder/keep_out.h"

namespace fabvdb::powder {

struct HoleCandidateOptions {
    double diameter = 4.0;
    double nominal_wall = 3.0;
};

//! `shell` is negative in the wall, `part` negative inside the part (cavity included).
std::vector<DrainHole> hole_candidates(const CavityPatches& patches, const openvdb::FloatGrid& shell,
                                       const openvdb::FloatGrid& part, const KeepOut& keep_out,
                                       const HoleCandidateOptions& options, Progress& progress);

}  // namespace fabvdb::powder
