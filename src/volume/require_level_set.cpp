//! The level-set precondition (see require_level_set.h).
#include "volume/require_level_set.h"

#include <cmath>
#include <string>

#include "core/error.h"

namespace fabvdb::volume {

void require_level_set(const openvdb::FloatGrid& grid, const char* what) {
    // Voxel edges of equal length, relative to their size: OpenVDB's own
    // test (hasUniformVoxels) calls some exactly cubic rotated frames of
    // small voxels non-uniform (see level_set_volume.h).
    const openvdb::Vec3d size = grid.voxelSize();
    const bool uniform = size[0] > 0 && std::abs(size[1] - size[0]) <= 1e-6 * size[0] &&
                         std::abs(size[2] - size[0]) <= 1e-6 * size[0];
    if (grid.getGridClass() != openvdb::GRID_LEVEL_SET || !uniform)
        throw Error(FABVDB_ERR_INVALID_ARGUMENT, std::string(what) + " is not a level set with uniform voxels");
}

}  // namespace fabvdb::volume
