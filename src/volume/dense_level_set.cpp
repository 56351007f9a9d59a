//! A level set from a dense block (see dense_level_set.h).
#include "volume/dense_level_set.h"

#include <cmath>

#include <openvdb/tools/Prune.h>

namespace fabvdb::volume {

openvdb::FloatGrid::Ptr dense_level_set(const openvdb::tools::Dense<float>& block,
                                        const openvdb::math::Transform& transform, float background,
                                        const Progress& progress) {
    openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(background);
    grid->setTransform(transform.copy());
    openvdb::tools::copyFromDense(block, *grid, 0.0f);
    progress.check();
    for (auto value = grid->beginValueOn(); value; ++value)
        if (std::abs(*value) >= background) {
            value.setValue(*value < 0 ? -background : background);
            value.setValueOff();
        }
    openvdb::tools::pruneLevelSet(grid->tree());
    progress.check();
    grid->setGridClass(openvdb::GRID_LEVEL_SET);
    return grid;
}

}  // namespace fabvdb::volume
