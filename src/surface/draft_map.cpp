//! draft_map: normal test against sin φ, then one ray per facing triangle
//! against an AABB tree of S_low that skips the triangle the ray starts on.
#include "surface/draft_map.h"

#include <cmath>
#include <optional>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>
#include <tbb/parallel_for.h>

#include "core/vec3_ops.h"

namespace fabvdb::surface {

namespace {

using K = CGAL::Simple_cartesian<double>;
using Triangles = std::vector<K::Triangle_3>;
using Primitive = CGAL::AABB_triangle_primitive<K, Triangles::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

K::Point_3 point(const Vec3& p) { return {p[0], p[1], p[2]}; }

}  // namespace

std::vector<uint8_t> draft_map(const Shell& shell, const Vec3& direction, double draft_radians) {
    const Vec3 d = normalized(direction);
    const double within = std::sin(draft_radians);
    const size_t n = shell.triangle_count();
    Triangles triangles;
    triangles.reserve(n);
    for (const Triangle& f : shell.outer.triangles)
        triangles.emplace_back(point(shell.outer.vertices[f[0]]), point(shell.outer.vertices[f[1]]),
                               point(shell.outer.vertices[f[2]]));
    Tree tree(triangles.begin(), triangles.end());
    tree.build();  // before the parallel queries: the lazy build is not thread-safe
    std::vector<uint8_t> classes(n, needs_draft);
    tbb::parallel_for(size_t(0), n, [&](size_t t) {
        const double c = dot(shell.normal[t], d);
        if (std::abs(c) < within) return;
        classes[t] = c > 0 ? draft_positive : draft_negative;
        const Triangle& f = shell.outer.triangles[t];
        const Vec3 centre =
            (1.0 / 3.0) * (shell.outer.vertices[f[0]] + shell.outer.vertices[f[1]] + shell.outer.vertices[f[2]]);
        const Vec3 toward = c > 0 ? d : -1.0 * d;
        const K::Ray_3 ray(point(centre), K::Direction_3(toward[0], toward[1], toward[2]));
        const auto skip_self = [&](Triangles::const_iterator id) { return size_t(id - triangles.cbegin()) == t; };
        if (tree.first_intersected_primitive(ray, skip_self)) classes[t] = undercut;
    });
    return classes;
}

}  // namespace fabvdb::surface
