//! A level set from a dense block of signed distances: the block copied into
//! a grid on `transform`, and values at or beyond the background made
//! inactive ±background, so the narrow band is a band again. The sign of
//! every sample is kept exactly (no rebuild through a mesh, which would move
//! the surface by a fraction of a voxel).
#pragma once

#include <openvdb/openvdb.h>
#include <openvdb/tools/Dense.h>

#include "core/progress.h"

namespace fabvdb::volume {

openvdb::FloatGrid::Ptr dense_level_set(const openvdb::tools::Dense<float>& block,
                                        const openvdb::math::Transform& transform, float background,
                                        const Progress& progress);

}  // namespace fabvdb::volume
