//! The unsigned distance to a mesh within `half_band` voxels of it
//! (OpenVDB meshToVolume, UNSIGNED_DISTANCE_FIELD), on `transform`, and,
//! into `closest_triangle` when given, the index of the triangle nearest to
//! each voxel. Takes any triangles (open, crossing); guarantees active
//! voxels only within the band. Costs one meshToVolume. Cancellable.
#pragma once

#include <openvdb/openvdb.h>

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::volume {

openvdb::FloatGrid::Ptr unsigned_band(const Mesh& mesh, const openvdb::math::Transform& transform, float half_band,
                                      Progress& progress, openvdb::Int32Grid* closest_triangle = nullptr);

}  // namespace fabvdb::volume
