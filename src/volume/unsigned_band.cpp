//! The unsigned band of a mesh (see unsigned_band.h).
#include "volume/unsigned_band.h"

#include <openvdb/tools/MeshToVolume.h>

#include "volume/progress_interrupter.h"

namespace fabvdb::volume {

openvdb::FloatGrid::Ptr unsigned_band(const Mesh& mesh, const openvdb::math::Transform& transform, float half_band,
                                      Progress& progress, openvdb::Int32Grid* closest_triangle) {
    std::vector<openvdb::Vec3s> points(mesh.vertices.size());
    for (size_t i = 0; i < points.size(); ++i)
        points[i] = openvdb::Vec3s(
            transform.worldToIndex(openvdb::Vec3d(mesh.vertices[i][0], mesh.vertices[i][1], mesh.vertices[i][2])));
    std::vector<openvdb::Vec3I> triangles(mesh.triangles.size());
    for (size_t i = 0; i < triangles.size(); ++i)
        triangles[i] = openvdb::Vec3I(mesh.triangles[i][0], mesh.triangles[i][1], mesh.triangles[i][2]);
    openvdb::tools::QuadAndTriangleDataAdapter<openvdb::Vec3s, openvdb::Vec3I> adapter(points, triangles);
    ProgressInterrupter interrupter(progress);
    openvdb::FloatGrid::Ptr grid = openvdb::tools::meshToVolume<openvdb::FloatGrid>(
        interrupter, adapter, transform, half_band, half_band, openvdb::tools::UNSIGNED_DISTANCE_FIELD,
        closest_triangle);
    progress.check();
    return grid;
}

}  // namespace fabvdb::volume
