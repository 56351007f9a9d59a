//! local_thickness: gradient ascent of the distance with trilinear samples and
//! central differences in half-voxel steps (shorter ones, or a step towards
//! the best neighbour, where a step along the gradient would not rise), then
//! the ridge placed where the straight branches on either side of it meet;
//! one sample max_radius deep first, which caps most points. Parallel over
//! points (TBB).
#include "volume/local_thickness.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <vector>

#include <openvdb/tools/Interpolation.h>
#include <tbb/parallel_for.h>

namespace fabvdb::volume {

namespace {

//! The ridge of f along the line x + s·u near s = 0, where f's samples rose to
//! `peak`: the branches are fitted through samples 2.5 and 3.5 voxels to
//! either side (farther than a cell's diagonal, so no sample's cell holds the ridge and the
//! trilinear samples of a distance that is linear on each side are exact) and
//! meet at the ridge. Returns the offset s of the ridge and its value, or
//! false when the branches are not a clear rise and fall (a ridge running
//! along u, other surfaces within three voxels) or meet farther than 1.5
//! voxels away or more than a voxel above the samples.
template <class F>
bool ridge_between_branches(const F& f, const openvdb::Vec3d& x, const openvdb::Vec3d& u, double h, double peak,
                            double& offset, double& value) {
    const double a = 2.5 * h, b = 3.5 * h;
    const double near_left = f(x - a * u), far_left = f(x - b * u);
    const double near_right = f(x + a * u), far_right = f(x + b * u);
    const double rise = (near_left - far_left) / h, fall = (far_right - near_right) / h;
    if (!(rise > 0.3 && fall < -0.3)) return false;
    // near_left + rise·(s + a) = near_right + fall·(s − a)
    offset = (near_right - near_left - a * (fall + rise)) / (rise - fall);
    value = near_left + rise * (offset + a);
    return std::abs(offset) <= 1.5 * h && value >= peak - 1e-9 && value <= peak + h;
}

//! The unit directions from a voxel to its 26 neighbours.
const std::vector<openvdb::Vec3d> neighbour_directions = [] {
    std::vector<openvdb::Vec3d> directions;
    for (int i = -1; i <= 1; ++i)
        for (int j = -1; j <= 1; ++j)
            for (int k = -1; k <= 1; ++k)
                if (i != 0 || j != 0 || k != 0) directions.push_back(openvdb::Vec3d(i, j, k).unitSafe());
    return directions;
}();

}  // namespace

LocalThickness local_thickness(const openvdb::FloatGrid& grid, const std::vector<Vec3>& points, ThicknessSide side,
                               double max_radius, Progress& progress) {
    progress.stage(side == ThicknessSide::solid ? "wall thickness" : "gap width");
    const double h = grid.voxelSize()[0];
    const double step = 0.5 * h;
    const double sign = side == ThicknessSide::solid ? -1.0 : 1.0;
    const int max_steps = int(std::ceil(3.0 * max_radius / step)) + 16;
    LocalThickness result;
    result.thickness.resize(points.size());
    result.centre.resize(points.size());
    result.capped.assign(points.size(), 0);
    std::atomic<size_t> done{0};
    tbb::parallel_for(tbb::blocked_range<size_t>(0, points.size(), 512), [&](const tbb::blocked_range<size_t>& range) {
        if (progress.cancelled()) return;
        const openvdb::FloatGrid::ConstAccessor accessor = grid.getConstAccessor();  // the sampler keeps a reference
        openvdb::tools::GridSampler<openvdb::FloatGrid::ConstAccessor, openvdb::tools::BoxSampler> sampler(
            accessor, grid.transform());
        const auto f = [&](const openvdb::Vec3d& p) { return sign * double(sampler.wsSample(p)); };
        const auto gradient_at = [&](const openvdb::Vec3d& p) {
            openvdb::Vec3d gradient;
            for (int k = 0; k < 3; ++k) {
                openvdb::Vec3d e(0.0);
                e[k] = 0.5 * h;
                gradient[k] = (f(p + e) - f(p - e)) / h;
            }
            return gradient;
        };
        for (size_t i = range.begin(); i != range.end(); ++i) {
            openvdb::Vec3d x(points[i][0], points[i][1], points[i][2]);
            double value = f(x);
            openvdb::Vec3d direction(0.0);
            openvdb::Vec3d gradient = gradient_at(x);
            // Most of a part is thicker than the cap: a ball of max_radius
            // fits straight along the first gradient, so the climb is one step.
            if (value < max_radius && gradient.length() >= 0.2) {
                const openvdb::Vec3d centre = x + (max_radius - value) * gradient.unitSafe();
                if (f(centre) >= max_radius) {
                    result.thickness[i] = 2.0 * max_radius;
                    result.centre[i] = {centre[0], centre[1], centre[2]};
                    result.capped[i] = 1;
                    continue;
                }
            }
            for (int s = 0; s < max_steps && value < max_radius; ++s) {
                if (s > 0) gradient = gradient_at(x);
                if (gradient.length() < 0.2) break;  // on the ridge, or off the band
                // Along the gradient, shorter steps when a step would not
                // rise; along a kink (a convex edge's or corner's bisector)
                // the samples dip, so then the best of the 26 directions to a
                // voxel's neighbours; past the ridge when none rises.
                openvdb::Vec3d u = gradient.unitSafe();
                double length = step, next_value = value;
                for (; length > 0.1 * h; length *= 0.5) {
                    next_value = f(x + length * u);
                    if (next_value > value) break;
                }
                if (!(next_value > value)) {
                    length = step;
                    for (const openvdb::Vec3d& d : neighbour_directions) {
                        const double candidate = f(x + step * d);
                        if (candidate > next_value) {
                            next_value = candidate;
                            u = d;
                        }
                    }
                }
                if (!(next_value > value)) break;
                x += length * u;
                value = next_value;
                direction = u;
            }
            // The ridge across the way the walk came, and across the axes
            // (a walk along a convex edge's bisector arrives on a kink, so
            // its own line may not see two straight branches): the highest
            // ridge found, each at most a voxel above the samples.
            if (value < max_radius) {
                const openvdb::Vec3d lines[4] = {direction, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
                const double sampled = value;
                openvdb::Vec3d best = x;
                for (const openvdb::Vec3d& u : lines) {
                    double offset = 0.0, ridge = sampled;
                    if (u.length() > 0.5 && ridge_between_branches(f, x, u, h, sampled, offset, ridge) && ridge > value) {
                        value = ridge;
                        best = x + offset * u;
                    }
                }
                x = best;
            }
            const bool capped = value >= max_radius;
            result.thickness[i] = 2.0 * std::min(std::max(value, 0.0), max_radius);
            result.centre[i] = {x[0], x[1], x[2]};
            result.capped[i] = capped ? 1 : 0;
        }
        done += range.size();
        progress.update(double(done) / double(points.size()));
    });
    progress.check();
    return result;
}

}  // namespace fabvdb::volume
