//! Where to start a row of evenly spaced grid lines so that they keep as far
//! as they can from a set of coordinates. The mold's parting-surface grid
//! and its channel walls follow such lines; a line through the part's
//! vertices lays the parting surface's edges in the plane of the part's
//! silhouette walls, and where those walls lie in that plane only within
//! rounding (the extreme contour vertices of a part meshed on a voxel grid
//! whose planes the mold frame keeps, some a float step off), the exact
//! booleans leave slivers a rounding error wide that no double or float
//! coordinates can hold apart. Pure function.
#pragma once

#include <vector>

namespace fabvdb::surface {

//! The origin o in (start − step, start] of the lines o + i·step (i ∈ ℤ)
//! whose distance to the nearest of `coordinates` is largest: the middle of
//! the widest gap between the coordinates taken modulo `step`. `start` when
//! there are no coordinates. Throws Error(INVALID_ARGUMENT) unless step > 0
//! and every value is finite.
double clear_grid_origin(const std::vector<double>& coordinates, double start, double step);

}  // namespace fabvdb::surface
