//! Hand-over of the runs a part cannot keep (see hand_over_runs.h).
#include "volume/hand_over_runs.h"

#include <algorithm>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <openvdb/tools/Composite.h>
#include <openvdb/tools/Dense.h>
#include <openvdb/tools/GridTransformer.h>
#include <openvdb/tools/Interpolation.h>

#include "core/error.h"
#include "volume/column_runs.h"
#include "volume/dense_level_set.h"
#include "volume/level_set_volume.h"
#include "volume/progress_interrupter.h"

namespace fabvdb::volume {

namespace {

//! The runs of `swept`'s columns other than the kept one, as a level set on
//! `swept`'s transform (empty when every column has one run).
openvdb::FloatGrid::Ptr unkept_runs(const openvdb::FloatGrid& swept, const openvdb::FloatGrid* kept_surface,
                                    const Progress& progress) {
    openvdb::CoordBBox box = swept.evalActiveVoxelBoundingBox();
    if (box.empty()) return openvdb::FloatGrid::create(swept.background());
    box.expand(1);
    openvdb::tools::Dense<float> block(box);
    openvdb::tools::copyToDense(swept, block);
    progress.check();
    const openvdb::Coord dim = box.dim();
    const size_t nz = size_t(dim.z()), ny = size_t(dim.y()), columns = size_t(dim.x()) * ny;
    const float outside = float(0.5 * swept.voxelSize()[0]);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, columns), [&](const tbb::blocked_range<size_t>& range) {
        if (progress.cancelled()) return;
        const SurfaceCrossings crossings(swept.transform(), box.min(), kept_surface);
        for (size_t c = range.begin(); c != range.end(); ++c) {
            float* column = block.data() + c * nz;
            const std::vector<Run> runs = inside_runs(column, nz);
            if (runs.empty()) continue;
            const Run kept = runs[kept_run(runs, crossings, int(c / ny), int(c % ny))];
            for (size_t k = 0; k < nz; ++k)
                if (runs.size() == 1 || (k + 1 >= kept.start && k <= kept.end))
                    column[k] = std::max(std::abs(column[k]), outside);
        }
    });
    progress.check();
    return dense_level_set(block, swept.transform(), swept.background(), progress);
}

}  // namespace

HandOver hand_over_unkept_runs(const std::vector<openvdb::FloatGrid::Ptr>& own,
                               const std::vector<openvdb::FloatGrid::Ptr>& swept,
                               const openvdb::FloatGrid* kept_surface, Progress& progress) {
    if (own.size() != swept.size())
        throw Error(FABVDB_ERR_INVALID_ARGUMENT, "hand-over: as many swept parts as parts are needed");
    progress.stage("sweep: hand over the runs a part cannot keep");
    const size_t count = own.size();
    HandOver result;
    result.given.assign(count, 0.0);
    result.received.assign(count, 0.0);
    for (const auto& part : own) result.parts.push_back(part->deepCopy());
    if (count < 2) return result;
    ProgressInterrupter interrupter(progress);
    for (size_t p = 0; p < count; ++p) {
        // The unkept runs on the parts' transform, only where they were the part's own.
        openvdb::FloatGrid::Ptr unkept = openvdb::FloatGrid::create(own[p]->background());
        unkept->setTransform(own[p]->transform().copy());
        unkept->setGridClass(openvdb::GRID_LEVEL_SET);
        openvdb::tools::resampleToMatch<openvdb::tools::BoxSampler>(*unkept_runs(*swept[p], kept_surface, progress),
                                                                    *unkept, interrupter);
        progress.check();
        openvdb::FloatGrid::Ptr mine = own[p]->deepCopy();
        openvdb::tools::csgIntersection(*unkept, *mine);
        const double volume = level_set_volume(*unkept);
        progress.update((double(p) + 0.5) / double(count));
        if (!(volume > 0)) continue;

        // Each inside voxel goes to the other part nearest to it.
        std::vector<openvdb::FloatGrid::Ptr> share(count);
        for (size_t q = 0; q < count; ++q)
            if (q != p) share[q] = unkept->deepCopy();
        const float outside = float(0.5 * own[p]->voxelSize()[0]);
        std::vector<openvdb::FloatGrid::ConstAccessor> others;
        for (size_t q = 0; q < count; ++q) others.push_back(swept[q]->getConstAccessor());
        for (auto voxel = unkept->cbeginValueOn(); voxel; ++voxel) {
            if (!(*voxel < 0)) continue;
            const openvdb::Vec3d world = unkept->indexToWorld(voxel.getCoord());
            size_t nearest = count;
            double nearest_value = 0;
            for (size_t q = 0; q < count; ++q) {
                if (q == p) continue;
                const double value = openvdb::tools::BoxSampler::sample(others[q], swept[q]->worldToIndex(world));
                if (nearest == count || value < nearest_value) nearest = q, nearest_value = value;
            }
            for (size_t q = 0; q < count; ++q)
                if (q != p && q != nearest) share[q]->tree().setValueOn(voxel.getCoord(), std::max(-*voxel, outside));
        }
        progress.check();
        for (size_t q = 0; q < count; ++q) {
            if (q == p) continue;
            const double share_volume = level_set_volume(*share[q]);
            if (!(share_volume > 0)) continue;
            result.received[q] += share_volume;
            openvdb::tools::csgUnion(*result.parts[q], *share[q]);
        }
        result.given[p] = volume;
        openvdb::tools::csgDifference(*result.parts[p], *unkept);
        progress.check();
        progress.update(double(p + 1) / double(count));
    }
    return result;
}

}  // namespace fabvdb::volume
