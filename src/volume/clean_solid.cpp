//! The clean-solid test (see clean_solid.h).
#include "volume/clean_solid.h"

#include <atomic>
#include <cmath>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Surface_mesh.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "volume/closed_manifold.h"
#include "volume/crossing_pairs.h"
#include "volume/memory_estimate.h"
#include "volume/mesh_shells.h"

namespace fabvdb::volume {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;

Kernel::Point_3 point(const Vec3& p) { return Kernel::Point_3(p[0], p[1], p[2]); }

bool has_degenerate_triangle(const Mesh& mesh) {
    std::atomic<bool> degenerate{false};
    tbb::parallel_for(tbb::blocked_range<size_t>(0, mesh.triangles.size(), 4096),
                      [&](const tbb::blocked_range<size_t>& range) {
        for (size_t i = range.begin(); i != range.end() && !degenerate; ++i) {
            const Triangle& t = mesh.triangles[i];
            if (CGAL::collinear(point(mesh.vertices[t[0]]), point(mesh.vertices[t[1]]), point(mesh.vertices[t[2]])))
                degenerate = true;
        }
    });
    return degenerate;
}

//! Whether a closed oriented manifold whose triangles do not cross bounds a
//! volume. One such shell always bounds a region, outward exactly when its
//! volume is positive; several must also nest consistently (CGAL), and CGAL
//! also accepts a mesh turned wholly inside out (it bounds the unbounded
//! complement), whose volume is negative.
bool bounds_volume(const Mesh& mesh) {
    if (signed_volume(mesh) <= 0.0) return false;
    // A flat mesh or shell (a sliver tetrahedron) bounds no volume worth the
    // name (mesh_shells.h).
    const double diagonal = bounding_box(mesh).diagonal();
    if (2.0 * signed_volume(mesh) < 1e-4 * diagonal * surface_area(mesh)) return false;
    const std::vector<MeshShell> shells = split_shells(mesh);
    for (const MeshShell& shell : shells)
        if (is_flat_shell(mesh, shell, diagonal)) return false;
    if (shells.size() == 1) return true;
    // Only the vertices triangles use: CGAL's volume test fails on isolated ones.
    SurfaceMesh surface;
    std::vector<SurfaceMesh::Vertex_index> vertex(mesh.vertices.size(), SurfaceMesh::null_vertex());
    for (const Triangle& t : mesh.triangles)
        for (uint32_t v : t)
            if (vertex[v] == SurfaceMesh::null_vertex()) vertex[v] = surface.add_vertex(point(mesh.vertices[v]));
    for (const Triangle& t : mesh.triangles)
        if (surface.add_face(vertex[t[0]], vertex[t[1]], vertex[t[2]]) == SurfaceMesh::null_face()) return false;
    return CGAL::Polygon_mesh_processing::does_bound_a_volume(surface);
}

}  // namespace

SolidCheck check_solid(const Mesh& mesh, Progress& progress, const std::vector<char>& candidates) {
    progress.stage("check input surface");
    SolidCheck result;
    if (mesh.triangles.empty() || !is_closed_manifold(mesh) || has_degenerate_triangle(mesh)) return result;
    progress.update(0.2);
    result.crossings = crossing_pairs(mesh, candidates);
    if (!result.crossings.empty()) return result;
    progress.update(0.8);
    result.clean = bounds_volume(mesh);
    progress.update(1.0);
    return result;
}

}  // namespace fabvdb::volume
