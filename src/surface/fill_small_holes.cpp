//! Filling small holes with faired patches (see fill_small_holes.h).
#define CGAL_EIGEN3_ENABLED  // fairing solves with Eigen (linked by this module)
#include "surface/fill_small_holes.h"

#include <iterator>
#include <vector>

#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>

#include "surface/cgal_surface_mesh.h"
#include "surface/mesh_topology.h"

namespace fabvdb::surface {

namespace {

using SurfaceMesh = CgalSurfaceMesh;
using Halfedge = SurfaceMesh::Halfedge_index;
namespace PMP = CGAL::Polygon_mesh_processing;

//! Whether the mesh, on its own indices, may be an oriented 2-manifold whose
//! boundary loops are all at most `max_diameter` across: told from its edges
//! alone, before the costlier conversion that decides (a large scan's open
//! side is found in a fraction of the conversion's time).
bool may_have_only_small_holes(const Mesh& mesh, double max_diameter) {
    const EdgeTable edges = build_edge_table(mesh);
    for (size_t e = 0; e < edges.edge_count(); ++e) {
        const size_t uses = edges.use_count(e);
        if (uses > 2 || (uses == 2 && edges.uses[edges.begin[e]].forward == edges.uses[edges.begin[e] + 1].forward))
            return false;
    }
    const std::vector<std::vector<uint32_t>> loops = boundary_loops(mesh, edges);
    if (loops.empty()) return false;
    for (const std::vector<uint32_t>& loop : loops) {
        BoundingBox box{mesh.vertices[loop[0]], mesh.vertices[loop[0]]};
        for (uint32_t v : loop) box.add(mesh.vertices[v]);
        if (!(box.diagonal() <= max_diameter)) return false;
    }
    return true;
}

}  // namespace

std::optional<FilledHoles> fill_small_holes(const Mesh& mesh, double max_diameter, Progress& progress) {
    if (!may_have_only_small_holes(mesh, max_diameter)) return std::nullopt;
    std::optional<SurfaceMesh> converted = to_cgal_surface_mesh(mesh);
    if (!converted) return std::nullopt;
    SurfaceMesh& surface = *converted;

    std::vector<Halfedge> borders;
    PMP::extract_boundary_cycles(surface, std::back_inserter(borders));
    if (borders.empty()) return std::nullopt;

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
