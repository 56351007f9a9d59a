//! `fabvdb repair` as one operation (see repair.h).
#include "volume/repair.h"

#include <algorithm>
#include <chrono>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include "core/error.h"
#include "volume/drop_small_shells.h"
#include "volume/extract_mesh.h"
#include "volume/rebuild_band.h"
#include "volume/snap_to_mesh.h"

namespace fabvdb::volume {

namespace {

template <class Body>
auto timed(std::map<std::string, double>& timings, const char* stage, const Body& body) {
    const auto start = std::chrono::steady_clock::now();
    auto result = body();
    timings[stage] += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

// Whether two triangles of the mesh intersect other than along shared edges
// and corners (CGAL's exact predicates), or the mesh is not a 2-manifold.
bool self_intersects(const Mesh& mesh) {
    using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
    namespace PMP = CGAL::Polygon_mesh_processing;
    std::vector<Point> points;
    points.reserve(mesh.vertices.size());
    for (const Vec3& v : mesh.vertices) points.emplace_back(v[0], v[1], v[2]);
    std::vector<std::vector<std::size_t>> polygons;
    polygons.reserve(mesh.triangles.size());
    for (const Triangle& t : mesh.triangles) polygons.push_back({t[0], t[1], t[2]});
    if (!PMP::is_polygon_soup_a_polygon_mesh(polygons)) return true;
    CGAL::Surface_mesh<Point> surface;
    PMP::polygon_soup_to_polygon_mesh(points, polygons, surface);
    return PMP::does_self_intersect<CGAL::Parallel_if_available_tag>(surface);
}

// Walls thinner than a voxel extract as two sheets through the same cells,
// which may touch: such a solid is grown by half a voxel (at most twice)
// until its surface is clean.
Mesh extract_clean_surface(openvdb::FloatGrid::Ptr& grid, double adaptivity, int half_band, Progress& progress) {
    Mesh mesh = extract_mesh(*grid, adaptivity, progress);
    for (int attempt = 0; attempt < 2 && self_intersects(mesh); ++attempt) {
        progress.stage("thicken thin walls");
        grid = rebuild_band(*grid, 0.5 * grid->voxelSize()[0], half_band, progress);
        mesh = extract_mesh(*grid, adaptivity, progress);
    }
    return mesh;
}

}  // namespace

double voxel_size_for_resolution(const Mesh& mesh, int resolution, const std::string& input_name) {
    if (resolution < 8) throw Error(FABVDB_ERR_INVALID_ARGUMENT, "resolution must be >= 8 voxels");
    const BoundingBox box = bounding_box(mesh);
    const double longest = std::max({box.max[0] - box.min[0], box.max[1] - box.min[1], box.max[2] - box.min[2]});
    if (!(longest > 0.0)) throw Error(FABVDB_ERR_BAD_INPUT, input_name + ": the mesh has no extent (no triangle, or all its points coincide)");
    return longest / resolution;
}

RepairResult repair(const Mesh& mesh, const RepairOptions& options, Progress& progress) {
    RepairResult result;
    result.grid = signed_distance_from_mesh(mesh, options.distance, progress, &result.distance);
    auto& timings = result.distance.timings;
    const ShellCounts shells = timed(timings, "shells", [&] {
        return drop_small_shells(result.grid, options.min_shell_volume, progress);
    });
    result.shells_kept = shells.kept;
    result.shells_dropped = shells.dropped;
    if (shells.kept == 0)
        throw Error(FABVDB_ERR_BAD_INPUT, options.distance.input_name + ": every shell is smaller than the minimum shell volume");
    result.distance.active_voxels = result.grid->activeVoxelCount();
    if (!options.extract) return result;
    result.mesh = timed(timings, "extract surface", [&] {
        return extract_clean_surface(result.grid, options.adaptivity, options.distance.half_band_voxels, progress);
    });
    if (options.snap)
        result.snapped_vertices = timed(timings, "snap", [&] {
            return snap_to_mesh(result.mesh, mesh, result.grid->voxelSize()[0], progress);
        });
    return result;
}

}  // namespace fabvdb::volume
