//! Removal of small shells from a level set (see drop_small_shells.h).
#include "volume/drop_small_shells.h"

#include <algorithm>

#include <openvdb/tools/Composite.h>
#include <openvdb/tools/LevelSetUtil.h>

#include "core/error.h"
#include "volume/level_set_volume.h"

namespace fabvdb::volume {

ShellCounts drop_small_shells(openvdb::FloatGrid::Ptr& grid, double min_volume, Progress& progress) {
    if (!(min_volume >= 0.0)) throw Error(FABVDB_ERR_INVALID_ARGUMENT, "minimum shell volume must be >= 0");
    progress.stage("shells");
    ShellCounts counts;
    if (min_volume == 0.0) {
        // Counting needs only the connected pieces of the zero-crossing mask,
        // which segmentSDF splits by, not the pieces' own level sets.
        std::vector<openvdb::BoolGrid::Ptr> pieces;
        openvdb::tools::extractActiveVoxelSegmentMasks(*openvdb::tools::extractIsosurfaceMask(*grid, 0.0f), pieces);
        progress.check();
        counts.kept = std::max<uint64_t>(1, pieces.size());
        return counts;
    }
    if (grid->activeVoxelCount() == 0) return counts;  // no shell at all
    std::vector<openvdb::FloatGrid::Ptr> shells;
    openvdb::tools::segmentSDF(*grid, shells);
    progress.check();
    std::vector<openvdb::FloatGrid::Ptr> kept;
    for (size_t i = 0; i < shells.size(); ++i) {
        if (shells[i]->activeVoxelCount() > 0 && level_set_volume(*shells[i]) >= min_volume)
            kept.push_back(shells[i]);
        else
            ++counts.dropped;
        progress.update(double(i + 1) / double(shells.size()));
    }
    counts.kept = kept.size();
    if (counts.dropped == 0) return counts;
    openvdb::FloatGrid::Ptr result = openvdb::FloatGrid::create(grid->background());
    result->setTransform(grid->transform().copy());
    result->setGridClass(openvdb::GRID_LEVEL_SET);
    result->setName(grid->getName());
    for (auto& shell : kept) openvdb::tools::csgUnion(*result, *shell);
    grid = result;
    return counts;
}

}  // namespace fabvdb::volume
