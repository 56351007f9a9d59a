//! Filling small holes with faired patches (see fill_small_holes.h).
#define CGAL_EIGEN3_ENABLED  // fairing solves with Eigen (linked by this module)
#include "surface/fill_small_holes.h"

#include <cmath>
#include <iterator>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/polygon_mesh_to_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>

namespace fabvdb::surface {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;
using Halfedge = SurfaceMesh::Halfedge_index;
namespace PMP = CGAL::Polygon_mesh_processing;

double loop_diameter(const SurfaceMesh& surface, Halfedge border) {
    CGAL::Bbox_3 box;
    for (Halfedge h : CGAL::halfedges_around_face(border, surface)) box += surface.point(surface.target(h)).bbox();
    return std::sqrt((box.xmax() - box.xmin()) * (box.xmax() - box.xmin()) +
                     (box.ymax() - box.ymin()) * (box.ymax() - box.ymin()) +
                     (box.zmax() - box.zmin()) * (box.zmax() - box.zmin()));
}

}  // namespace

std::optional<FilledHoles> fill_small_holes(const Mesh& mesh, double max_diameter, Progress& progress) {
    std::vector<Point> points;
    points.reserve(mesh.vertices.size());
    for (const Vec3& p : mesh.vertices) points.emplace_back(p[0], p[1], p[2]);
    std::vector<std::vector<std::size_t>> polygons;
    polygons.reserve(mesh.triangles.size());
    for (const Triangle& t : mesh.triangles) polygons.push_back({t[0], t[1], t[2]});
    if (!PMP::is_polygon_soup_a_polygon_mesh(polygons)) return std::nullopt;
    SurfaceMesh surface;
    PMP::polygon_soup_to_polygon_mesh(points, polygons, surface);

    std::vector<Halfedge> borders;
    PMP::extract_boundary_cycles(surface, std::back_inserter(borders));
    if (borders.empty()) return std::nullopt;
    for (Halfedge border : borders)
        if (!(loop_diameter(surface, border) <= max_diameter)) return std::nullopt;

    FilledHoles filled;
    for (Halfedge border : borders) {
        progress.check();
        std::vector<SurfaceMesh::Face_index> faces;
        std::vector<SurfaceMesh::Vertex_index> vertices;
        const auto outcome = PMP::triangulate_refine_and_fair_hole(surface, border, std::back_inserter(faces),
                                                                   std::back_inserter(vertices));
        if (!std::get<0>(outcome) || faces.empty()) return std::nullopt;
        ++filled.holes;
        filled.added_triangles += faces.size();
    }
    points.clear();
    polygons.clear();
    PMP::polygon_mesh_to_polygon_soup(surface, points, polygons);
    for (const Point& p : points) filled.mesh.vertices.push_back({p.x(), p.y(), p.z()});
    for (const auto& polygon : polygons) {
        if (polygon.size() != 3) return std::nullopt;
        filled.mesh.triangles.push_back({uint32_t(polygon[0]), uint32_t(polygon[1]), uint32_t(polygon[2])});
    }
    return filled;
}

}  // namespace fabvdb::surface
