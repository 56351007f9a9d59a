//! Detail restoration of decomposition parts (see detail_restoration.h).
#include "volume/detail_restoration.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <openvdb/tools/LevelSetRebuild.h>
#include <openvdb/tools/MeshToVolume.h>

#include "core/error.h"
#include "volume/level_set_volume.h"
#include "volume/progress_interrupter.h"

namespace fabvdb::volume {

std::vector<openvdb::FloatGrid::Ptr> restore_part_details(const openvdb::FloatGrid& input,
                                                          const std::vector<Mesh>& parts,
                                                          const DetailRestorationOptions& options,
                                                          Progress& progress) {
    if (!(options.shell_thickness > 0) || !(options.reach > 0))
        throw Error(FABVDB_ERR_INVALID_ARGUMENT, "detail restoration needs a shell thickness and a reach > 0");
    if (input.getGridClass() != openvdb::GRID_LEVEL_SET)
        throw Error(FABVDB_ERR_INVALID_ARGUMENT, "detail restoration needs the input as a level set");
    const double voxel = input.voxelSize()[0];
    const float band = float(std::max(options.reach, options.shell_thickness) / voxel + 3.0);
    ProgressInterrupter interrupter(progress);

    progress.stage("detail restoration: part volumes");
    std::vector<openvdb::FloatGrid::Ptr> low_res;
    for (size_t i = 0; i < parts.size(); ++i) {
        std::vector<openvdb::Vec3s> points;
        std::vector<openvdb::Vec3I> triangles;
        for (const Vec3& p : parts[i].vertices) {
            const openvdb::Vec3d index = input.transform().worldToIndex(openvdb::Vec3d(p[0], p[1], p[2]));
            points.emplace_back(float(index[0]), float(index[1]), float(index[2]));
        }
        for (const Triangle& t : parts[i].triangles) triangles.emplace_back(t[0], t[1], t[2]);
        openvdb::tools::QuadAndTriangleDataAdapter<openvdb::Vec3s, openvdb::Vec3I> adapter(points, triangles);
        auto grid = openvdb::tools::meshToVolume<openvdb::FloatGrid>(interrupter, adapter, input.transform(), band,
                                                                     band);
        progress.check();
        if (grid->activeVoxelCount() == 0)
            throw Error(FABVDB_ERR_BAD_INPUT,
                        options.input_name + ": part " + std::to_string(i) + " encloses no volume");
        low_res.push_back(grid);
        progress.update(double(i + 1) / double(2 * parts.size()));
    }

    progress.stage("detail restoration: restore");
    const float omega = float(options.shell_thickness), reach = float(options.reach);
    std::vector<openvdb::FloatGrid::Ptr> restored;
    for (size_t i = 0; i < parts.size(); ++i) {
        // Start from the part's topology dilated by its own band: every voxel
        // within the reach is active, the interior stays an inside tile.
        openvdb::FloatGrid::Ptr combined = low_res[i]->deepCopy();
        auto input_access = input.getConstAccessor();
        std::vector<openvdb::FloatGrid::ConstAccessor> others;
        for (size_t j = 0; j < parts.size(); ++j)
            if (j != i) others.push_back(low_res[j]->getConstAccessor());
        for (auto value = combined->beginValueOn(); value; ++value) {
            const openvdb::Coord ijk = value.getCoord();
            const float own = *value;
            float nearest_other = std::numeric_limits<float>::max();
            for (auto& other : others) nearest_other = std::min(nearest_other, other.getValue(ijk));
            const float phi = input_access.getValue(ijk);
            float result = std::max({phi, own - reach, -phi - omega});
            if (!others.empty()) result = std::max(result, 0.5f * (own - nearest_other));
            value.setValue(result);
        }
        progress.check();
        auto grid = openvdb::tools::levelSetRebuild(*combined, 0.0f, float(input.background() / voxel),
                                                    float(input.background() / voxel), &input.transform(),
                                                    &interrupter);
        progress.check();
        grid->setGridClass(openvdb::GRID_LEVEL_SET);
        // A part about a voxel thin keeps almost no inside voxel: what would
        // be restored of it is crumbs.
        const double held =
            level_set_volume(*grid) / signed_volume(parts[i]);
        if (!(held >= 0.5))
            throw Error(FABVDB_ERR_BAD_INPUT,
                        options.input_name + ": part " + std::to_string(i) + " is about a voxel (" +
                            std::to_string(voxel) + " mm) thin over most of it: restored at this voxel it keeps " +
                            std::to_string(int(std::lround(100.0 * std::max(held, 0.0)))) +
                            "% of its volume; use a voxel at least three times finer, or fewer parts");
        restored.push_back(grid);
        progress.update(0.5 + double(i + 1) / double(2 * parts.size()));
    }
    return restored;
}

}  // namespace fabvdb::volume
