//! low_res_surface: extract_mesh, then CGAL isotropic remeshing at the edge
//! length that gives the target triangle count on the extracted area, then
//! the crumbs and the voids dropped.
#include "volume/low_res_surface.h"

#include <cmath>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Surface_mesh.h>

#include "core/error.h"
#include "volume/extract_mesh.h"
#include "volume/memory_estimate.h"
#include "volume/mesh_shells.h"

namespace fabvdb::volume {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;

}  // namespace

double edge_length_for_triangles(double area, size_t target_triangles) {
    return std::sqrt(4.0 * area / (std::sqrt(3.0) * double(std::max<size_t>(target_triangles, 1))));
}

Mesh low_res_surface(const openvdb::FloatGrid& grid, size_t target_triangles, Progress& progress) {
    const Mesh extracted = extract_mesh(grid, 0.0, progress);
    if (extracted.triangles.empty()) throw Error(FABVDB_ERR_BAD_INPUT, "the level set has no surface");
    progress.stage("remesh low-resolution surface");
    SurfaceMesh surface;
    std::vector<SurfaceMesh::Vertex_index> vertex(extracted.vertices.size());
    for (size_t i = 0; i < extracted.vertices.size(); ++i) {
        const Vec3& p = extracted.vertices[i];
        vertex[i] = surface.add_vertex(Kernel::Point_3(p[0], p[1], p[2]));
    }
    for (const Triangle& t : extracted.triangles)
        if (surface.add_face(vertex[t[0]], vertex[t[1]], vertex[t[2]]) == SurfaceMesh::null_face())
            throw Error(FABVDB_ERR_INTERNAL, "the extracted level-set surface is not manifold");
    const double edge = edge_length_for_triangles(surface_area(extracted), target_triangles);
    progress.update(0.1);
    CGAL::Polygon_mesh_processing::isotropic_remeshing(faces(surface), edge, surface,
                                                       CGAL::parameters::number_of_iterations(3));
    progress.check();
    surface.collect_garbage();
    Mesh result;
    result.vertices.reserve(surface.number_of_vertices());
    for (const auto v : surface.vertices()) {
        const auto& p = surface.point(v);
        result.vertices.push_back({p.x(), p.y(), p.z()});
    }
    result.triangles.reserve(surface.number_of_faces());
    for (const auto f : surface.faces()) {
        Triangle t{};
        int k = 0;
        for (const auto v : vertices_around_face(surface.halfedge(f), surface)) t[k++] = uint32_t(v.idx());
        result.triangles.push_back(t);
    }
    // Crumbs: sub-voxel bubbles of the level set, a few triangles each, that
    // no part could be made of. Voids: a cast part cannot hold a closed void,
    // so the decomposition fills them (their walls take no part).
    const double crumb = std::pow(0.5 * edge, 3);
    std::vector<uint32_t> kept;
    for (const MeshShell& shell : split_shells(result))
        if (shell.volume >= crumb) kept.insert(kept.end(), shell.triangles.begin(), shell.triangles.end());
    if (kept.size() < result.triangles.size()) result = sub_mesh(result, kept);
    if (result.triangles.empty()) throw Error(FABVDB_ERR_BAD_INPUT, "the level set has no surface");
    progress.update(1.0);
    return result;
}

}  // namespace fabvdb::volume
