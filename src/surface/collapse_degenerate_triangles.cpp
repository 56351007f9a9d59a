//! Degenerate triangles removed by edge flips and collapses (see
//! collapse_degenerate_triangles.h).
#include "surface/collapse_degenerate_triangles.h"

#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>

#include "surface/cgal_surface_mesh.h"
#include "surface/degenerate_triangles.h"

namespace fabvdb::surface {

std::optional<CollapsedDegenerates> collapse_degenerate_triangles(const Mesh& mesh, Progress& progress) {
    CollapsedDegenerates result;
    result.degenerate = degenerate_triangles(mesh).size();
    if (result.degenerate == 0) return std::nullopt;
    std::optional<CgalSurfaceMesh> surface = to_cgal_surface_mesh(mesh);
    if (!surface) return std::nullopt;
    progress.check();
    if (!CGAL::Polygon_mesh_processing::remove_degenerate_faces(*surface)) return std::nullopt;
    surface->collect_garbage();
    std::optional<Mesh> back = from_cgal_surface_mesh(*surface);
    if (!back || back->triangles.empty() || !degenerate_triangles(*back).empty()) return std::nullopt;
    result.mesh = std::move(*back);
    return result;
}

}  // namespace fabvdb::surface
