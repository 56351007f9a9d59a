//! Sampling and dropping the cavity's powder (see powder_drop.h).
#include "powder/powder_drop.h"

#include <cmath>

#include <tbb/parallel_for.h>

#include "core/error.h"

namespace fabvdb::powder {

PowderSamples drop_cavity_powder(const openvdb::FloatGrid& cavity, const CavityPatches& patches,
                                 const SurfaceRayCaster& caster, const OrientationFlow& first, size_t max_samples,
                                 Progress& progress) {
    progress.stage("powder drop");
    const openvdb::CoordBBox box = cavity.evalActiveVoxelBoundingBox();
    if (box.empty()) throw Error(FABVDB_ERR_BAD_INPUT, "the cavity is empty");
    const openvdb::Vec3d lo = cavity.indexToWorld(box.min()), hi = cavity.indexToWorld(box.max());
    const openvdb::Vec3d extent = hi - lo;
    const double voxel = cavity.voxelSize()[0];
    const double spacing =
        std::max(voxel, std::cbrt(extent[0] * extent[1] * extent[2] / double(std::max<size_t>(max_samples, 1))));
    const int nx = int(extent[0] / spacing) + 1, ny = int(extent[1] / spacing) + 1, nz = int(extent[2] / spacing) + 1;

    // Candidate points per x slab, kept in order so the result is deterministic.
    std::vector<std::vector<Vec3>> slab_points(nx);
    std::vector<std::vector<uint32_t>> slab_patches(nx);
    std::vector<std::vector<std::array<int32_t, 3>>> slab_cells(nx);
    tbb::parallel_for(0, nx, [&](int ix) {
        if (progress.cancelled()) return;
        auto accessor = cavity.getConstAccessor();
        for (int iy = 0; iy < ny; ++iy)
            for (int iz = 0; iz < nz; ++iz) {
                const openvdb::Vec3d p = lo + openvdb::Vec3d(ix + 0.5, iy + 0.5, iz + 0.5) * spacing;
                const openvdb::Coord ijk = openvdb::Coord::round(cavity.worldToIndex(p));
                if (accessor.getValue(ijk) >= 0.0f) continue;
                const Vec3 origin{p[0], p[1], p[2]};
                const int64_t hit = caster.first_hit(origin, first.gravity, HUGE_VAL);
                if (hit < 0) continue;
                slab_points[ix].push_back(origin);
                slab_patches[ix].push_back(first.main_destination[patches.patch_of_triangle[size_t(hit)]]);
                slab_cells[ix].push_back({ix, iy, iz});
            }
    });
    progress.check();
    PowderSamples samples;
    samples.sample_volume = spacing * spacing * spacing;
    samples.spacing = spacing;
    samples.origin = {lo[0] + 0.5 * spacing, lo[1] + 0.5 * spacing, lo[2] + 0.5 * spacing};
    for (int ix = 0; ix < nx; ++ix) {
        samples.position.insert(samples.position.end(), slab_points[ix].begin(), slab_points[ix].end());
        samples.rest_patch.insert(samples.rest_patch.end(), slab_patches[ix].begin(), slab_patches[ix].end());
        samples.cell.insert(samples.cell.end(), slab_cells[ix].begin(), slab_cells[ix].end());
    }
    if (samples.position.empty()) throw Error(FABVDB_ERR_BAD_INPUT, "the cavity holds no powder sample");
    progress.update(1.0);
    return samples;
}

}  // namespace fabvdb::powder
