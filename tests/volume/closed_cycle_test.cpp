// Closed cycles: closed shells are (also inside out, unwelded, overlapping,
// nested or meeting at an edge); a hole or one flipped triangle is not;
// points are compared by position and degenerate triangles count.
#include <gtest/gtest.h>

#include <cstdint>
#include <utility>

#include "support/shapes.h"
#include "volume/closed_cycle.h"
#include "volume/edge_table.h"
#include "volume/position_ids.h"

namespace {

using fabvdb::Mesh;
using fabvdb::test::flipped;
using fabvdb::test::make_box;
using fabvdb::test::merged;
using fabvdb::test::unwelded;

// As the signed distance asks it: on the edge table of the mesh welded by position.
bool is_closed_cycle(const Mesh& mesh) {
    return fabvdb::volume::is_closed_cycle(fabvdb::volume::build_edge_table(fabvdb::volume::weld_positions(mesh)));
}

TEST(ClosedCycle, ClosedShells) {
    EXPECT_TRUE(is_closed_cycle(make_box({0, 0, 0}, {1, 2, 3})));
    EXPECT_TRUE(is_closed_cycle(flipped(make_box({0, 0, 0}, {1, 2, 3}))));
    EXPECT_TRUE(is_closed_cycle(fabvdb::test::make_sphere({0, 0, 0}, 1.0, 2)));
    EXPECT_TRUE(is_closed_cycle(fabvdb::test::make_torus({0, 0, 0}, 3.0, 1.0, 12, 8)));
    EXPECT_TRUE(is_closed_cycle(Mesh{}));
}

TEST(ClosedCycle, OverlappingNestedAndEdgeSharingShells) {
    EXPECT_TRUE(is_closed_cycle(merged(make_box({0, 0, 0}, {2, 2, 2}), make_box({1, 1, 1}, {3, 3, 3}))));
    EXPECT_TRUE(is_closed_cycle(merged(make_box({0, 0, 0}, {4, 4, 4}), flipped(make_box({1, 1, 1}, {2, 2, 2})))));
    // Two boxes meeting along the edge x = y = 1: four triangles at that edge.
    EXPECT_TRUE(is_closed_cycle(merged(make_box({0, 0, 0}, {1, 1, 1}), make_box({1, 1, 0}, {2, 2, 1}))));
}

TEST(ClosedCycle, PositionsNotIndices) {
    const Mesh box = make_box({-1, -1, -1}, {1, 1, 1});
    EXPECT_TRUE(is_closed_cycle(unwelded(box)));
    // Unused vertices, also ones at the positions of used vertices, change nothing.
    Mesh extra = box;
    extra.vertices.push_back({7, 7, 7});
    extra.vertices.push_back(box.vertices[3]);
    EXPECT_TRUE(is_closed_cycle(extra));
}

TEST(ClosedCycle, HoleOrFlippedTriangleIsNot) {
    Mesh holed = make_box({0, 0, 0}, {1, 1, 1});
    holed.triangles.erase(holed.triangles.begin() + 5);
    EXPECT_FALSE(is_closed_cycle(holed));
    EXPECT_FALSE(is_closed_cycle(unwelded(holed)));

    Mesh one_flipped = make_box({0, 0, 0}, {1, 1, 1});
    std::swap(one_flipped.triangles[7][0], one_flipped.triangles[7][1]);
    EXPECT_FALSE(is_closed_cycle(one_flipped));

    // A closed box and an open one are not a closed cycle together.
    EXPECT_FALSE(is_closed_cycle(merged(make_box({5, 5, 5}, {6, 6, 6}), holed)));

    Mesh lone;
    lone.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    lone.triangles = {{0, 1, 2}};
    EXPECT_FALSE(is_closed_cycle(lone));
}

TEST(ClosedCycle, DegenerateTrianglesCount) {
    // Split the box's first triangle (0, 2, 3) at m, the midpoint of the edge
    // 0-2: the T-junction leaves the edge 0-2 open...
    Mesh mesh = make_box({0, 0, 0}, {1, 1, 1});
    ASSERT_EQ(mesh.triangles[0], (fabvdb::Triangle{0, 2, 3}));
    mesh.vertices.push_back({0, 0.5, 0});
    const uint32_t m = 8;
    mesh.triangles[0] = {0, m, 3};
    mesh.triangles.push_back({m, 2, 3});
    EXPECT_FALSE(is_closed_cycle(mesh));
    // ...and a zero-area sliver (2, m, 0) along it closes the cycle.
    mesh.triangles.push_back({2, m, 0});
    EXPECT_TRUE(is_closed_cycle(mesh));
    // A sliver the wrong way round opens it again.
    mesh.triangles.back() = {0, m, 2};
    EXPECT_FALSE(is_closed_cycle(mesh));
}

}  // namespace
