// A level set of a clean closed mesh by OpenVDB's own meshToLevelSet (3-voxel
// half band), for tests that need a solid without going through the repair.
#pragma once

#include <openvdb/openvdb.h>

#include "core/mesh.h"

namespace fabvdb::test {

openvdb::FloatGrid::Ptr plain_level_set(const Mesh& mesh, double voxel);
//! The same on any linear transform (e.g. one turned to a parting direction).
openvdb::FloatGrid::Ptr plain_level_set(const Mesh& mesh, const openvdb::math::Transform& transform);
//! The same with a half band of `half_band` mm on each side.
openvdb::FloatGrid::Ptr plain_level_set(const Mesh& mesh, double voxel, double half_band);

}  // namespace fabvdb::test
