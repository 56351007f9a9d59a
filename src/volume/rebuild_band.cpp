//! A fresh narrow band around an iso-surface (see rebuild_band.h).
#include "volume/rebuild_band.h"

#include <openvdb/tools/LevelSetRebuild.h>

#include "volume/extract_mesh.h"
#include "volume/progress_interrupter.h"

namespace fabvdb::volume {

openvdb::FloatGrid::Ptr rebuild_band(const openvdb::FloatGrid& grid, double isovalue, int half_band_voxels,
                                     Progress& progress) {
    ProgressInterrupter interrupter(progress);
    const float band = float(half_band_voxels);
    openvdb::FloatGrid::Ptr rebuilt = openvdb::tools::levelSetRebuild(
        grid, float(isovalue + surface_isovalue(grid)), band, band, nullptr, &interrupter);
    progress.check();
    rebuilt->setGridClass(openvdb::GRID_LEVEL_SET);
    rebuilt->setName(grid.getName());
    return rebuilt;
}

}  // namespace fabvdb::volume
