// Closest point on a triangle: each Voronoi region (three corners, three
// edges, the face) gives the point and feature worked out by hand; random
// points and triangles agree with a clamp-to-edges-or-project search; a
// degenerate triangle gives a point at the right distance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "volume/closest_point_on_triangle.h"

namespace {

using fabvdb::volume::closest_point_on_triangle;
using fabvdb::volume::TriangleFeature;
using openvdb::Vec3d;

void expect_point(const Vec3d& actual, const Vec3d& expected, double tolerance = 1e-14) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(actual[k], expected[k], tolerance) << "coordinate " << k;
}

TEST(ClosestPointOnTriangle, EachRegionOfARightTriangle) {
    const Vec3d a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
    struct Case {
        Vec3d p, point;
        TriangleFeature feature;
    };
    const Case cases[] = {
        {{0.5, 0.5, 3}, {0.5, 0.5, 0}, TriangleFeature::face},
        {{0.5, 0.25, 0}, {0.5, 0.25, 0}, TriangleFeature::face},  // on the triangle
        {{-1, -1, 1}, a, TriangleFeature::corner0},
        {{3, -1, 0}, b, TriangleFeature::corner1},
        {{5, 0, -2}, b, TriangleFeature::corner1},  // beyond b along a -> b
        {{-1, 3, 5}, c, TriangleFeature::corner2},
        {{1, -2, 1}, {1, 0, 0}, TriangleFeature::edge01},
        {{-2, 1, 0}, {0, 1, 0}, TriangleFeature::edge20},
        {{2, 2, -1}, {1, 1, 0}, TriangleFeature::edge12},  // the edge x + y = 2
        {{2, 1, 0}, {1.5, 0.5, 0}, TriangleFeature::edge12},
    };
    for (const Case& test : cases) {
        const auto found = closest_point_on_triangle(test.p, a, b, c);
        SCOPED_TRACE(testing::Message() << "p = " << test.p);
        expect_point(found.point, test.point);
        EXPECT_EQ(found.feature, test.feature);
    }
}

TEST(ClosestPointOnTriangle, FeaturesFollowTheCornerOrder) {
    // The same triangle with its corners named in another order.
    const Vec3d a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
    const auto at_b = closest_point_on_triangle({3, -1, 0}, b, c, a);
    EXPECT_EQ(at_b.feature, TriangleFeature::corner0);
    const auto on_ab = closest_point_on_triangle({1, -2, 1}, b, c, a);
    EXPECT_EQ(on_ab.feature, TriangleFeature::edge20);
    expect_point(on_ab.point, {1, 0, 0});
    const auto on_bc = closest_point_on_triangle({2, 2, -1}, b, c, a);
    EXPECT_EQ(on_bc.feature, TriangleFeature::edge01);
    expect_point(on_bc.point, {1, 1, 0});
}

// Closest point on segment s-t by clamped projection.
Vec3d on_segment(const Vec3d& p, const Vec3d& s, const Vec3d& t) {
    const Vec3d st = t - s;
    const double u = std::clamp((p - s).dot(st) / st.dot(st), 0.0, 1.0);
    return s + st * u;
}

TEST(ClosestPointOnTriangle, AgreesWithProjectionOrEdgeSearch) {
    std::mt19937 random(20260127);
    std::uniform_real_distribution<double> coordinate(-5.0, 5.0);
    auto point = [&] { return Vec3d(coordinate(random), coordinate(random), coordinate(random)); };
    for (int trial = 0; trial < 2000; ++trial) {
        const Vec3d a = point(), b = point(), c = point(), p = point();
        const Vec3d normal = (b - a).cross(c - a);
        if (normal.length() < 1e-2) continue;  // skip near-degenerate draws
        // The plane projection if it falls inside (all three edge tests
        // positive), else the nearest of the three edges' closest points.
        const Vec3d n = normal / normal.length();
        const Vec3d projected = p - n * (p - a).dot(n);
        const bool inside = (b - a).cross(projected - a).dot(n) >= 0 && (c - b).cross(projected - b).dot(n) >= 0 &&
                            (a - c).cross(projected - c).dot(n) >= 0;
        Vec3d expected = projected;
        if (!inside) {
            const Vec3d candidates[] = {on_segment(p, a, b), on_segment(p, b, c), on_segment(p, c, a)};
            expected = candidates[0];
            for (const Vec3d& q : candidates)
                if ((q - p).lengthSqr() < (expected - p).lengthSqr()) expected = q;
        }
        const auto found = closest_point_on_triangle(p, a, b, c);
        EXPECT_NEAR((found.point - p).length(), (expected - p).length(), 1e-9) << "trial " << trial;
        EXPECT_NEAR((found.point - expected).length(), 0.0, 1e-6) << "trial " << trial;
        // The point lies on the feature named.
        switch (found.feature) {
        case TriangleFeature::corner0: EXPECT_EQ(found.point, a); break;
        case TriangleFeature::corner1: EXPECT_EQ(found.point, b); break;
        case TriangleFeature::corner2: EXPECT_EQ(found.point, c); break;
        case TriangleFeature::edge01: EXPECT_NEAR((on_segment(found.point, a, b) - found.point).length(), 0, 1e-9); break;
        case TriangleFeature::edge12: EXPECT_NEAR((on_segment(found.point, b, c) - found.point).length(), 0, 1e-9); break;
        case TriangleFeature::edge20: EXPECT_NEAR((on_segment(found.point, c, a) - found.point).length(), 0, 1e-9); break;
        case TriangleFeature::face: EXPECT_TRUE(inside) << "trial " << trial; break;
        }
    }
}

TEST(ClosestPointOnTriangle, DegenerateTrianglesGiveAClosestPoint) {
    // All corners at one point.
    const Vec3d q(1, 2, 3);
    const auto single = closest_point_on_triangle({4, 6, 3}, q, q, q);
    expect_point(single.point, q);
    // Corners on a line: the closest points to (1.5, 1, 0) is (1.5, 0, 0),
    // at distance 1, whatever the corner order.
    const Vec3d a(0, 0, 0), b(1, 0, 0), c(2, 0, 0);
    for (const auto& [x, y, z] : {std::array<Vec3d, 3>{a, b, c}, {b, c, a}, {c, a, b}, {a, c, b}, {a, a, c}}) {
        const auto found = closest_point_on_triangle({1.5, 1, 0}, x, y, z);
        EXPECT_TRUE(std::isfinite(found.point[0]) && std::isfinite(found.point[1]) && std::isfinite(found.point[2]));
        EXPECT_NEAR((found.point - Vec3d(1.5, 1, 0)).length(), 1.0, 1e-12);
    }
}

}  // namespace
