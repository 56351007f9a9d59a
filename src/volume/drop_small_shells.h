//! Removal of the small solid pieces of a level set: splits the solid into
//! its connected shells (OpenVDB segmentSDF), measures each one's volume
//! (volume/level_set_volume) and keeps the union of those of at least `min_volume`
//! mm³ (0 keeps everything, and only counts the shells: the connected pieces
//! of the zero-crossing voxels, as segmentSDF splits them). The grid is
//! replaced only when something was dropped; it may become empty.
#pragma once

#include <cstdint>

#include <openvdb/openvdb.h>

#include "core/progress.h"

namespace fabvdb::volume {

struct ShellCounts {
    uint64_t kept = 0;
    uint64_t dropped = 0;
};

ShellCounts drop_small_shells(openvdb::FloatGrid::Ptr& grid, double min_volume, Progress& progress);

}  // namespace fabvdb::volume
