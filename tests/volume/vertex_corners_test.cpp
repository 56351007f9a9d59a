// Corners grouped by vertex: rows built by hand for a small mesh (unused
// vertices, a vertex named twice), and the triangles across an edge: none on
// a border, one per edge of a closed box (checked by search), all of a
// non-manifold edge with the first in triangle order.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "support/shapes.h"
#include "volume/vertex_corners.h"

namespace {

using fabvdb::Mesh;
using fabvdb::volume::VertexCorners;

TEST(VertexCorners, RowsOfASmallMesh) {
    Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {5, 5, 5}};
    mesh.triangles = {{0, 1, 2}, {2, 1, 3}};
    const VertexCorners corners(mesh);
    // Corners: 0 -> v0, 1 -> v1, 2 -> v2, 3 -> v2, 4 -> v1, 5 -> v3; v4 unused.
    EXPECT_EQ(corners.first, (std::vector<uint32_t>{0, 1, 3, 5, 6, 6}));
    EXPECT_EQ(corners.corner, (std::vector<uint32_t>{0, 1, 4, 2, 3, 5}));
}

TEST(VertexCorners, AVertexNamedTwiceIsThereTwice) {
    Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {1, 0, 0}};
    mesh.triangles = {{1, 0, 1}, {0, 0, 0}};
    const VertexCorners corners(mesh);
    EXPECT_EQ(corners.first, (std::vector<uint32_t>{0, 4, 6}));
    EXPECT_EQ(corners.corner, (std::vector<uint32_t>{1, 3, 4, 5, 0, 2}));
}

TEST(VertexCorners, EmptyMesh) {
    const VertexCorners corners(Mesh{});
    EXPECT_EQ(corners.first, (std::vector<uint32_t>{0}));
    EXPECT_TRUE(corners.corner.empty());
}

TEST(VertexCorners, AcrossABorderAndAnInnerEdge) {
    Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    mesh.triangles = {{0, 1, 2}, {2, 1, 3}};
    const VertexCorners corners(mesh);
    const auto inner = corners.across(mesh, 0, 1);  // 1 -> 2, which triangle 1 runs 2 -> 1
    EXPECT_EQ(inner.count, 1);
    EXPECT_EQ(inner.first, 1u);
    const auto back = corners.across(mesh, 1, 0);  // 2 -> 1
    EXPECT_EQ(back.count, 1);
    EXPECT_EQ(back.first, 0u);
    const auto border = corners.across(mesh, 0, 0);  // 0 -> 1
    EXPECT_EQ(border.count, 0);
    EXPECT_EQ(border.first, UINT32_MAX);
}

TEST(VertexCorners, EveryEdgeOfAClosedBoxHasOneAcross) {
    const Mesh box = fabvdb::test::make_box({0, 0, 0}, {1, 2, 3});
    const VertexCorners corners(box);
    for (uint32_t t = 0; t < box.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            const uint32_t from = box.triangles[t][k], to = box.triangles[t][(k + 1) % 3];
            // The reverse edge, by a search over every triangle's edges.
            uint32_t expected = UINT32_MAX;
            for (uint32_t u = 0; u < box.triangles.size() && expected == UINT32_MAX; ++u)
                for (int j = 0; j < 3; ++j)
                    if (box.triangles[u][j] == to && box.triangles[u][(j + 1) % 3] == from) expected = u;
            const auto across = corners.across(box, t, k);
            EXPECT_EQ(across.count, 1) << "triangle " << t << " edge " << k;
            EXPECT_EQ(across.first, expected) << "triangle " << t << " edge " << k;
        }
}

TEST(VertexCorners, NonManifoldEdgeCountsOnlyTheOtherDirection) {
    // Five triangles on the edge 0-1: triangle 1 runs 0 -> 1 like triangle 0;
    // triangles 2, 3 and 4 run 1 -> 0.
    Mesh fan;
    fan.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, 1, 1}};
    fan.triangles = {{0, 1, 2}, {6, 0, 1}, {1, 0, 3}, {0, 4, 1}, {5, 1, 0}};
    const VertexCorners corners(fan);
    const auto across = corners.across(fan, 0, 0);
    EXPECT_EQ(across.count, 3);
    EXPECT_EQ(across.first, 2u);
    const auto other_way = corners.across(fan, 4, 1);  // 1 -> 0: triangles 0 and 1 run 0 -> 1
    EXPECT_EQ(other_way.count, 2);
    EXPECT_EQ(other_way.first, 0u);
}

}  // namespace
