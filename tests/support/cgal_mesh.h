//! CGAL views of a Mesh for the independent checks in tests/ and bench/: the
//! exact-predicates kernel's points and triangles, an AABB tree over
//! triangles for distances, and a Surface_mesh for CGAL's own predicates
//! (self-intersection, side of a closed mesh). Coordinates are copied
//! exactly; vertex i of the mesh is vertex i of the Surface_mesh.
//! Header-only; each conversion is one pass over the mesh.
#pragma once

#include <vector>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include "core/mesh.h"

namespace fabvdb::test::cgal {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Triangle3 = Kernel::Triangle_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, std::vector<Triangle3>::const_iterator>;
//! Built over a std::vector<Triangle3>, which must outlive it.
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

inline Point point(const Vec3& p) { return Point(p[0], p[1], p[2]); }

inline Triangle3 triangle(const Mesh& mesh, const Triangle& t) {
    return Triangle3(point(mesh.vertices[t[0]]), point(mesh.vertices[t[1]]), point(mesh.vertices[t[2]]));
}

inline std::vector<Triangle3> triangles_of(const Mesh& mesh) {
    std::vector<Triangle3> triangles;
    triangles.reserve(mesh.triangles.size());
    for (const Triangle& t : mesh.triangles) triangles.push_back(triangle(mesh, t));
    return triangles;
}

//! The mesh as a Surface_mesh. A face that would break 2-manifoldness is
//! left out, and then `*all_faces_added` (when given) is false.
inline SurfaceMesh surface_mesh_of(const Mesh& mesh, bool* all_faces_added = nullptr) {
    SurfaceMesh surface;
    std::vector<SurfaceMesh::Vertex_index> vertex;
    vertex.reserve(mesh.vertices.size());
    for (const Vec3& p : mesh.vertices) vertex.push_back(surface.add_vertex(point(p)));
    bool all = true;
    for (const Triangle& t : mesh.triangles)
        if (surface.add_face(vertex[t[0]], vertex[t[1]], vertex[t[2]]) == SurfaceMesh::null_face()) all = false;
    if (all_faces_added) *all_faces_added = all;
    return surface;
}

}  // namespace fabvdb::test::cgal
