//! Lost input surface put back as tubes (see keep_lost_surface.h).
#include "volume/keep_lost_surface.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <openvdb/tools/Interpolation.h>
#include <openvdb/tools/Morphology.h>

#include "core/error.h"
#include "core/vec3_ops.h"
#include "volume/rebuild_band.h"
#include "volume/require_level_set.h"
#include "volume/unsigned_band.h"

namespace fabvdb::volume {

namespace {

using Sampler = openvdb::tools::GridSampler<openvdb::FloatGrid::ConstAccessor, openvdb::tools::BoxSampler>;

// One part's lost samples: the voxels they lie in and the triangles they lie on.
struct Lost {
    std::vector<openvdb::Coord> voxels;
    std::vector<char> triangles;
};

// The tube of one part: its lost triangles' unsigned distance minus the
// radius, kept within `reach` voxels of its lost samples' voxels.
openvdb::FloatGrid::Ptr tube(const Lost& lost, const Mesh& input, const openvdb::math::Transform& transform,
                             double radius, int reach, Progress& progress) {
    openvdb::BoolGrid mask(false);
    {
        auto accessor = mask.getAccessor();
        for (const openvdb::Coord& ijk : lost.voxels) accessor.setValueOn(ijk, true);
    }
    openvdb::tools::dilateActiveValues(mask.tree(), reach, openvdb::tools::NN_FACE_EDGE_VERTEX,
                                       openvdb::tools::IGNORE_TILES);
    Mesh lost_mesh;
    lost_mesh.vertices = input.vertices;
    for (size_t t = 0; t < input.triangles.size(); ++t)
        if (lost.triangles[t]) lost_mesh.triangles.push_back(input.triangles[t]);
    openvdb::FloatGrid::Ptr grid = unsigned_band(lost_mesh, transform, float(reach + 1), progress);
    const auto in_mask = mask.getConstAccessor();
    for (auto v = grid->beginValueOn(); v; ++v) {
        if (in_mask.isValueOn(v.getCoord()))
            v.setValue(float(*v - radius));
        else
            v.setValueOff();
    }
    return grid;
}

}  // namespace

std::vector<openvdb::FloatGrid::Ptr> keep_lost_surface(const std::vector<openvdb::FloatGrid::Ptr>& parts,
                                                       const Mesh& input, const KeepLostSurfaceOptions& options,
                                                       Progress& progress, LostSurface* stats) {
    if (parts.empty()) throw Error(FABVDB_ERR_INVALID_ARGUMENT, "no part to keep the input surface in");
    for (const openvdb::FloatGrid::Ptr& part : parts) {
        require_level_set(*part, "a part");
        if (part->transform() != parts[0]->transform())
            throw Error(FABVDB_ERR_INVALID_ARGUMENT, "the parts are on different transforms");
    }
    if (!(options.tolerance > 0) || !(options.radius > 0) || !(options.reach > options.tolerance) ||
        options.half_band_voxels < 2)
        throw Error(FABVDB_ERR_INVALID_ARGUMENT, "the lost-surface tolerance and radius must be > 0, the reach over "
                                                 "the tolerance and the half band >= 2 voxels");
    if (options.solid) require_level_set(*options.solid, "the input level set");
    progress.stage("mold: lost input surface");
    const openvdb::math::Transform& transform = parts[0]->transform();
    const double voxel = transform.voxelSize()[0];
    // Distances to each zero surface itself: a band signed from the winding
    // number holds the distance to the input, also beside a fin that no
    // voxel is inside and that the zero surface has none of.
    std::vector<openvdb::FloatGrid::Ptr> exact;
    for (const openvdb::FloatGrid::Ptr& part : parts)
        exact.push_back(rebuild_band(*part, 0.0, options.half_band_voxels, progress));

    const size_t n = parts.size();
    // Off the bands every part is at its background distance: no farther.
    const double reach = std::min(options.reach, (options.half_band_voxels - 1) * voxel);
    std::vector<Lost> lost(n);
    for (Lost& l : lost) l.triangles.assign(input.triangles.size(), 0);
    LostSurface found;
    std::mutex merge;
    const double spacing = 0.5 * voxel;
    tbb::parallel_for(tbb::blocked_range<size_t>(0, input.triangles.size()), [&](const tbb::blocked_range<size_t>& r) {
        if (progress.cancelled()) return;
        // Samplers hold their accessor by reference: both sized once.
        std::vector<openvdb::FloatGrid::ConstAccessor> accessors;
        accessors.reserve(n);
        std::vector<Sampler> samplers;
        samplers.reserve(n);
        for (const openvdb::FloatGrid::Ptr& grid : exact) {
            accessors.push_back(grid->getConstAccessor());
            samplers.emplace_back(accessors.back(), grid->transform());
        }
        const openvdb::FloatGrid& solid = options.solid ? *options.solid : *exact[0];
        const openvdb::FloatGrid::ConstAccessor solid_accessor = solid.getConstAccessor();
        const Sampler inside(solid_accessor, solid.transform());
        std::vector<std::vector<openvdb::Coord>> voxels(n);
        size_t samples = 0, lost_samples = 0;
        for (size_t t = r.begin(); t != r.end(); ++t) {
            const Vec3& a = input.vertices[input.triangles[t][0]];
            const Vec3& b = input.vertices[input.triangles[t][1]];
            const Vec3& c = input.vertices[input.triangles[t][2]];
            const double longest = std::max({norm(b - a), norm(c - b), norm(a - c)});
            const int steps = std::max(1, int(std::ceil(longest / spacing)));
            for (int i = 0; i <= steps; ++i)
                for (int j = 0; i + j <= steps; ++j) {
                    const double u = double(i) / steps, v = double(j) / steps;
                    const openvdb::Vec3d p(a[0] + u * (b[0] - a[0]) + v * (c[0] - a[0]),
                                           a[1] + u * (b[1] - a[1]) + v * (c[1] - a[1]),
                                           a[2] + u * (b[2] - a[2]) + v * (c[2] - a[2]));
                    ++samples;
                    double nearest = std::numeric_limits<double>::infinity();
                    size_t owner = 0;
                    for (size_t k = 0; k < n; ++k) {
                        const double value = samplers[k].wsSample(p);
                        if (value < nearest) nearest = value, owner = k;
                    }
                    if (!(nearest > options.tolerance) || nearest > reach) continue;
                    if (options.solid && inside.wsSample(p) < -options.tolerance) continue;
                    ++lost_samples;
                    lost[owner].triangles[t] = 1;
                    voxels[owner].push_back(transform.worldToIndexCellCentered(p));
                }
        }
        std::lock_guard<std::mutex> lock(merge);
        found.samples += samples;
        found.lost_samples += lost_samples;
        for (size_t k = 0; k < n; ++k) lost[k].voxels.insert(lost[k].voxels.end(), voxels[k].begin(), voxels[k].end());
    });
    progress.check();
    for (size_t t = 0; t < input.triangles.size(); ++t)
        for (const Lost& l : lost)
            if (l.triangles[t]) {
                ++found.lost_triangles;
                break;
            }
    if (stats) *stats = found;
    if (found.lost_samples == 0) return parts;

    const int tube_voxels = int(std::ceil(options.radius / voxel)) + 1;
    std::vector<openvdb::FloatGrid::Ptr> tubes(n);
    for (size_t k = 0; k < n; ++k)
        if (!lost[k].voxels.empty())
            tubes[k] = tube(lost[k], input, transform, options.radius, tube_voxels, progress);
    // A place inside several tubes goes to the first: each tube less those before it.
    for (size_t k = 0; k < n; ++k) {
        if (!tubes[k]) continue;
        for (size_t j = 0; j < k; ++j) {
            if (!tubes[j]) continue;
            const auto before = tubes[j]->getConstAccessor();
            for (auto v = tubes[k]->beginValueOn(); v; ++v) {
                float other = 0;
                if (before.probeValue(v.getCoord(), other) && -other > *v) v.setValue(-other);
            }
        }
    }
    // Each part with its own tube and less the others', where that changes
    // which voxels are inside it.
    std::vector<openvdb::FloatGrid::Ptr> result(parts);
    for (size_t k = 0; k < n; ++k) {
        const auto combined = [&](size_t j, float was, float t) { return j == k ? std::min(was, t) : std::max(was, -t); };
        bool changes = false;
        for (size_t j = 0; j < n && !changes; ++j) {
            if (!tubes[j]) continue;
            const auto own = exact[k]->getConstAccessor();
            for (auto v = tubes[j]->cbeginValueOn(); v && !changes; ++v) {
                const float was = own.getValue(v.getCoord());
                changes = (combined(j, was, *v) < 0) != (was < 0);
            }
        }
        if (!changes) continue;
        const openvdb::FloatGrid::Ptr changed = exact[k]->deepCopy();
        auto out = changed->getAccessor();
        for (size_t j = 0; j < n; ++j) {
            if (!tubes[j]) continue;
            for (auto v = tubes[j]->cbeginValueOn(); v; ++v)
                out.setValue(v.getCoord(), combined(j, out.getValue(v.getCoord()), *v));
        }
        progress.check();
        result[k] = rebuild_band(*changed, 0.0, options.half_band_voxels, progress);
        result[k]->setName(parts[k]->getName());
    }
    return result;
}

}  // namespace fabvdb::volume
