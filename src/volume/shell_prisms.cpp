//! shell_prisms: gradient descent on φ with trilinear samples and central
//! differences, steps of a quarter voxel, parallel over vertices (TBB).
#include "volume/shell_prisms.h"

#include <algorithm>
#include <atomic>
#include <cmath>

#include <openvdb/tools/Interpolation.h>
#include <tbb/parallel_for.h>

namespace fabvdb::volume {

ShellPrisms shell_prisms(const openvdb::FloatGrid& grid, const std::vector<Vec3>& outer_vertices, double thickness,
                         double max_depth, Progress& progress) {
    progress.stage("shell prisms");
    const double h = grid.voxelSize()[0];
    const double step = 0.25 * h;
    const int max_steps = int(std::ceil(4.0 * max_depth / step)) + 8;
    ShellPrisms result;
    result.inner.resize(outer_vertices.size());
    result.depth.resize(outer_vertices.size());
    std::atomic<size_t> done{0};
    tbb::parallel_for(tbb::blocked_range<size_t>(0, outer_vertices.size(), 1024), [&](const tbb::blocked_range<size_t>& range) {
        if (progress.cancelled()) return;
        // The sampler holds its accessor by reference: the accessor is named.
        const openvdb::FloatGrid::ConstAccessor accessor = grid.getConstAccessor();
        openvdb::tools::GridSampler<openvdb::FloatGrid::ConstAccessor, openvdb::tools::BoxSampler> sampler(
            accessor, grid.transform());
        const auto phi = [&](const openvdb::Vec3d& p) { return double(sampler.wsSample(p)); };
        for (size_t i = range.begin(); i != range.end(); ++i) {
            openvdb::Vec3d p(outer_vertices[i][0], outer_vertices[i][1], outer_vertices[i][2]);
            double value = phi(p);
            openvdb::Vec3d inner = p;
            bool inner_found = false;
            double deepest = std::max(0.0, -value);
            for (int s = 0; s < max_steps && deepest < max_depth; ++s) {
                openvdb::Vec3d gradient;
                for (int k = 0; k < 3; ++k) {
                    openvdb::Vec3d e(0.0);
                    e[k] = 0.5 * h;
                    gradient[k] = (phi(p + e) - phi(p - e)) / h;
                }
                if (gradient.length() < 1e-6) break;  // outside the band or on the medial axis
                const openvdb::Vec3d next = p - step * gradient.unitSafe();
                const double next_value = phi(next);
                if (next_value >= value) break;  // φ stopped decreasing: the medial axis
                p = next;
                value = next_value;
                deepest = std::max(deepest, -value);
                if (!inner_found && value <= -thickness) {
                    inner = p;
                    inner_found = true;
                }
            }
            if (!inner_found) inner = p;
            result.inner[i] = {inner[0], inner[1], inner[2]};
            result.depth[i] = std::min(deepest, max_depth);
        }
        done += range.size();
        progress.update(double(done) / outer_vertices.size());
    });
    progress.check();
    return result;
}

}  // namespace fabvdb::volume
