//! Widens a level set's narrow band to `interior` voxels deep inside and
//! `exterior` voxels out by closest-point propagation: the band's voxels
//! within 1.5 voxels of the surface get a closest surface point from their
//! distance and its central differences (x − φ·∇φ/|∇φ|), then points spread
//! a layer of 26-neighbours at a time, in order of distance, each voxel
//! taking the nearest of its neighbours' points, at its distance to it, on
//! that neighbour's side, until no new voxel lies within the widths. The
//! band's own voxels keep their values. Beside flat parts of the surface
//! (the straight branches local_thickness.h fits) a new value is the true
//! distance; elsewhere within a fifth of a voxel under it and half a voxel
//! over it (a closest point inherited across the layers drifts sideways
//! inside a curved part: tests/volume/widen_band_test.cpp). Inactive values
//! are signed by flood fill (±the widths). Costs about 26 lookups per new
//! voxel, in parallel; cancellable (no partial grid).
#pragma once

#include <openvdb/openvdb.h>

#include "core/progress.h"

namespace fabvdb::volume {

openvdb::FloatGrid::Ptr widen_band(const openvdb::FloatGrid& grid, int interior, int exterior, Progress& progress);

}  // namespace fabvdb::volume
