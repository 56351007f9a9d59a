//! Sampling and dropping the cavity's powder (see powder_drop.h).
#include "powder/powder_drop.h"

#include <cmath>

#include <tbb/parallel_for.h>

#include "core/error.h"

namespace fabvdb::powder {

PowderSamples drop_cavity_powder(const openvdb::FloatGrid& cavity, const CavityPatches& patches,
                                 const volume::SurfaceRayCaster& caster, const OrientationFlow& first, size_t max_samples,
                                 const std::string& input_name, Progress& progress) {
    progress.stage("powder drop");
    const openvdb::CoordBBox box = cavity.evalActiveVoxelBoundingBox();
    if (box.empty()) throw Error(FABVDB_ERR_BAD_INPUT, "the cavity is empty");
    const openvdb::Vec3d lo = cavity.indexToWorld(box.min()), hi = cavity.indexToWorld(box.max());
    const openvdb::Vec3d extent = hi - lo;
    const double voxel = cavity.voxelSize()[0];
    const double spacing =
        std::max(voxel, std::cbrt(extent[0] * extent[1] * extent[2] / double(std::max<size_t>(max_samples, 1))));
    // Samples at the centres of a grid of cells `step` wide from lo, shifted
    // by `shift` cells.
    const auto sample = [&](double step, double shift) {
        const int nx = int(extent[0] / step) + 1, ny = int(extent[1] / step) + 1, nz = int(extent[2] / step) + 1;
        // Candidate points per x slab, kept in order so the result is deterministic.
        std::vector<std::vector<Vec3>> slab_points(nx);
        std::vector<std::vector<uint32_t>> slab_patches(nx);
        std::vector<std::vector<std::array<int32_t, 3>>> slab_cells(nx);
        tbb::parallel_for(0, nx, [&](int ix) {
            if (progress.cancelled()) return;
            auto accessor = cavity.getConstAccessor();
            for (int iy = 0; iy < ny; ++iy)
                for (int iz = 0; iz < nz; ++iz) {
                    const openvdb::Vec3d p = lo + openvdb::Vec3d(ix + shift, iy + shift, iz + shift) * step;
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
        samples.sample_volume = step * step * step;
        samples.spacing = step;
        samples.origin = {lo[0] + shift * step, lo[1] + shift * step, lo[2] + shift * step};
        for (int ix = 0; ix < nx; ++ix) {
            samples.position.insert(samples.position.end(), slab_points[ix].begin(), slab_points[ix].end());
            samples.rest_patch.insert(samples.rest_patch.end(), slab_patches[ix].begin(), slab_patches[ix].end());
            samples.cell.insert(samples.cell.end(), slab_cells[ix].begin(), slab_cells[ix].end());
        }
        return samples;
    };
    PowderSamples samples = sample(spacing, 0.5);
    // A cavity one voxel thin can lie wholly between the shifted centres:
    // then its own voxels are the samples.
    if (samples.position.empty()) samples = sample(voxel, 0.0);
    if (samples.position.empty())
        throw Error(FABVDB_ERR_BAD_INPUT, input_name + ": its cavity holds no powder sample: no voxel of it is "
                                                       "reached from above by a ray to its surface");
    progress.update(1.0);
    return samples;
}

}  // namespace fabvdb::powder
