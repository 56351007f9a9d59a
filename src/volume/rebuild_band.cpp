//! A fresh narrow band around an iso-surface (see rebuild_band.h).
#include "volume/rebuild_band.h"

#include <openvdb/tools/MeshToVolume.h>
#include <openvdb/tools/SignedFloodFill.h>
#include <openvdb/tools/VolumeToMesh.h>
#include <openvdb/tree/LeafManager.h>

#include "volume/extract_mesh.h"
#include "volume/progress_interrupter.h"

namespace fabvdb::volume {

openvdb::FloatGrid::Ptr rebuild_band(const openvdb::FloatGrid& grid, double isovalue, int half_band_voxels,
                                     Progress& progress) {
    const float surface = float(isovalue + surface_isovalue(grid));
    std::vector<openvdb::Vec3s> points;
    std::vector<openvdb::Vec3I> triangles;
    std::vector<openvdb::Vec4I> quads;
    openvdb::tools::volumeToMesh(grid, points, triangles, quads, surface, 0.0);
    progress.check();

    const openvdb::math::Transform& transform = grid.transform();
    for (openvdb::Vec3s& p : points) p = openvdb::Vec3s(transform.worldToIndex(openvdb::Vec3d(p)));
    quads.reserve(quads.size() + triangles.size());
    for (const openvdb::Vec3I& t : triangles)
        quads.emplace_back(t[0], t[1], t[2], openvdb::util::INVALID_IDX);
    triangles = {};
    openvdb::tools::QuadAndTriangleDataAdapter<openvdb::Vec3s, openvdb::Vec4I> adapter(points, quads);
    ProgressInterrupter interrupter(progress);
    const float band = float(half_band_voxels);
    openvdb::FloatGrid::Ptr rebuilt = openvdb::tools::meshToVolume<openvdb::FloatGrid>(
        interrupter, adapter, transform, band, band, openvdb::tools::UNSIGNED_DISTANCE_FIELD);
    progress.check();

    openvdb::tree::LeafManager<openvdb::FloatTree> leaves(rebuilt->tree());
    leaves.foreach([&](openvdb::FloatTree::LeafNodeType& leaf, size_t) {
        auto accessor = grid.getConstAccessor();
        for (auto voxel = leaf.beginValueOn(); voxel; ++voxel)
            if (accessor.getValue(voxel.getCoord()) < surface) voxel.setValue(-*voxel);
    });
    openvdb::tools::signedFloodFill(rebuilt->tree());
    progress.check();
    rebuilt->setTransform(transform.copy());
    rebuilt->setGridClass(openvdb::GRID_LEVEL_SET);
    rebuilt->setName(grid.getName());
    return rebuilt;
}

}  // namespace fabvdb::volume
