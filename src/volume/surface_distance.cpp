//! Point-to-surface distances by a CGAL AABB tree (see surface_distance.h).
#include "volume/surface_distance.h"

#include <cmath>
#include <vector>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include "core/error.h"

namespace fabvdb::volume {

namespace {
using Kernel = CGAL::Simple_cartesian<double>;
using Triangles = std::vector<Kernel::Triangle_3>;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, Triangles::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Kernel::Point_3 point(const Vec3& p) { return {p[0], p[1], p[2]}; }
}  // namespace

struct SurfaceDistance::Tree {
    Triangles triangles;
    fabvdb::volume::Tree tree;
};

SurfaceDistance::SurfaceDistance(const Mesh& mesh) : tree_(std::make_unique<Tree>()) {
    if (mesh.triangles.empty()) throw Error(FABVDB_ERR_BAD_INPUT, "distance to a surface without triangles");
    tree_->triangles.reserve(mesh.triangles.size());
    for (const Triangle& t : mesh.triangles)
        tree_->triangles.emplace_back(point(mesh.vertices[t[0]]), point(mesh.vertices[t[1]]),
                                      point(mesh.vertices[t[2]]));
    tree_->tree.insert(tree_->triangles.cbegin(), tree_->triangles.cend());
    tree_->tree.build();
    tree_->tree.accelerate_distance_queries();
}

SurfaceDistance::~SurfaceDistance() = default;

SurfaceDistance::Nearest SurfaceDistance::nearest(const Vec3& p) const {
    const auto [closest, primitive] = tree_->tree.closest_point_and_primitive(point(p));
    Nearest result;
    result.distance = std::sqrt(CGAL::squared_distance(closest, point(p)));
    result.triangle = size_t(primitive - tree_->triangles.cbegin());
    return result;
}

}  // namespace fabvdb::volume
