//! A drain hole drilled from a cavity out through the wall: where it opens
//! on the cavity surface, its axis, diameter and tunnel; and whether a
//! candidate keeps the minimum distance from the holes already placed.
//! Plain data; spaced_from costs O(holes).
#pragma once

#include <cstdint>
#include <vector>

#include "core/mesh.h"

namespace fabvdb::powder {

struct DrainHole {
    uint32_t patch = 0;  //!< the patch the hole opens on
    Vec3 center{0, 0, 0};  //!< on the cavity surface
    Vec3 axis{0, 0, 1};    //!< unit, from the cavity out through the wall
    double diameter = 4.0;
    double depth = 0.0;    //!< drilled length from `center` along `axis` (through the wall and beyond)
    double through = 0.0;  //!< tunnel length from `center` along `axis` to the outer surface
    uint32_t cavity = 0;
};

//! Whether `candidate`'s centre is at least `min_center_distance` from every hole's.
bool spaced_from(const DrainHole& candidate, const std::vector<DrainHole>& holes, double min_center_distance);

}  // namespace fabvdb::powder
