//! Mesh to CGAL Surface_mesh and back (see cgal_surface_mesh.h).
#include "surface/cgal_surface_mesh.h"

#include <cstddef>
#include <vector>

#include <CGAL/Polygon_mesh_processing/polygon_mesh_to_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

namespace fabvdb::surface {

namespace PMP = CGAL::Polygon_mesh_processing;

std::optional<CgalSurfaceMesh> to_cgal_surface_mesh(const Mesh& mesh) {
    std::vector<CGAL::Epick::Point_3> points;
    points.reserve(mesh.vertices.size());
    for (const Vec3& p : mesh.vertices) points.emplace_back(p[0], p[1], p[2]);
    std::vector<std::vector<std::size_t>> polygons;
    polygons.reserve(mesh.triangles.size());
    for (const Triangle& t : mesh.triangles) polygons.push_back({t[0], t[1], t[2]});
    if (!PMP::is_polygon_soup_a_polygon_mesh(polygons)) return std::nullopt;
    CgalSurfaceMesh surface;
    PMP::polygon_soup_to_polygon_mesh(points, polygons, surface);
    return surface;
}

std::optional<Mesh> from_cgal_surface_mesh(const CgalSurfaceMesh& surface) {
    std::vector<CGAL::Epick::Point_3> points;
    std::vector<std::vector<std::size_t>> polygons;
    PMP::polygon_mesh_to_polygon_soup(surface, points, polygons);
    Mesh mesh;
    mesh.vertices.reserve(points.size());
    for (const auto& p : points) mesh.vertices.push_back({p.x(), p.y(), p.z()});
    mesh.triangles.reserve(polygons.size());
    for (const auto& polygon : polygons) {
        if (polygon.size() != 3) return std::nullopt;
        mesh.triangles.push_back({uint32_t(polygon[0]), uint32_t(polygon[1]), uint32_t(polygon[2])});
    }
    return mesh;
}

}  // namespace fabvdb::surface
