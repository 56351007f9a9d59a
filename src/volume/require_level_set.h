//! The check every operation on a given level set starts with: the grid is a
//! level set (grid class) with uniform voxels (edges equal to 1e-6 of their
//! length, in any rotated frame and at any scale), or an INVALID_ARGUMENT Error
//! names what it was ("the part", "a keep-out solid").
#pragma once

#include <openvdb/openvdb.h>

namespace fabvdb::volume {

void require_level_set(const openvdb::FloatGrid& grid, const char* what);

}  // namespace fabvdb::volume
