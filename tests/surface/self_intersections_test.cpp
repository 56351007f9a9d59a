// self_intersecting_pairs on cases known by construction: pairs of loose
// triangles that pierce, touch at a point, overlap in their plane or stay
// apart; neighbours by position only (an unwelded seam, which must not
// count) or by index; degenerate triangles tested as their segment or point;
// a unit box cut at half height by a large triangle (its 8 side triangles
// exactly); two overlapping spheres; cancellation.
#include "surface/self_intersections.h"

#include <gtest/gtest.h>

#include <atomic>

#include "core/error.h"
#include "support/pair_checks.h"
#include "support/shapes.h"

namespace fabvdb::surface {
namespace {

using Pairs = std::vector<std::pair<uint32_t, uint32_t>>;

Pairs pairs_of(const Mesh& mesh) {
    Progress progress;
    return self_intersecting_pairs(mesh, progress);
}

const std::array<Vec3, 3> flat = {{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}}};

TEST(SelfIntersections, CleanShapesHaveNone) {
    EXPECT_TRUE(pairs_of(Mesh{}).empty());
    EXPECT_TRUE(pairs_of(test::make_box({0, 0, 0}, {1, 1, 1})).empty());
    EXPECT_TRUE(pairs_of(test::make_sphere({0, 0, 0}, 1.0, 3)).empty());
    EXPECT_TRUE(pairs_of(test::make_torus({0, 0, 0}, 3.0, 1.0, 24, 12)).empty());
    // Separate boxes, their boxes' faces 1e-9 apart.
    EXPECT_TRUE(
        pairs_of(test::merged(test::make_box({0, 0, 0}, {1, 1, 1}), test::make_box({1 + 1e-9, 0, 0}, {2, 1, 1})))
            .empty());
}

TEST(SelfIntersections, LooseTrianglesMeetingOrTouching) {
    // Piercing.
    EXPECT_EQ(pairs_of(test::loose_triangles({flat, {{{0.5, 0.5, -1}, {0.5, 0.5, 1}, {0.6, 0.4, 1}}}})), (Pairs{{0, 1}}));
    // A corner resting on the interior: touching counts.
    EXPECT_EQ(pairs_of(test::loose_triangles({flat, {{{0.5, 0.5, 0}, {0.5, 0.5, 1}, {1, 0.5, 1}}}})), (Pairs{{0, 1}}));
    // Lifted off by 1e-9: apart.
    EXPECT_TRUE(pairs_of(test::loose_triangles({flat, {{{0.5, 0.5, 1e-9}, {0.5, 0.5, 1}, {1, 0.5, 1}}}})).empty());
    // Coplanar overlap, and coplanar across the hypotenuse (boxes overlapping).
    EXPECT_EQ(pairs_of(test::loose_triangles({flat, {{{0.5, 0.5, 0}, {3, 0.5, 0}, {0.5, 3, 0}}}})), (Pairs{{0, 1}}));
    EXPECT_TRUE(pairs_of(test::loose_triangles({flat, {{{2, 0.1, 0}, {2, 2, 0}, {0.1, 2, 0}}}})).empty());
    // Three triangles: the last pierces the first only, listed as (0, 2).
    EXPECT_EQ(pairs_of(test::loose_triangles({flat, {{{5, 5, 0}, {6, 5, 0}, {5, 6, 0}}}, {{{0.5, 0.5, -1}, {0.5, 0.5, 1}, {0.6, 0.4, 1}}}})),
              (Pairs{{0, 2}}));
}

TEST(SelfIntersections, SharedPositionsAreNeighboursNotIntersections) {
    // An unwelded seam: the second triangle has its own copies of the
    // first's hypotenuse ends.
    EXPECT_TRUE(pairs_of(test::loose_triangles({flat, {{{2, 0, 0}, {2, 2, 0}, {0, 2, 0}}}})).empty());
    // Sharing one corner by position and piercing elsewhere: not reported
    // either (the pair shares a vertex position).
    EXPECT_TRUE(pairs_of(test::loose_triangles({flat, {{{0, 0, 0}, {1, 1, -1}, {0.2, 0.2, 1}}}})).empty());
    // The same, the corner shared by index.
    Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 1, -1}, {0.2, 0.2, 1}};
    mesh.triangles = {{0, 1, 2}, {0, 3, 4}};
    EXPECT_TRUE(pairs_of(mesh).empty());
    // Without the shared corner the same piercing is found.
    mesh.vertices.push_back({-0.1, -0.1, 0.05});
    mesh.triangles[1][0] = 5;
    EXPECT_EQ(pairs_of(mesh), (Pairs{{0, 1}}));
}

