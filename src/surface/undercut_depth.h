//! The undercut depth of a part of a decomposition along a parting direction:
//! how deep the mold's sweep buries the part's outer surface where it fills a
//! gap. A line along the direction that leaves the part's outer surface and
//! enters it again, with no other part's outer surface in between, crosses a
//! gap; the sweep fills each line from the lowest to the highest point of the
//! part on it (ω under a lowest crossing that leaves the part, or over a
//! highest one that enters it: the part's prisms), and the depth of a gap's end is its distance to the nearest point
//! so filled that is not: along its own line (to the line's ends) or across
//! to the nearest line not filled at its height. The part's undercut depth is
//! the deepest such end, up to `reach`. The sweep fills such a gap or, when it
//! is deep, trims half of it (volume/trim_deep_fills.h), leaving the input
//! surface up to about half that depth from the cast part; the decomposition
//! bounds it (coarse_decomposition.h). Lines are cast on a square grid of
//! `spacing` across the part's projection (at most 512 × 512 lines: a wider
//! part gets a coarser grid) through the full-resolution input the shell
//! holds, each input triangle in the part of its nearest S_low triangle (the
//! detail S_low smooths away is what the sweep buries), or through S_low's
//! outer triangles for a shell without one (the other parts keeping nothing
//! out: an upper bound where they would); gaps narrower than the grid may be
//! missed. Costs one pass over the triangles, a sort of each line's crossings
//! and, per gap end, a look at the lines within its depth.
#pragma once

#include <vector>

#include "core/mesh.h"
#include "surface/shell.h"

namespace fabvdb::surface {

struct UndercutDepth {
    double depth = 0;      //!< millimetres (the shell's units); 0: no gap
    Vec3 at{0, 0, 0};      //!< the deepest gap end (on its line)
};

//! `direction`: unit vector. `part_of_triangle`: per outer triangle of S_low.
UndercutDepth undercut_depth(const Shell& shell, const std::vector<int>& part_of_triangle, int part,
                             const Vec3& direction, double spacing, double reach);

}  // namespace fabvdb::surface
