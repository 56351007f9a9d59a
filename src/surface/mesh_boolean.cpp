//! Boolean operations on closed meshes (see mesh_boolean.h).
#include "surface/mesh_boolean.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <array>

#include "core/error.h"

namespace fabvdb::surface {

namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Solid = CGAL::Surface_mesh<Kernel::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

// The mesh checked with exact predicates on its double coordinates (Epick:
// the checks construct nothing, so they need no exact constructions), then
// copied to exact points for the corefinement.
Solid validated_solid(const Mesh& mesh, const std::string& name) {
    using Checked = CGAL::Surface_mesh<CGAL::Epick::Point_3>;
    validate_mesh(mesh, name);
    if (mesh.triangles.empty()) throw Error(FABVDB_ERR_BAD_INPUT, name + " has no triangles");
    std::vector<CGAL::Epick::Point_3> points;
    points.reserve(mesh.vertices.size());
    for (const Vec3& p : mesh.vertices) points.emplace_back(p[0], p[1], p[2]);
    std::vector<std::vector<std::size_t>> polygons;
    polygons.reserve(mesh.triangles.size());
    for (const Triangle& t : mesh.triangles) polygons.push_back({t[0], t[1], t[2]});
    if (!PMP::is_polygon_soup_a_polygon_mesh(polygons))
        throw Error(FABVDB_ERR_BAD_INPUT, name + " is not a 2-manifold, consistently oriented surface");
    Checked checked;
    PMP::polygon_soup_to_polygon_mesh(points, polygons, checked);
    if (!CGAL::is_closed(checked)) throw Error(FABVDB_ERR_BAD_INPUT, name + " is not closed (it has boundary edges)");
    if (PMP::does_self_intersect(checked)) throw Error(FABVDB_ERR_BAD_INPUT, name + " intersects itself");
    if (!PMP::is_outward_oriented(checked))
        throw Error(FABVDB_ERR_BAD_INPUT, name + " is inside out (its triangles face inward)");
    if (!PMP::does_bound_a_volume(checked))
        throw Error(FABVDB_ERR_BAD_INPUT, name + " does not bound a volume (inverted or nested shells)");
    Solid solid;
    solid.reserve(checked.number_of_vertices(), checked.number_of_edges(), checked.number_of_faces());
    std::vector<Solid::Vertex_index> exact(checked.number_of_vertices());
    for (Checked::Vertex_index v : checked.vertices()) {
        const auto& p = checked.point(v);
        exact[v] = solid.add_vertex(Kernel::Point_3(p.x(), p.y(), p.z()));
    }
    for (Checked::Face_index f : checked.faces()) {
        std::array<Solid::Vertex_index, 3> corners;
        int k = 0;
        for (Checked::Vertex_index v : CGAL::vertices_around_face(checked.halfedge(f), checked)) corners[k++] = exact[v];
        solid.add_face(corners[0], corners[1], corners[2]);
    }
    return solid;
}

// Rounds the exact result to doubles. Points closer than double precision
// can round to one position, leaving degenerate triangles, and points a
// hair apart make needles: both are collapsed away (CGAL
// remove_degenerate_faces, remove_almost_degenerate_faces) before the export.
Mesh to_mesh(const Solid& solid) {
    using Rounded = CGAL::Surface_mesh<CGAL::Epick::Point_3>;
    Rounded rounded;
    std::vector<Rounded::Vertex_index> handle(solid.number_of_vertices() + solid.number_of_removed_vertices());
    for (Solid::Vertex_index v : solid.vertices()) {
        const Kernel::Point_3& p = solid.point(v);
        handle[v] = rounded.add_vertex({CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
    }
    for (Solid::Face_index f : solid.faces()) {
        std::vector<Rounded::Vertex_index> corners;
        for (Solid::Vertex_index v : CGAL::vertices_around_face(solid.halfedge(f), solid)) corners.push_back(handle[v]);
        if (corners.size() != 3 || rounded.add_face(corners) == Rounded::null_face())
            throw Error(FABVDB_ERR_INTERNAL, "boolean result is not a triangle surface");
    }
    PMP::remove_degenerate_faces(rounded);
    // Needles whose shortest edge is under a ten-thousandth of a millimetre
    // (points rounding left nearly coincident, which a float STL file would
    // merge into a degenerate triangle) are collapsed; caps are left alone.
    PMP::experimental::remove_almost_degenerate_faces(rounded, -1.0, 1e3, 1e-4);
    rounded.collect_garbage();
    Mesh mesh;
    for (Rounded::Vertex_index v : rounded.vertices()) {
        const auto& p = rounded.point(v);
        mesh.vertices.push_back({p.x(), p.y(), p.z()});
    }
    for (Rounded::Face_index f : rounded.faces()) {
        Triangle t{};
        int k = 0;
        for (Rounded::Vertex_index v : CGAL::vertices_around_face(rounded.halfedge(f), rounded)) t[k++] = uint32_t(v);
        mesh.triangles.push_back(t);
    }
    return mesh;
}

const char* verb(BooleanOperation operation) {
    switch (operation) {
        case BooleanOperation::unite: return "union with";
        case BooleanOperation::subtract: return "subtraction of";
        case BooleanOperation::intersect: return "intersection with";
    }
    return "";
}

}  // namespace

Mesh mesh_boolean(const Mesh& first, const std::string& first_name, const std::vector<BooleanStep>& steps,
                  const Progress& progress) {
    Solid result = validated_solid(first, first_name);
    for (size_t i = 0; i < steps.size(); ++i) {
        const BooleanStep& step = steps[i];
        if (!step.operand) throw Error(FABVDB_ERR_INVALID_ARGUMENT, "boolean operand " + step.name + " is null");
        Solid operand = validated_solid(*step.operand, step.name);
        progress.check();
        Solid out;
        bool valid = false;
        switch (step.operation) {
            case BooleanOperation::unite: valid = PMP::corefine_and_compute_union(result, operand, out); break;
            case BooleanOperation::subtract: valid = PMP::corefine_and_compute_difference(result, operand, out); break;
            case BooleanOperation::intersect:
                valid = PMP::corefine_and_compute_intersection(result, operand, out);
                break;
        }
        if (!valid)
            throw Error(FABVDB_ERR_BAD_INPUT, std::string("the ") + verb(step.operation) + " " + step.name +
                                                  " would not give a 2-manifold solid (the solids touch along "
                                                  "an edge or at a point)");
        result = std::move(out);
    }
    return to_mesh(result);
}

}  // namespace fabvdb::surface
