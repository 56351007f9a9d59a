//! Moldability enforcement by sweeping (see sweep.h).
#include "volume/sweep.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <openvdb/tools/Composite.h>
#include <openvdb/tools/Dense.h>
#include <openvdb/tools/GridTransformer.h>
#include <openvdb/tools/Interpolation.h>

#include "core/error.h"
#include "volume/aligned_frame.h"
#include "volume/dense_level_set.h"
#include "volume/level_set_volume.h"
#include "volume/progress_interrupter.h"
#include "volume/require_level_set.h"
#include "volume/trim_deep_fills.h"

namespace fabvdb::volume {

namespace {

using Sampler = openvdb::tools::GridSampler<openvdb::FloatGrid::ConstAccessor, openvdb::tools::BoxSampler>;

openvdb::FloatGrid::Ptr resampled(const openvdb::FloatGrid& grid, const openvdb::math::Transform::Ptr& transform,
                                  float background, ProgressInterrupter& interrupter, const Progress& progress) {
    auto out = openvdb::FloatGrid::create(background);
    out->setTransform(transform);
    out->setGridClass(openvdb::GRID_LEVEL_SET);
    openvdb::tools::resampleToMatch<openvdb::tools::BoxSampler>(grid, *out, interrupter);
    progress.check();
    return out;
}

// The union of `solids` on the voxels of `box` in `transform`: each solid
// sampled where the voxel lies (trilinear, in the solid's own frame), only
// within the solid's active box, so the cost grows with the block and not
// with the solids' surfaces (a resample through a mesh per solid would).
openvdb::FloatGrid::Ptr union_on_block(const std::vector<openvdb::FloatGrid::ConstPtr>& solids,
                                       const openvdb::CoordBBox& box, const openvdb::math::Transform& transform,
                                       float background, const Progress& progress) {
    openvdb::tools::Dense<float> block(box, background);
    for (const auto& solid : solids) {
        openvdb::CoordBBox active = solid->evalActiveVoxelBoundingBox();
        if (active.empty()) continue;
        active.expand(1);
        const openvdb::BBoxd index = transform.worldToIndex(solid->transform().indexToWorld(active));
        openvdb::CoordBBox within(openvdb::Coord::floor(index.min()), openvdb::Coord::ceil(index.max()));
        within.intersect(box);
        if (within.empty()) continue;
        tbb::parallel_for(tbb::blocked_range<int>(within.min().x(), within.max().x() + 1),
                          [&](const tbb::blocked_range<int>& range) {
                              if (progress.cancelled()) return;
                              const openvdb::FloatGrid::ConstAccessor access = solid->getConstAccessor();
                              const Sampler sampler(access, solid->transform());
                              float* data = block.data();
                              for (int x = range.begin(); x != range.end(); ++x)
                                  for (int y = within.min().y(); y <= within.max().y(); ++y)
                                      for (int z = within.min().z(); z <= within.max().z(); ++z) {
                                          const openvdb::Coord ijk(x, y, z);
                                          const float value = float(sampler.wsSample(transform.indexToWorld(ijk)));
                                          float& kept = data[block.coordToOffset(ijk)];
                                          kept = std::min(kept, std::clamp(value, -background, background));
                                      }
                          });
        progress.check();
    }
    return dense_level_set(block, transform, background, progress);
}

// Each column of the dense block (z is contiguous) becomes the hull of where
// it is inside: max(running min from below, running min from above).
void sweep_columns(openvdb::tools::Dense<float>& dense, const Progress& progress) {
    const openvdb::Coord dim = dense.bbox().dim();
    const size_t nz = size_t(dim.z()), columns = size_t(dim.x()) * size_t(dim.y());
    float* data = dense.data();
    tbb::parallel_for(tbb::blocked_range<size_t>(0, columns), [&](const tbb::blocked_range<size_t>& range) {
        if (progress.cancelled()) return;
        std::vector<float> from_below(nz);
        for (size_t c = range.begin(); c != range.end(); ++c) {
            float* column = data + c * nz;
            float running = column[0];
            for (size_t k = 0; k < nz; ++k) from_below[k] = running = std::min(running, column[k]);
            running = column[nz - 1];
            for (size_t k = nz; k-- > 0;) {
                running = std::min(running, column[k]);
                column[k] = std::max(from_below[k], running);
            }
        }
    });
    progress.check();
}

}  // namespace

openvdb::math::Transform::Ptr aligned_transform(double voxel_size, const Vec3& direction) {
    const AlignedFrame frame = aligned_frame(direction);
    // OpenVDB maps index to world as a row vector times the matrix: row k is
    // the world image of index axis k.
    openvdb::math::Mat4d matrix = openvdb::math::Mat4d::identity();
    for (int k = 0; k < 3; ++k) {
        matrix(0, k) = voxel_size * frame.e1[k];
        matrix(1, k) = voxel_size * frame.e2[k];
        matrix(2, k) = voxel_size * frame.d[k];
    }
    return openvdb::math::Transform::createLinearTransform(matrix);
}

openvdb::FloatGrid::Ptr sweep_double_height_field(const openvdb::FloatGrid& part, const Vec3& direction,
                                                  const std::vector<openvdb::FloatGrid::ConstPtr>& keep_out,
                                                  const SweepOptions& options, Progress& progress,
                                                  SweepStats* stats) {
    require_level_set(part, "the part");
    for (const auto& solid : keep_out) {
        if (!solid) throw Error(FABVDB_ERR_INVALID_ARGUMENT, "a keep-out solid is null");
        require_level_set(*solid, "a keep-out solid");
    }
    if (options.kept_surface) require_level_set(*options.kept_surface, "the input surface");
    const double voxel = part.voxelSize()[0];
    const float background = part.background();
    const openvdb::math::Transform::Ptr transform = aligned_transform(voxel, direction);
    ProgressInterrupter interrupter(progress);

    progress.stage("sweep: resample to the parting direction");
    openvdb::FloatGrid::Ptr aligned = resampled(part, transform, background, interrupter, progress);
    SweepStats figures;
    figures.volume_before = level_set_volume(*aligned);
    if (aligned->activeVoxelCount() == 0) throw Error(FABVDB_ERR_BAD_INPUT, "the part to sweep is empty");

    openvdb::CoordBBox box = aligned->evalActiveVoxelBoundingBox();
    box.expand(1);
    // The block is held once, twice with an input surface to keep (before
    // and after the sweep), and once more for the other parts.
    const uint64_t blocks = 1 + (options.kept_surface ? 1 : 0) + (keep_out.empty() ? 0 : 1);
    const uint64_t dense_bytes = uint64_t(box.volume()) * sizeof(float) * blocks;
    if (options.memory_budget_bytes && dense_bytes > options.memory_budget_bytes)
        throw Error(FABVDB_ERR_OUT_OF_BUDGET, "sweeping the part needs " + std::to_string(dense_bytes >> 20) +
                                                  " MiB of column buffer, over the memory budget");

    // The other parts on the aligned grid: the sweep's added material keeps
    // out of them, and trimming does not give up what they hold.
    openvdb::FloatGrid::Ptr others;
    if (!keep_out.empty()) {
        progress.stage("sweep: other parts");
        others = union_on_block(keep_out, box, *transform, background, progress);
    }

    progress.stage("sweep: columns");
    openvdb::FloatGrid::Ptr swept;
    {
        openvdb::tools::Dense<float> dense(box);
        openvdb::tools::copyToDense(*aligned, dense);
        progress.update(0.3);
        std::vector<float> original;
        if (options.kept_surface) original.assign(dense.data(), dense.data() + dense.valueCount());
        sweep_columns(dense, progress);
        progress.update(0.6);
        if (options.kept_surface) {
            figures.columns_trimmed = trim_deep_fills(original, dense, *transform, *options.kept_surface, background,
                                                      2.0 * voxel, others.get(), progress);
        }
        swept = dense_level_set(dense, *transform, background, progress);
    }
    figures.volume_swept = level_set_volume(*swept);

    if (others) {
        progress.stage("sweep: keep out of other parts");
        openvdb::tools::csgDifference(*swept, *others);
        progress.check();
    }
    figures.volume_after = level_set_volume(*swept);
    figures.added_volume = figures.volume_after - figures.volume_before;
    figures.removed_by_keep_out = figures.volume_swept - figures.volume_after;
    if (stats) *stats = figures;
    return swept;
}

}  // namespace fabvdb::volume
