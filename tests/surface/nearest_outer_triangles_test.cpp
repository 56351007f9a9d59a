//! nearest_outer_triangles against a brute-force search over every S_low
//! triangle (CGAL's point-triangle distance, no tree): a fine icosphere on a
//! coarse one and a box's triangles on a larger box, each input triangle
//! mapped to a triangle at the smallest distance from its centroid.
#include <gtest/gtest.h>

#include <CGAL/Simple_cartesian.h>

#include "support/shapes.h"
#include "surface/nearest_outer_triangles.h"

namespace {

using fabvdb::Mesh;
using fabvdb::Vec3;
using K = CGAL::Simple_cartesian<double>;

double distance_to(const Mesh& mesh, uint32_t t, const K::Point_3& p) {
    const auto point = [&](uint32_t v) {
        return K::Point_3(mesh.vertices[v][0], mesh.vertices[v][1], mesh.vertices[v][2]);
    };
    const auto& f = mesh.triangles[t];
    return CGAL::squared_distance(p, K::Triangle_3(point(f[0]), point(f[1]), point(f[2])));
}

void expect_nearest(const Mesh& input, const Mesh& outer) {
    const std::vector<uint32_t> nearest = fabvdb::surface::nearest_outer_triangles(input, outer);
    ASSERT_EQ(nearest.size(), input.triangles.size());
    for (size_t t = 0; t < input.triangles.size(); ++t) {
        const auto& f = input.triangles[t];
        K::Point_3 c(0, 0, 0);
        double x = 0, y = 0, z = 0;
        for (uint32_t v : f) x += input.vertices[v][0] / 3, y += input.vertices[v][1] / 3, z += input.vertices[v][2] / 3;
        c = K::Point_3(x, y, z);
        double best = 1e300;
        for (uint32_t s = 0; s < outer.triangles.size(); ++s) best = std::min(best, distance_to(outer, s, c));
        ASSERT_LT(nearest[t], outer.triangles.size());
        EXPECT_NEAR(distance_to(outer, nearest[t], c), best, 1e-9) << "input triangle " << t;
    }
}

}  // namespace

TEST(NearestOuterTriangles, FineSphereOnACoarseOne) {
    expect_nearest(fabvdb::test::make_sphere({1, 2, 3}, 10.0, 3), fabvdb::test::make_sphere({1, 2, 3}, 10.5, 1));
}

TEST(NearestOuterTriangles, BoxInsideALargerBox) {
    expect_nearest(fabvdb::test::make_box({1, 1, 1}, {9, 9, 5}), fabvdb::test::make_box({0, 0, 0}, {10, 10, 6}));
}
