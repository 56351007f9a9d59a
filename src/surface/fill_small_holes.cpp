//! Filling small holes with faired patches (see fill_small_holes.h).
#define CGAL_EIGEN3_ENABLED  // fairing solves with Eigen (linked by this module)
#include "surface/fill_small_holes.h"

#include <cmath>
#include <iterator>
#include <vector>

#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>

#include "surface/cgal_surface_mesh.h"

namespace fabvdb::surface {

namespace {

using SurfaceMesh = CgalSurfaceMesh;
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
    std::optional<SurfaceMesh> converted = to_cgal_surface_mesh(mesh);
    if (!converted) return std::nullopt;
    SurfaceMesh& surface = *converted;

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
    std::optional<Mesh> back = from_cgal_surface_mesh(surface);
    if (!back) return std::nullopt;
    filled.mesh = std::move(*back);
    return filled;
}

}  // namespace fabvdb::surface
