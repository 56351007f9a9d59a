//! The draft/undercut map of S_low for one pulling direction d (any unit
//! vector, not only the 162 candidates), as a mold designer reads it: each
//! triangle is `positive` (n·d ≥ sin φ: it releases from the mold half that
//! is pulled along +d), `negative` (n·d ≤ −sin φ: the half pulled along −d),
//! `needs_draft` (|n·d| < sin φ: a wall steeper than the draft angle φ) or
//! `undercut` (the ray from its centroid along the side it faces, ±d, hits
//! S_low again, so the mold half cannot be pulled off it). Rays are cast
//! against a CGAL AABB tree of S_low, built per call: O(N log N) for N
//! triangles, a few milliseconds at N = 10 000.
#pragma once

#include <cstdint>
#include <vector>

#include "surface/shell.h"

namespace fabvdb::surface {

enum DraftClass : uint8_t { draft_positive = 0, draft_negative = 1, needs_draft = 2, undercut = 3 };

//! One class per S_low triangle. `direction`: non-zero; `draft_radians` in [0, π/2).
std::vector<uint8_t> draft_map(const Shell& shell, const Vec3& direction, double draft_radians);

}  // namespace fabvdb::surface
