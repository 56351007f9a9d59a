//! Exact disjointness of the cavity and outer surfaces (see surfaces_disjoint.h).
#include "volume/surfaces_disjoint.h"

#include <atomic>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/error.h"

namespace fabvdb::volume {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Triangle3 = Kernel::Triangle_3;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, std::vector<Triangle3>::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Triangle3 triangle(const Mesh& mesh, const fabvdb::Triangle& t) {
    const auto point = [&](uint32_t v) {
        return Kernel::Point_3(mesh.vertices[v][0], mesh.vertices[v][1], mesh.vertices[v][2]);
    };
    return Triangle3(point(t[0]), point(t[1]), point(t[2]));
}

}  // namespace

void require_disjoint_surfaces(const Mesh& outer, const Mesh& cavity, const std::string& what, Progress& progress) {
    progress.stage("check wall separation");
    std::vector<Triangle3> outer_triangles;
    outer_triangles.reserve(outer.triangles.size());
    for (const fabvdb::Triangle& t : outer.triangles) outer_triangles.push_back(triangle(outer, t));
    Tree tree(outer_triangles.begin(), outer_triangles.end());
    tree.build();
    progress.update(0.3);
    std::atomic<size_t> touching{0};
    tbb::parallel_for(tbb::blocked_range<size_t>(0, cavity.triangles.size(), 1024),
                      [&](const tbb::blocked_range<size_t>& range) {
                          for (size_t i = range.begin(); i != range.end(); ++i) {
                              if (progress.cancelled()) return;
                              if (tree.do_intersect(triangle(cavity, cavity.triangles[i]))) ++touching;
                          }
                      });
    progress.check();
    progress.update(1.0);
    if (touching > 0)
        throw Error(FABVDB_ERR_INTERNAL, what + ": " + std::to_string(touching.load()) +
                                             " cavity triangles touch the outer surface");
}

}  // namespace fabvdb::volume
