// triangles_cross on pairs whose answer is known by construction, for each
// number of shared vertices (none, one, an edge, all three), with and
// without an embedded fan at the shared vertex; and, on random pairs that
// share nothing, agreement with CGAL's exact triangle intersection test
// (the filters in front of it never change its answer).
#include "volume/triangles_cross.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

namespace fabvdb::volume {
namespace {

// The two triangles (0, 1, 2) and (3, 4, 5) of six corners, none shared.
bool separate_cross(const std::array<Vec3, 6>& corners) {
    Mesh mesh{{corners.begin(), corners.end()}, {{0, 1, 2}, {3, 4, 5}}};
    const std::vector<char> none(6, 0);
    return triangles_cross(mesh, none, mesh.triangles[0], mesh.triangles[1]);
}

TEST(TrianglesCross, NothingShared) {
    const Vec3 a = {0, 0, 0}, b = {2, 0, 0}, c = {0, 2, 0};
    // A vertical triangle through the flat one's interior at (0.5, 0.5, 0).
    EXPECT_TRUE(separate_cross({a, b, c, {0.5, 0.5, -1}, {0.5, 0.5, 1}, {0.6, 0.4, 1}}));
    // The same moved to x + y = 2.5, beyond the hypotenuse: apart.
    EXPECT_FALSE(separate_cross({a, b, c, {1.25, 1.25, -1}, {1.25, 1.25, 1}, {1.35, 1.15, 1}}));
    // Parallel 0.1 above: apart.
    EXPECT_FALSE(separate_cross({a, b, c, {0, 0, 0.1}, {2, 0, 0.1}, {0, 2, 0.1}}));
    // A corner resting on the interior: closed triangles touch.
    EXPECT_TRUE(separate_cross({a, b, c, {0.5, 0.5, 0}, {0.5, 0.5, 1}, {1, 0.5, 1}}));
    // Coplanar and overlapping; coplanar across the hypotenuse x + y = 2.
    EXPECT_TRUE(separate_cross({a, b, c, {0.5, 0.5, 0}, {3, 0.5, 0}, {0.5, 3, 0}}));
    EXPECT_FALSE(separate_cross({a, b, c, {2, 0.1, 0}, {2, 2, 0}, {0.1, 2, 0}}));
}

TEST(TrianglesCross, OneSharedVertex) {
    Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 1, -1}, {0.2, 0.2, 1}};
    mesh.triangles = {{0, 1, 2}, {0, 3, 4}};
    std::vector<char> embedded(5, 0);
    const auto cross_now = [&] { return triangles_cross(mesh, embedded, mesh.triangles[0], mesh.triangles[1]); };
    // The edge (1, 1, −1)–(0.2, 0.2, 1) meets z = 0 at (0.6, 0.6), inside.
    EXPECT_TRUE(cross_now());
    EXPECT_TRUE(triangles_cross(mesh, embedded, mesh.triangles[1], mesh.triangles[0]));
    // Said to be at an embedded fan, the pair is not tested.
    embedded[0] = 1;
    EXPECT_FALSE(cross_now());
    embedded[0] = 0;
    // Both ends above the plane: only vertex 0 in common.
    mesh.vertices[3] = {1, 1, 0.5};
    EXPECT_FALSE(cross_now());
    // Coplanar, inside the first's angle, then in the opposite quadrant.
    mesh.vertices[3] = {1, 0.2, 0};
    mesh.vertices[4] = {0.2, 1, 0};
    EXPECT_TRUE(cross_now());
    mesh.vertices[3] = {-1, -0.2, 0};
    mesh.vertices[4] = {-0.2, -1, 0};
    EXPECT_FALSE(cross_now());
}

TEST(TrianglesCross, SharedEdge) {
    Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}};
    mesh.triangles = {{0, 1, 2}, {1, 0, 3}};
    std::vector<char> embedded(4, 0);
    const auto cross_now = [&] { return triangles_cross(mesh, embedded, mesh.triangles[0], mesh.triangles[1]); };
    // Flat on opposite sides of the edge, then bent 55° about it: apart.
    EXPECT_FALSE(cross_now());
    mesh.vertices[3] = {0.5, -1, 0.7};
    EXPECT_FALSE(cross_now());
    // Folded flat onto the first: coplanar on one side, overlapping.
    mesh.vertices[3] = {0.3, 0.5, 0};
    EXPECT_TRUE(cross_now());
    // The same fold with an embedded fan at an end of the edge: not tested.
    embedded[1] = 1;
    EXPECT_FALSE(cross_now());
    embedded[1] = 0;
    // Both run 0 -> 1 (inconsistent orientation), on opposite sides: apart.
    mesh.vertices[3] = {0.5, -1, 0};
    mesh.triangles[1] = {0, 1, 3};
    EXPECT_FALSE(cross_now());
}

TEST(TrianglesCross, DuplicatesCrossEvenAtAnEmbeddedFan) {
    Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const std::vector<char> embedded(3, 1);
    EXPECT_TRUE(triangles_cross(mesh, embedded, {0, 1, 2}, {1, 2, 0}));
    EXPECT_TRUE(triangles_cross(mesh, embedded, {0, 1, 2}, {0, 2, 1}));
}

TEST(TrianglesCross, SameAsCgalOnRandomSeparatePairs) {
    using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
    const auto point = [](const Vec3& p) { return Kernel::Point_3(p[0], p[1], p[2]); };
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    int crossing = 0;
    for (int pair = 0; pair < 4000; ++pair) {
        std::array<Vec3, 6> corners;
        for (Vec3& p : corners) p = {unit(rng), unit(rng), unit(rng)};
        // Every fourth pair flattened into z = 0: coplanar cases.
        if (pair % 4 == 0)
            for (Vec3& p : corners) p[2] = 0.0;
        const Kernel::Triangle_3 a(point(corners[0]), point(corners[1]), point(corners[2]));
        const Kernel::Triangle_3 b(point(corners[3]), point(corners[4]), point(corners[5]));
        const bool expected = CGAL::do_intersect(a, b);
        crossing += expected;
        ASSERT_EQ(separate_cross(corners), expected) << "pair " << pair;
    }
    EXPECT_GT(crossing, 500);
    EXPECT_LT(crossing, 3500);
}

}  // namespace
}  // namespace fabvdb::volume
