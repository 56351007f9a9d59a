//! The clean-solid test (see clean_solid.h).
#include "volume/clean_solid.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Surface_mesh.h>

#include "volume/closed_manifold.h"
#include "volume/crossing_pairs.h"

namespace fabvdb::volume {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;

Kernel::Point_3 point(const Vec3& p) { return Kernel::Point_3(p[0], p[1], p[2]); }

bool has_degenerate_triangle(const Mesh& mesh) {
    for (const Triangle& t : mesh.triangles)
        if (CGAL::collinear(point(mesh.vertices[t[0]]), point(mesh.vertices[t[1]]), point(mesh.vertices[t[2]])))
            return true;
    return false;
}

}  // namespace

bool is_clean_solid(const Mesh& mesh, Progress& progress) {
    progress.stage("check input surface");
    if (mesh.triangles.empty() || !is_closed_manifold(mesh) || has_degenerate_triangle(mesh)) return false;
    progress.update(0.2);
    if (!crossing_pairs(mesh).empty()) return false;
    progress.update(0.8);
    // Only the vertices triangles use: CGAL's volume test fails on isolated ones.
    SurfaceMesh surface;
    std::vector<SurfaceMesh::Vertex_index> vertex(mesh.vertices.size(), SurfaceMesh::null_vertex());
    for (const Triangle& t : mesh.triangles)
        for (uint32_t v : t)
            if (vertex[v] == SurfaceMesh::null_vertex()) vertex[v] = surface.add_vertex(point(mesh.vertices[v]));
    for (const Triangle& t : mesh.triangles)
        if (surface.add_face(vertex[t[0]], vertex[t[1]], vertex[t[2]]) == SurfaceMesh::null_face()) return false;
    // CGAL also accepts a mesh turned wholly inside out (it bounds the
    // unbounded complement); its volume is negative.
    const bool bounds_volume =
        CGAL::Polygon_mesh_processing::does_bound_a_volume(surface) && signed_volume(mesh) > 0.0;
    progress.update(1.0);
    return bounds_volume;
}

}  // namespace fabvdb::volume
