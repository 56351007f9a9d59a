//! Cutting a mesh along its crossings (see cut_along_crossings.h).
#include "volume/cut_along_crossings.h"

#include <algorithm>
#include <exception>
#include <tuple>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Surface_mesh.h>

namespace fabvdb::volume {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;

Point point(const Vec3& p) { return Point(p[0], p[1], p[2]); }

//! Whether a corner of b that is not a corner of a lies exactly in a's
//! plane (exact predicate): b touches a there, or lies in its plane.
bool touches_plane(const Mesh& mesh, uint32_t a, uint32_t b) {
    const Triangle& s = mesh.triangles[a];
    const Triangle& t = mesh.triangles[b];
    for (int k = 0; k < 3; ++k) {
        if (t[k] == s[0] || t[k] == s[1] || t[k] == s[2]) continue;
        if (CGAL::orientation(point(mesh.vertices[s[0]]), point(mesh.vertices[s[1]]), point(mesh.vertices[s[2]]),
                              point(mesh.vertices[t[k]])) == CGAL::COPLANAR)
            return true;
    }
    return false;
}

}  // namespace

std::optional<CutSurface> cut_along_crossings(const Mesh& mesh,
                                              const std::vector<std::pair<uint32_t, uint32_t>>& crossings) {
    for (const auto& [a, b] : crossings)
        if (touches_plane(mesh, a, b) || touches_plane(mesh, b, a)) return std::nullopt;
    std::vector<char> crossing(mesh.triangles.size(), 0);
    for (const auto& [a, b] : crossings) crossing[a] = crossing[b] = 1;
    SurfaceMesh part;
    std::vector<uint32_t> local(mesh.vertices.size(), UINT32_MAX), global;
    CutSurface surface;
    surface.mesh.vertices = mesh.vertices;
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        if (!crossing[t]) {
            surface.mesh.triangles.push_back(mesh.triangles[t]);
            continue;
        }
        SurfaceMesh::Vertex_index corner[3];
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = mesh.triangles[t][k];
            if (local[v] == UINT32_MAX) {
                local[v] = uint32_t(global.size());
                global.push_back(v);
                part.add_vertex(point(mesh.vertices[v]));
            }
            corner[k] = SurfaceMesh::Vertex_index(local[v]);
        }
        if (part.add_face(corner[0], corner[1], corner[2]) == SurfaceMesh::null_face()) return std::nullopt;
    }
    surface.first_piece = surface.mesh.triangles.size();

    auto cut = part.add_property_map<SurfaceMesh::Edge_index, bool>("e:cut", false).first;
    try {
        CGAL::Polygon_mesh_processing::experimental::autorefine(
            part, CGAL::Polygon_mesh_processing::parameters::edge_is_constrained_map(cut));
    } catch (const std::exception&) {
        return std::nullopt;  // a configuration the corefinement does not handle
    }

    // The first vertices are the input's, in order; the cut points follow.
    // The autorefinement orders the cut points, the pieces and their corners
    // differently from run to run: they are put in order of position (the
    // cut points, each piece from its least corner, the pieces), so that the
    // result is the same every run.
    const auto position = [&](SurfaceMesh::Vertex_index v) {
        const Point& p = part.point(v);
        return Vec3{p.x(), p.y(), p.z()};
    };
    std::vector<uint32_t> index(part.number_of_vertices() + part.number_of_removed_vertices(), UINT32_MAX);
    std::vector<SurfaceMesh::Vertex_index> cut_points;
    for (SurfaceMesh::Vertex_index v : part.vertices()) {
        if (size_t(v) < global.size()) {
            index[v] = global[v];
            if (position(v) != mesh.vertices[global[v]]) return std::nullopt;
        } else {
            cut_points.push_back(v);
        }
    }
    std::sort(cut_points.begin(), cut_points.end(),
              [&](SurfaceMesh::Vertex_index a, SurfaceMesh::Vertex_index b) { return position(a) < position(b); });
    for (SurfaceMesh::Vertex_index v : cut_points) {
        index[v] = uint32_t(surface.mesh.vertices.size());
        surface.mesh.vertices.push_back(position(v));
    }
    const std::vector<Vec3>& at = surface.mesh.vertices;
    std::vector<Triangle> pieces;
    for (SurfaceMesh::Face_index f : part.faces()) {
        Triangle t;
        int k = 0;
        for (SurfaceMesh::Vertex_index v : CGAL::vertices_around_face(part.halfedge(f), part)) {
            if (k == 3) return std::nullopt;
            t[k++] = index[v];
        }
        if (k != 3) return std::nullopt;
        std::rotate(t.begin(), std::min_element(t.begin(), t.end(), [&](uint32_t a, uint32_t b) { return at[a] < at[b]; }),
                    t.end());
        pieces.push_back(t);
    }
    std::sort(pieces.begin(), pieces.end(), [&](const Triangle& a, const Triangle& b) {
        return std::tie(at[a[0]], at[a[1]], at[a[2]]) < std::tie(at[b[0]], at[b[1]], at[b[2]]);
    });
    surface.mesh.triangles.insert(surface.mesh.triangles.end(), pieces.begin(), pieces.end());
    for (SurfaceMesh::Edge_index e : part.edges())
        if (cut[e]) {
            const uint32_t a = index[part.source(part.halfedge(e))], b = index[part.target(part.halfedge(e))];
            surface.cut_edges.insert(CutSurface::edge_key(a, b));
            surface.cut_edges.insert(CutSurface::edge_key(b, a));
        }
    return surface;
}

}  // namespace fabvdb::volume
