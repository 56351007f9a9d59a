//! A level set carried onto another transform by sampling (see resample_level_set.h).
#include "volume/resample_level_set.h"

#include <cmath>

#include <tbb/parallel_reduce.h>

#include <openvdb/tools/Interpolation.h>
#include <openvdb/tools/Prune.h>
#include <openvdb/tools/SignedFloodFill.h>
#include <openvdb/tree/LeafManager.h>

#include "core/error.h"

namespace fabvdb::volume {

namespace {

//! The voxels of `transform` at the corners of the cells holding the images
//! of the band's voxels: on voxels no smaller than the source's, every voxel
//! of the new transform in the band's reach is such a corner.
struct BandImages {
    const openvdb::FloatGrid& grid;
    const openvdb::math::Transform& transform;
    const Progress& progress;
    openvdb::MaskTree mask;

    BandImages(const openvdb::FloatGrid& grid_, const openvdb::math::Transform& transform_, const Progress& progress_)
        : grid(grid_), transform(transform_), progress(progress_) {}
    BandImages(BandImages& other, tbb::split) : grid(other.grid), transform(other.transform), progress(other.progress) {}

    void operator()(const openvdb::tree::LeafManager<const openvdb::FloatTree>::LeafRange& range) {
        if (progress.cancelled()) return;
        openvdb::tree::ValueAccessor<openvdb::MaskTree> marks(mask);
        for (auto leaf = range.begin(); leaf; ++leaf)
            for (auto voxel = leaf->cbeginValueOn(); voxel; ++voxel) {
                const openvdb::Vec3d image =
                    transform.worldToIndex(grid.transform().indexToWorld(voxel.getCoord()));
                const openvdb::Coord base = openvdb::Coord::floor(image);
                for (int dx = 0; dx < 2; ++dx)
                    for (int dy = 0; dy < 2; ++dy)
                        for (int dz = 0; dz < 2; ++dz) marks.setValueOn(base.offsetBy(dx, dy, dz));
            }
    }
    void join(BandImages& other) { mask.topologyUnion(other.mask); }
};

}  // namespace

openvdb::FloatGrid::Ptr resample_level_set(const openvdb::FloatGrid& grid, const openvdb::math::Transform& transform,
                                           const Progress& progress) {
    if (!transform.hasUniformScale() || transform.voxelSize()[0] < grid.voxelSize()[0] * (1 - 1e-9))
        throw Error(FABVDB_ERR_INVALID_ARGUMENT, "resampling a level set onto smaller or non-cubic voxels");
    const float background = grid.background();
    openvdb::FloatGrid::Ptr out = openvdb::FloatGrid::create(background);
    out->setTransform(transform.copy());
    out->setGridClass(openvdb::GRID_LEVEL_SET);
    out->setName(grid.getName());

    openvdb::tree::LeafManager<const openvdb::FloatTree> source(grid.tree());
    BandImages images(grid, transform, progress);
    tbb::parallel_reduce(source.leafRange(), images);
    progress.check();
    out->tree().topologyUnion(images.mask);

    openvdb::tree::LeafManager<openvdb::FloatTree> leaves(out->tree());
    leaves.foreach([&](openvdb::FloatTree::LeafNodeType& leaf, size_t) {
        if (progress.cancelled()) return;
        const openvdb::FloatGrid::ConstAccessor access = grid.getConstAccessor();
        const openvdb::tools::GridSampler<openvdb::FloatGrid::ConstAccessor, openvdb::tools::BoxSampler> sampler(
            access, grid.transform());
        for (auto voxel = leaf.beginValueOn(); voxel; ++voxel) {
            const float value = float(sampler.wsSample(transform.indexToWorld(voxel.getCoord())));
            if (std::abs(value) < background) {
                voxel.setValue(value);
            } else {
                voxel.setValue(value < 0 ? -background : background);
                voxel.setValueOff();
            }
        }
    });
    progress.check();
    openvdb::tools::signedFloodFill(out->tree());
    openvdb::tools::pruneLevelSet(out->tree());
    progress.check();
    return out;
}

}  // namespace fabvdb::volume
