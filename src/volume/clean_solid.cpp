//! The clean-solid test (see clean_solid.h).
#include "volume/clean_solid.h"

#include <unordered_map>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

namespace fabvdb::volume {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;

//! Each directed edge once, and its reverse once.
bool edges_pair_up(const Mesh& mesh) {
    std::unordered_map<uint64_t, int> directed;
    directed.reserve(mesh.triangles.size() * 3);
    for (const Triangle& t : mesh.triangles) {
        if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) return false;
        for (int k = 0; k < 3; ++k) {
            const uint64_t key = (uint64_t(t[k]) << 32) | t[(k + 1) % 3];
            if (++directed[key] > 1) return false;
        }
    }
    for (const auto& [key, count] : directed) {
        const uint64_t reverse = (key << 32) | (key >> 32);
        if (directed.find(reverse) == directed.end()) return false;
    }
    return true;
}

}  // namespace

bool is_clean_solid(const Mesh& mesh, Progress& progress) {
    progress.stage("check input surface");
    if (mesh.triangles.empty() || !edges_pair_up(mesh)) return false;
    progress.update(0.2);
    // Only the vertices triangles use: CGAL's volume test fails on isolated ones.
    SurfaceMesh surface;
    std::vector<SurfaceMesh::Vertex_index> vertex(mesh.vertices.size(), SurfaceMesh::null_vertex());
    for (const Triangle& t : mesh.triangles)
        for (uint32_t v : t)
            if (vertex[v] == SurfaceMesh::null_vertex())
                vertex[v] = surface.add_vertex(
                    Kernel::Point_3(mesh.vertices[v][0], mesh.vertices[v][1], mesh.vertices[v][2]));
    for (const Triangle& t : mesh.triangles)
        if (surface.add_face(vertex[t[0]], vertex[t[1]], vertex[t[2]]) == SurfaceMesh::null_face()) return false;
    for (auto f : surface.faces())
        if (CGAL::Polygon_mesh_processing::is_degenerate_triangle_face(f, surface)) return false;
    progress.update(0.4);
    if (CGAL::Polygon_mesh_processing::does_self_intersect<CGAL::Parallel_if_available_tag>(surface)) return false;
    progress.update(0.9);
    const bool bounds_volume = CGAL::Polygon_mesh_processing::does_bound_a_volume(surface);
    progress.update(1.0);
    return bounds_volume;
}

}  // namespace fabvdb::volume