TEST(SelfIntersections, DegenerateTrianglesAreTheirSegmentOrPoint) {
    // A needle (three collinear corners) through the flat triangle.
    EXPECT_EQ(pairs_of(test::loose_triangles({flat, {{{0.5, 0.5, -1}, {0.5, 0.5, 1}, {0.5, 0.5, 0.3}}}})), (Pairs{{0, 1}}));
    // The same needle beside it.
    EXPECT_TRUE(pairs_of(test::loose_triangles({flat, {{{1.5, 1.5, -1}, {1.5, 1.5, 1}, {1.5, 1.5, 0.3}}}})).empty());
    // A needle ending on the plane inside the triangle: touching.
    EXPECT_EQ(pairs_of(test::loose_triangles({flat, {{{0.5, 0.5, 0}, {0.5, 0.5, 1}, {0.5, 0.5, 0.4}}}})), (Pairs{{0, 1}}));
    // A point (all corners equal) on the triangle, and one just above it.
    EXPECT_EQ(pairs_of(test::loose_triangles({flat, {{{0.5, 0.5, 0}, {0.5, 0.5, 0}, {0.5, 0.5, 0}}}})), (Pairs{{0, 1}}));
    EXPECT_TRUE(pairs_of(test::loose_triangles({flat, {{{0.5, 0.5, 1e-9}, {0.5, 0.5, 1e-9}, {0.5, 0.5, 1e-9}}}})).empty());
}

TEST(SelfIntersections, BoxCutAtHalfHeightMeetsItsSideTriangles) {
    // make_box: triangles 0-1 bottom, 2-3 top, 4-11 the sides, each side
    // triangle with corners at z = 0 and z = 1; the blade at z = 0.5 covers
    // the box's shadow.
    Mesh mesh = test::make_box({0, 0, 0}, {1, 1, 1});
    const uint32_t first = uint32_t(mesh.vertices.size());
    mesh.vertices.push_back({-3, -3, 0.5});
    mesh.vertices.push_back({6, -3, 0.5});
    mesh.vertices.push_back({-3, 6, 0.5});
    mesh.triangles.push_back({first, first + 1, first + 2});
    Pairs expected;
    for (uint32_t t = 4; t < 12; ++t) expected.push_back({t, 12});
    EXPECT_EQ(pairs_of(mesh), expected);
    // Lowered onto the bottom face (z = 0): it touches everything but the top.
    for (uint32_t v = first; v < first + 3; ++v) mesh.vertices[v][2] = 0.0;
    expected = {{0, 12}, {1, 12}};
    for (uint32_t t = 4; t < 12; ++t) expected.push_back({t, 12});
    EXPECT_EQ(pairs_of(mesh), expected);
}

TEST(SelfIntersections, OverlappingSpheresPairAcrossOnly) {
    const Mesh a = test::make_sphere({0, 0, 0}, 1.0, 3);
    const Mesh mesh = test::merged(a, test::make_sphere({0.9, 0.2, 0.1}, 0.6, 3));
    const Pairs pairs = pairs_of(mesh);
    ASSERT_GT(pairs.size(), 20u);
    test::expect_sorted_pairs_across(pairs, uint32_t(a.triangles.size()));
    // Apart, they meet nowhere.
    EXPECT_TRUE(pairs_of(test::merged(a, test::make_sphere({2.7, 0.2, 0.1}, 0.6, 3))).empty());
}

TEST(SelfIntersections, CancelledThrows) {
    std::atomic<bool> cancel{true};
    Progress progress(nullptr, nullptr, &cancel);
    try {
        self_intersecting_pairs(test::make_sphere({0, 0, 0}, 1.0, 2), progress);
        ADD_FAILURE() << "not cancelled";
    } catch (const Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_CANCELLED);
    }
}

}  // namespace
}  // namespace fabvdb::surface
