//! A level set carried onto another transform by sampling: every voxel of
//! the new transform next to the image of a voxel of the band is sampled
//! trilinearly in the source, values at or beyond the background leave the
//! band, and the inside gets its sign by flood fill. Unlike
//! openvdb::tools::resampleToMatch on level sets, which meshes the surface
//! and voxelizes the mesh again, the cost grows with the band's voxels only
//! (about 8 marks and one sample per voxel); the values are the source's
//! interpolated distances, not distances to the interpolated surface.
//! Takes a level set (GRID_LEVEL_SET) with a closed band and a transform
//! with cubic voxels no smaller than the grid's (else
//! Error(INVALID_ARGUMENT)); keeps the background and name. Cancellable.
#pragma once

#include <openvdb/openvdb.h>

#include "core/progress.h"

namespace fabvdb::volume {

openvdb::FloatGrid::Ptr resample_level_set(const openvdb::FloatGrid& grid, const openvdb::math::Transform& transform,
                                           const Progress& progress);

}  // namespace fabvdb::volume
