//! level_set_volume: a shallow copy of the grid under a scale transform.
#include "volume/level_set_volume.h"

#include <openvdb/tools/LevelSetMeasure.h>

namespace fabvdb::volume {

double level_set_volume(const openvdb::FloatGrid& grid) {
    if (grid.activeVoxelCount() == 0) return 0.0;
    const openvdb::FloatGrid::ConstPtr scaled =
        grid.copyReplacingTransform(openvdb::math::Transform::createLinearTransform(grid.voxelSize()[0]));
    return openvdb::tools::levelSetVolume(*scaled);
}

}  // namespace fabvdb::volume
