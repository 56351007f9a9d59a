//! The level-set precondition (see require_level_set.h).
#include "volume/require_level_set.h"

#include <string>

#include "core/error.h"

namespace fabvdb::volume {

void require_level_set(const openvdb::FloatGrid& grid, const char* what) {
    if (grid.getGridClass() != openvdb::GRID_LEVEL_SET || !grid.hasUniformVoxels())
        throw Error(FABVDB_ERR_INVALID_ARGUMENT, std::string(what) + " is not a level set with uniform voxels");
}

}  // namespace fabvdb::volume
