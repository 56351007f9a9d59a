// part_pinches on two square pyramids meeting tip to tip at the origin (the
// union's boundary pinched at one vertex): the apex gets a copy per pyramid,
// 1% of the way to the centre of that pyramid's ring, (0, 0, ±0.01)
// exactly, and the triangles of each pyramid use their own copy. A closed
// surface without pinches is left as it is; a vertex whose triangles do not
// close into fans gives nothing and changes nothing.
#include "volume/part_pinches.h"

#include <gtest/gtest.h>

#include "support/shapes.h"

namespace fabvdb::volume {
namespace {

// A closed square pyramid, apex at the origin, base at z = `height`
// (outward either way up).
Mesh pyramid(double height) {
    Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {1, 1, height}, {-1, 1, height}, {-1, -1, height}, {1, -1, height}};
    if (height > 0)
        mesh.triangles = {{0, 2, 1}, {0, 3, 2}, {0, 4, 3}, {0, 1, 4}, {1, 2, 3}, {1, 3, 4}};
    else
        mesh.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 1}, {1, 3, 2}, {1, 4, 3}};
    return mesh;
}

TEST(PartPinches, TwoPyramidsTipToTipArePartedAtTheTip) {
    // The lower pyramid's apex is the upper one's vertex 0.
    Mesh mesh = pyramid(1.0);
    const Mesh lower = pyramid(-1.0);
    for (size_t v = 1; v < lower.vertices.size(); ++v) mesh.vertices.push_back(lower.vertices[v]);
    for (Triangle t : lower.triangles) {
        for (uint32_t& v : t) v = v == 0 ? 0 : v + 4;
        mesh.triangles.push_back(t);
    }
    const std::optional<std::vector<uint32_t>> moved = part_pinches(mesh);
    ASSERT_TRUE(moved.has_value());
    ASSERT_EQ(*moved, (std::vector<uint32_t>{9, 10}));
    ASSERT_EQ(mesh.vertices.size(), 11u);
    // Vertex 0's corners in triangle order: the upper pyramid's fan first.
    EXPECT_EQ(mesh.vertices[9], (Vec3{0, 0, 0.01}));
    EXPECT_EQ(mesh.vertices[10], (Vec3{0, 0, -0.01}));
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const Triangle& triangle = mesh.triangles[t];
        EXPECT_EQ(std::count(triangle.begin(), triangle.end(), 0u), 0) << t;
        if (t < 4) EXPECT_EQ(triangle[0], 9u) << t;
        if (t >= 6 && t < 10) EXPECT_EQ(triangle[0], 10u) << t;
    }
}

TEST(PartPinches, AClosedSurfaceWithoutPinchesIsLeftAsItIs) {
    Mesh box = test::make_box({0, 0, 0}, {1, 1, 1});
    const Mesh before = box;
    const std::optional<std::vector<uint32_t>> moved = part_pinches(box);
    ASSERT_TRUE(moved.has_value());
    EXPECT_TRUE(moved->empty());
    EXPECT_EQ(box.vertices, before.vertices);
    EXPECT_EQ(box.triangles, before.triangles);
}

TEST(PartPinches, OpenFansGiveNothingAndChangeNothing) {
    Mesh open = test::make_box({0, 0, 0}, {1, 1, 1});
    open.triangles.pop_back();
    const Mesh before = open;
    EXPECT_FALSE(part_pinches(open).has_value());
    EXPECT_EQ(open.vertices, before.vertices);
    EXPECT_EQ(open.triangles, before.triangles);
}

}  // namespace
}  // namespace fabvdb::volume
