//! Synthetic meshes with a known defect, for the robustness tests: a clean
//! solid that the float coordinates of STL break, and a soup of unrelated
//! triangles that encloses nothing, a closed box with a zero-area cap.
#pragma once

#include <cstdint>

#include "core/mesh.h"

namespace fabvdb::test {

//! Box [100, 110]³ whose top face has two vertices 1e-7 mm apart in its
//! middle: a clean solid in doubles that the nearest floats (what STL
//! stores) turn degenerate, merging the two into one point.
Mesh make_box_with_close_pair();
//! `count` unrelated triangles (no shared vertex) scattered through the box
//! [0, side]³, each corner within `spread` of its triangle's centre on each
//! axis; the same for the same `seed`.
Mesh make_triangle_soup(uint32_t count, double side, double spread, unsigned seed);
//! make_box(lo, hi) with a vertex in the middle of one edge: the triangle on
//! one side of the edge is split there in two, and the other side's edge is
//! matched by a zero-area cap (the edge's ends and its midpoint). Closed and
//! consistently oriented, 14 triangles, one degenerate; the box's volume.
Mesh make_box_with_cap(const Vec3& lo, const Vec3& hi);

}  // namespace fabvdb::test
