// Closed oriented 2-manifolds by vertex indices: boxes, spheres and tori
// (also inside out, several, with unused vertices) are; a hole, a flipped
// triangle, a repeated vertex, unwelded corners, a pinched vertex, an edge of
// four triangles and a duplicated triangle are not.
#include <gtest/gtest.h>

#include <cstdint>
#include <utility>

#include "support/shapes.h"
#include "volume/closed_manifold.h"

namespace {

using fabvdb::Mesh;
using fabvdb::test::flipped;
using fabvdb::test::make_box;
using fabvdb::test::merged;
using fabvdb::volume::is_closed_manifold;

// The mesh with vertex `from` replaced by vertex `to` in every triangle.
Mesh renamed(Mesh mesh, uint32_t from, uint32_t to) {
    for (auto& t : mesh.triangles)
        for (uint32_t& v : t)
            if (v == from) v = to;
    return mesh;
}

TEST(ClosedManifold, ClosedShells) {
    EXPECT_TRUE(is_closed_manifold(make_box({0, 0, 0}, {1, 2, 3})));
    EXPECT_TRUE(is_closed_manifold(flipped(make_box({0, 0, 0}, {1, 2, 3}))));
    EXPECT_TRUE(is_closed_manifold(fabvdb::test::make_sphere({0, 0, 0}, 2.0, 3)));
    EXPECT_TRUE(is_closed_manifold(fabvdb::test::make_torus({0, 0, 0}, 3.0, 1.0, 16, 8)));
    // Two shells, even overlapping in space: the test is on indices only.
    EXPECT_TRUE(is_closed_manifold(merged(make_box({0, 0, 0}, {2, 2, 2}), make_box({1, 1, 1}, {3, 3, 3}))));
    Mesh extra = make_box({0, 0, 0}, {1, 1, 1});
    extra.vertices.push_back({9, 9, 9});  // used by no triangle
    EXPECT_TRUE(is_closed_manifold(extra));
}

TEST(ClosedManifold, HoleOrFlippedTriangle) {
    Mesh holed = make_box({0, 0, 0}, {1, 1, 1});
    holed.triangles.pop_back();
    EXPECT_FALSE(is_closed_manifold(holed));
    Mesh one_flipped = fabvdb::test::make_sphere({0, 0, 0}, 1.0, 2);
    std::swap(one_flipped.triangles[17][1], one_flipped.triangles[17][2]);
    EXPECT_FALSE(is_closed_manifold(one_flipped));
}

TEST(ClosedManifold, RepeatedVertexInATriangle) {
    Mesh mesh = make_box({0, 0, 0}, {1, 1, 1});
    mesh.triangles.push_back({2, 2, 5});
    EXPECT_FALSE(is_closed_manifold(mesh));
    // Also when its edges pair off with nothing else wrong: (v, v, w) then (w, v, v).
    Mesh pair = make_box({0, 0, 0}, {1, 1, 1});
    pair.triangles.push_back({1, 1, 4});
    pair.triangles.push_back({4, 1, 1});
    EXPECT_FALSE(is_closed_manifold(pair));
}

TEST(ClosedManifold, UnweldedCornersAreNotJoined) {
    const Mesh box = make_box({0, 0, 0}, {1, 1, 1});
    Mesh unwelded;
    for (const auto& t : box.triangles) {
        const uint32_t base = uint32_t(unwelded.vertices.size());
        for (uint32_t v : t) unwelded.vertices.push_back(box.vertices[v]);
        unwelded.triangles.push_back({base, base + 1, base + 2});
    }
    EXPECT_FALSE(is_closed_manifold(unwelded));
}

TEST(ClosedManifold, PinchedVertex) {
    // Two boxes sharing one corner index: that vertex has two fans.
    const Mesh a = make_box({0, 0, 0}, {1, 1, 1});
    const Mesh b = make_box({1, 1, 1}, {2, 2, 2});
    EXPECT_TRUE(is_closed_manifold(merged(a, b)));
    EXPECT_FALSE(is_closed_manifold(renamed(merged(a, b), 8 + 0, 7)));  // b's vertex 0 is a's (1,1,1)
}

TEST(ClosedManifold, EdgeOfFourTriangles) {
    // Two boxes sharing the edge x = y = 1 (a's vertices 3 and 7, b's 0 and 4).
    const Mesh a = make_box({0, 0, 0}, {1, 1, 1});
    const Mesh b = make_box({1, 1, 0}, {2, 2, 1});
    const Mesh one_index_shared = renamed(merged(a, b), 8 + 0, 3);
    EXPECT_FALSE(is_closed_manifold(one_index_shared));
    EXPECT_FALSE(is_closed_manifold(renamed(one_index_shared, 8 + 4, 7)));
}

TEST(ClosedManifold, DuplicatedTriangle) {
    Mesh mesh = make_box({0, 0, 0}, {1, 1, 1});
    mesh.triangles.push_back(mesh.triangles[4]);
    EXPECT_FALSE(is_closed_manifold(mesh));
    // A duplicate with its opposite alongside leaves every edge balanced, but
    // three triangles then run along each of its edges.
    mesh.triangles.push_back({mesh.triangles[4][0], mesh.triangles[4][2], mesh.triangles[4][1]});
    EXPECT_FALSE(is_closed_manifold(mesh));
}

}  // namespace
