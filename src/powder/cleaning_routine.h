//! A cleaning routine in words, for the person who removes the powder:
//! for each turn of a routine (the first as printed, then the later turns'
//! gravities, all in the part's coordinates), which hole points down (the
//! hole whose axis lies within 60° of gravity and closest to it; otherwise
//! none, and the lowest hole is named), and how to turn the part from the
//! previous step (the tilt and the axis it turns about, in the part's
//! coordinates). Holes are numbered from 1 in the words, from 0 in
//! `hole_down`. Costs O(turns × holes).
#pragma once

#include <string>
#include <vector>

#include "core/mesh.h"
#include "powder/drain_hole.h"

namespace fabvdb::powder {

struct CleaningStep {
    Vec3 gravity{0, 0, -1};
    int hole_down = -1;       //!< -1: no hole points down
    int lowest_hole = -1;     //!< the hole lowest along gravity (-1: no hole)
    double tilt_degrees = 0.0;  //!< from the previous step's gravity
    Vec3 tilt_axis{0, 0, 0};    //!< unit (zero for no tilt, or a half turn's any axis)
    std::string instruction;
};

std::vector<CleaningStep> cleaning_steps(const std::vector<DrainHole>& holes, const Vec3& first_gravity,
                                         const std::vector<Vec3>& later_gravities);

}  // namespace fabvdb::powder
