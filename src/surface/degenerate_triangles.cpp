//! Degenerate triangles by repeated index or CGAL's exact collinearity test.
#include "surface/degenerate_triangles.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace fabvdb::surface {

bool is_degenerate_triangle(const Mesh& mesh, const Triangle& t) {
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) return true;
    using Point = CGAL::Epick::Point_3;
    auto point = [&](uint32_t v) { return Point(mesh.vertices[v][0], mesh.vertices[v][1], mesh.vertices[v][2]); };
    return CGAL::collinear(point(t[0]), point(t[1]), point(t[2]));
}

std::vector<uint32_t> degenerate_triangles(const Mesh& mesh) {
    std::vector<uint32_t> found;
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
        if (is_degenerate_triangle(mesh, mesh.triangles[t])) found.push_back(uint32_t(t));
    return found;
}

}  // namespace fabvdb::surface
