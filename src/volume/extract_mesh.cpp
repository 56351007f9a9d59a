//! Extraction of a level set's zero iso-surface (see extract_mesh.h).
#include "volume/extract_mesh.h"

#include <algorithm>
#include <cmath>

#include <openvdb/tools/VolumeToMesh.h>

#include "core/error.h"
#include "volume/mesh_shells.h"
#include "volume/part_coincident_vertices.h"

namespace fabvdb::volume {

double surface_isovalue(const openvdb::FloatGrid& grid) { return 1e-4 * grid.voxelSize()[0]; }

Mesh extract_mesh(const openvdb::FloatGrid& grid, double adaptivity, Progress& progress, uint64_t* shells_dropped) {
    if (!(adaptivity >= 0.0 && adaptivity <= 1.0))
        throw Error(FABVDB_ERR_INVALID_ARGUMENT, "adaptivity must be in [0, 1]");
    progress.stage("extract surface");
    std::vector<openvdb::Vec3s> points;
    std::vector<openvdb::Vec3I> triangles;
    std::vector<openvdb::Vec4I> quads;
    openvdb::tools::volumeToMesh(grid, points, triangles, quads, surface_isovalue(grid), adaptivity);
    progress.update(0.8);

    Mesh mesh;
    mesh.vertices.reserve(points.size());
    for (const openvdb::Vec3s& p : points) mesh.vertices.push_back({double(p[0]), double(p[1]), double(p[2])});
    mesh.triangles.reserve(triangles.size() + 2 * quads.size());
    // OpenVDB winds its polygons clockwise seen from outside (negative inside):
    // every polygon is reversed to face outward.
    for (const openvdb::Vec3I& t : triangles) mesh.triangles.push_back({t[2], t[1], t[0]});
    for (const openvdb::Vec4I& q : quads) {
        if (squared_distance(mesh.vertices[q[0]], mesh.vertices[q[2]]) <=
            squared_distance(mesh.vertices[q[1]], mesh.vertices[q[3]])) {
            mesh.triangles.push_back({q[3], q[2], q[0]});
            mesh.triangles.push_back({q[2], q[1], q[0]});
        } else {
            mesh.triangles.push_back({q[3], q[1], q[0]});
            mesh.triangles.push_back({q[3], q[2], q[1]});
        }
    }
    part_coincident_vertices(mesh);
    // Shells under an eighth of a voxel in volume are sign noise of a few
    // voxels, no feature the grid can hold: crumbs; flat shells are slivers
    // that a writer would refuse (mesh_shells.h).
    const MeshShellCounts noise = drop_small_or_flat_shells(mesh, std::pow(0.5 * grid.voxelSize()[0], 3));
    if (shells_dropped) *shells_dropped = noise.dropped;
    progress.update(1.0);
    return mesh;
}

}  // namespace fabvdb::volume
