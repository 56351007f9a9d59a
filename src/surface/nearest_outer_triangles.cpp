//! Nearest S_low triangle per input triangle (see nearest_outer_triangles.h).
#include "surface/nearest_outer_triangles.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>
#include <tbb/parallel_for.h>

#include "core/vec3_ops.h"

namespace fabvdb::surface {

std::vector<uint32_t> nearest_outer_triangles(const Mesh& input, const Mesh& outer) {
    using K = CGAL::Simple_cartesian<double>;
    const auto point = [](const Vec3& p) { return K::Point_3(p[0], p[1], p[2]); };
    std::vector<K::Triangle_3> triangles;
    triangles.reserve(outer.triangles.size());
    for (const Triangle& f : outer.triangles)
        triangles.emplace_back(point(outer.vertices[f[0]]), point(outer.vertices[f[1]]), point(outer.vertices[f[2]]));
    using Primitive = CGAL::AABB_triangle_primitive<K, std::vector<K::Triangle_3>::const_iterator>;
    CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>> tree(triangles.begin(), triangles.end());
    tree.accelerate_distance_queries();
    std::vector<uint32_t> nearest(input.triangles.size(), 0);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, input.triangles.size(), 1024),
                      [&](const tbb::blocked_range<size_t>& r) {
                          for (size_t t = r.begin(); t != r.end(); ++t) {
                              const Triangle& f = input.triangles[t];
                              const Vec3 c = (1.0 / 3.0) * (input.vertices[f[0]] + input.vertices[f[1]] +
                                                            input.vertices[f[2]]);
                              nearest[t] = uint32_t(tree.closest_point_and_primitive(point(c)).second -
                                                    triangles.cbegin());
                          }
                      });
    return nearest;
}

}  // namespace fabvdb::surface
