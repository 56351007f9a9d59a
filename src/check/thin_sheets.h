//! Which thin regions of a surface are fins: thin walls held along one edge
//! and free otherwise (they break or warp), told apart from walls held along
//! their whole boundary (a panel in a frame, the walls of a closed or a
//! thin-walled box). A thin region (surface triangles under the wall limit,
//! joined through vertices) ends where the part grows thick: that line is
//! where the wall is held. A fin's two faces and its free rim are one region
//! whose border is a single loop around its root; a panel's two faces are
//! two regions, each bordered by a loop around the frame; a tray's thin
//! walls one region with two loops (outside and inside foot); a wholly thin
//! shell none. So the faces of one sheet are gathered first — regions whose
//! medial points (the ball centres the thickness walk reached) lie within a
//! cell of each other — and a sheet is a fin when its regions' borders make
//! exactly one loop of at least `min_loop` mm (shorter loops are the
//! threshold's ragged islands, not where a wall is held) and it wraps
//! around its rim: its faces look both ways, the sum of its area-weighted
//! normals under half its area (a patch read thin on one face only is no
//! free-standing wall). A rounded convex edge reads the thickness of the
//! wall behind it (local_thickness.h), so it forms no thin region at all. Pure; linear in the regions' size (a hash of
//! their medial points, 27 look-ups per vertex).
#pragma once

#include <cstdint>
#include <vector>

#include "core/mesh.h"
#include "surface/triangle_regions.h"

namespace fabvdb::check {

struct SheetReading {
    int sheet = 0;       //!< the index of the sheet the region belongs to (its faces gathered)
    int held_edges = 0;  //!< the border loops of that sheet: where it is held
    bool two_sided = false;  //!< its faces look both ways (it wraps around a rim or a shell)
    bool fin = false;    //!< held along one edge only, and two-sided
};

//! One reading per region; `centre`: per surface vertex, its medial point.
std::vector<SheetReading> thin_sheets(const Mesh& surface, const std::vector<surface::TriangleRegion>& regions,
                                      const std::vector<Vec3>& centre, double cell, double min_loop);

}  // namespace fabvdb::check
