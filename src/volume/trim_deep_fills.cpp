//! Fill or trim, per column (see trim_deep_fills.h).
#include "volume/trim_deep_fills.h"

#include <algorithm>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <openvdb/tools/Interpolation.h>
#include <openvdb/tools/LevelSetRebuild.h>

#include "volume/column_runs.h"
#include "volume/progress_interrupter.h"

namespace fabvdb::volume {

namespace {

using Sampler = openvdb::tools::GridSampler<openvdb::FloatGrid::ConstAccessor, openvdb::tools::BoxSampler>;

}  // namespace

size_t trim_deep_fills(const std::vector<float>& original, openvdb::tools::Dense<float>& filled,
                       const openvdb::math::Transform& transform, const openvdb::FloatGrid& surface,
                       float background, double min_depth, Progress& progress) {
    progress.stage("sweep: fill or trim");
    const openvdb::CoordBBox box = filled.bbox();
    const openvdb::Coord dim = box.dim();
    const int nx = dim.x(), ny = dim.y();
    const size_t nz = size_t(dim.z()), columns = size_t(nx) * size_t(ny);
    const double voxel = transform.voxelSize()[0];

    // Depth below the filled part's surface, as a true signed distance.
    openvdb::FloatGrid::Ptr distance;
    {
        auto hull = openvdb::FloatGrid::create(background);
        hull->setTransform(transform.copy());
        hull->setGridClass(openvdb::GRID_LEVEL_SET);
        openvdb::tools::copyFromDense(filled, *hull, 0.0f);
        progress.check();
        const float interior = float(std::max(3.0, std::ceil(4.0 * min_depth / voxel)));
        ProgressInterrupter interrupter(progress);
        distance = openvdb::tools::levelSetRebuild(*hull, 0.0f, 1.0f, interior, nullptr, &interrupter);
        progress.check();
    }
    progress.update(0.5);

    const auto world = [&](size_t c, double z) {
        const int i = int(c / size_t(ny)) + box.min().x(), j = int(c % size_t(ny)) + box.min().y();
        return transform.indexToWorld(openvdb::Vec3d(i, j, double(box.min().z()) + z));
    };
    // Per column: how deep the input surface at its gaps is buried (0: no
    // gap bounded by input surface).
    std::vector<float> depth(columns, 0.0f);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, columns), [&](const tbb::blocked_range<size_t>& range) {
        if (progress.cancelled()) return;
        const openvdb::FloatGrid::ConstAccessor surface_access = surface.getConstAccessor();
        const openvdb::FloatGrid::ConstAccessor distance_access = distance->getConstAccessor();
        const Sampler surface_sampler(surface_access, surface.transform());
        const Sampler distance_sampler(distance_access, distance->transform());
        for (size_t c = range.begin(); c != range.end(); ++c) {
            const float* column = original.data() + c * nz;
            const std::vector<Run> runs = inside_runs(column, nz);
            for (size_t r = 0; r + 1 < runs.size(); ++r)
                for (const size_t k : {runs[r].end - 1, runs[r + 1].start - 1}) {
                    const openvdb::Vec3d p = world(c, zero_crossing(column, k));
                    if (std::abs(surface_sampler.wsSample(p)) >= voxel) continue;
                    depth[c] = std::max(depth[c], -distance_sampler.wsSample(p));
                }
        }
    });
    progress.check();

    // Regions of gap columns; in a deep one, the shallower half is trimmed.
    std::vector<int> region(columns, -1);
    std::vector<size_t> trimmed;
    std::vector<size_t> members, stack;
    for (size_t seed = 0; seed < columns; ++seed) {
        if (!(depth[seed] > 0) || region[seed] >= 0) continue;
        members.clear();
        stack.assign(1, seed);
        region[seed] = int(seed);
        float deepest = 0;
        while (!stack.empty()) {
            const size_t c = stack.back();
            stack.pop_back();
            members.push_back(c);
            deepest = std::max(deepest, depth[c]);
            const int i = int(c / size_t(ny)), j = int(c % size_t(ny));
            const int ni[4] = {i - 1, i + 1, i, i}, nj[4] = {j, j, j - 1, j + 1};
            for (int n = 0; n < 4; ++n) {
                if (ni[n] < 0 || nj[n] < 0 || ni[n] >= nx || nj[n] >= ny) continue;
                const size_t neighbour = size_t(ni[n]) * size_t(ny) + size_t(nj[n]);
                if (depth[neighbour] > 0 && region[neighbour] < 0) {
                    region[neighbour] = int(seed);
                    stack.push_back(neighbour);
                }
            }
        }
        if (deepest <= min_depth) continue;
        for (size_t c : members)
            if (depth[c] < 0.5f * deepest) trimmed.push_back(c);
    }
    progress.update(0.75);

    tbb::parallel_for(tbb::blocked_range<size_t>(0, trimmed.size()), [&](const tbb::blocked_range<size_t>& range) {
        const openvdb::FloatGrid::ConstAccessor surface_access = surface.getConstAccessor();
        const Sampler surface_sampler(surface_access, surface.transform());
        for (size_t t = range.begin(); t != range.end(); ++t) {
            const size_t c = trimmed[t];
            const float* column = original.data() + c * nz;
            const std::vector<Run> runs = inside_runs(column, nz);
            // The run with the most input surface at its ends, the longer on a tie.
            const Run* kept = nullptr;
            int kept_ends = -1;
            for (const Run& run : runs) {
                int ends = 0;
                for (const size_t k : {run.start - 1, run.end - 1})
                    ends += std::abs(surface_sampler.wsSample(world(c, zero_crossing(column, k)))) < voxel;
                if (ends > kept_ends || (ends == kept_ends && run.end - run.start > kept->end - kept->start))
                    kept = &run, kept_ends = ends;
            }
            float* out = filled.data() + c * nz;
            const float outside = float(0.5 * voxel);
            for (size_t k = 0; k < nz; ++k)
                out[k] = k + 1 >= kept->start && k <= kept->end ? column[k] : std::max(std::abs(column[k]), outside);
        }
    });
    progress.check();
    return trimmed.size();
}

}  // namespace fabvdb::volume
