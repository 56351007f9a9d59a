//! The surface of a swept level set (sweep.h) as a triangle mesh that is an
//! exact double height field along the grid's index z axis (the parting
//! direction d): every line parallel to d crosses it at most twice, by
//! construction, which an iso-surface extractor does not promise. Each index
//! column (i, j) gives the interval where it is inside (one inside run, the
//! zero crossings linearly interpolated: where other parts split a column,
//! the run column_runs.h keeps); the shadow of the part is
//! the zero contour of the column minimum (a 2D distance to the shadow), found
//! by marching squares with separated saddles; each marching-squares polygon
//! is fanned from an inside column and lifted twice, to the column tops
//! (facing +d) and to the column bottoms (facing −d), the two sheets sharing
//! the contour vertices. The result is closed, 2-manifold, outward, without
//! faces parallel to d, without shells under an eighth of a voxel³ or flat
//! (mesh_shells.h), and in world coordinates. Cancellable.
#pragma once

#include <openvdb/openvdb.h>

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::volume {

//! `swept`: a level set on a linear transform (sweep_double_height_field's
//! result). `kept_surface`: a level set whose zero crossings a column's kept
//! run should hold (the input surface; nullptr: the longest run). An empty
//! mesh when no column is inside or only noise is (the part vanished).
Mesh double_height_field_mesh(const openvdb::FloatGrid& swept, Progress& progress,
                              const openvdb::FloatGrid* kept_surface = nullptr);

}  // namespace fabvdb::volume
