// The edge table against tables known by hand: one triangle (three edges,
// one use each, directions as listed), a box (18 edges, two opposite uses
// each, edges in order), a degenerate triangle (one edge used twice), a
// fin (three uses of one edge) and the empty mesh; and on a mesh large
// enough for the sort to run in parallel, the same order as a serial sort.
#include "volume/edge_table.h"

#include <algorithm>
#include <random>
#include <tuple>

#include <gtest/gtest.h>

#include "support/shapes.h"

namespace fabvdb::volume {
namespace {

using test::make_box;

TEST(EdgeTable, OneTriangle) {
    Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.triangles = {{2, 0, 1}};  // sides 2->0, 0->1, 1->2
    const EdgeTable table = build_edge_table(mesh);
    ASSERT_EQ(table.edge_count(), 3u);
    ASSERT_EQ(table.uses.size(), 3u);
    EXPECT_EQ(table.begin, (std::vector<size_t>{0, 1, 2, 3}));
    const struct {
        uint32_t lo, hi;
        bool forward;
    } expected[3] = {{0, 1, true}, {0, 2, false}, {1, 2, true}};
    for (size_t e = 0; e < 3; ++e) {
        EXPECT_EQ(table.uses[e].lo, expected[e].lo) << "edge " << e;
        EXPECT_EQ(table.uses[e].hi, expected[e].hi) << "edge " << e;
        EXPECT_EQ(table.uses[e].forward, expected[e].forward) << "edge " << e;
        EXPECT_EQ(table.uses[e].triangle, 0u);
        EXPECT_EQ(table.use_count(e), 1u);
    }
}

TEST(EdgeTable, ABoxGroupsEachEdgesTwoUses) {
    const EdgeTable table = build_edge_table(make_box({0, 0, 0}, {1, 1, 1}));
    ASSERT_EQ(table.edge_count(), 18u);  // 12 box edges and 6 face diagonals
    for (size_t e = 0; e < table.edge_count(); ++e) {
        ASSERT_EQ(table.use_count(e), 2u) << "edge " << e;
        const EdgeUse& a = table.uses[table.begin[e]];
        const EdgeUse& b = table.uses[table.begin[e] + 1];
        EXPECT_LT(a.lo, a.hi);
        EXPECT_EQ(a.lo, b.lo);
        EXPECT_EQ(a.hi, b.hi);
        EXPECT_LT(a.triangle, b.triangle);
        EXPECT_NE(a.forward, b.forward) << "outward box: its two sides run opposite ways";
        if (e > 0) {
            const EdgeUse& previous = table.uses[table.begin[e] - 1];
            EXPECT_TRUE(previous.lo < a.lo || (previous.lo == a.lo && previous.hi < a.hi));
        }
    }
}

TEST(EdgeTable, RepeatedIndexUsesOneEdgeTwice) {
    Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {1, 0, 0}};
    mesh.triangles = {{0, 0, 1}};
    const EdgeTable table = build_edge_table(mesh);
    ASSERT_EQ(table.edge_count(), 1u);
    ASSERT_EQ(table.use_count(0), 2u);
    EXPECT_NE(table.uses[0].forward, table.uses[1].forward);
}

TEST(EdgeTable, FinEdgeHasThreeUses) {
    Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
    mesh.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
    const EdgeTable table = build_edge_table(mesh);
    ASSERT_EQ(table.use_count(0), 3u);
    EXPECT_EQ(table.uses[0].lo, 0u);
    EXPECT_EQ(table.uses[0].hi, 1u);
    EXPECT_EQ(table.uses[0].triangle, 0u);
    EXPECT_EQ(table.uses[1].triangle, 1u);
    EXPECT_EQ(table.uses[2].triangle, 2u);
}

TEST(EdgeTable, EmptyMesh) {
    const EdgeTable table = build_edge_table(Mesh{});
    EXPECT_EQ(table.edge_count(), 0u);
    EXPECT_TRUE(table.uses.empty());
}

TEST(EdgeTable, LargeSoupInTheOrderOfASerialSort) {
    Mesh soup;
    std::mt19937 random(7);
    std::uniform_int_distribution<uint32_t> vertex(0, 999);
    soup.vertices.assign(1000, Vec3{0, 0, 0});
    for (int t = 0; t < 20000; ++t) soup.triangles.push_back({vertex(random), vertex(random), vertex(random)});
    const EdgeTable table = build_edge_table(soup);
    std::vector<std::tuple<uint32_t, uint32_t, uint32_t, bool>> expected;
    for (uint32_t t = 0; t < soup.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = soup.triangles[t][k], b = soup.triangles[t][(k + 1) % 3];
            if (a != b) expected.emplace_back(std::min(a, b), std::max(a, b), t, a < b);
        }
    std::sort(expected.begin(), expected.end());
    ASSERT_EQ(table.uses.size(), expected.size());
    for (size_t u = 0; u < expected.size(); ++u) {
        const EdgeUse& use = table.uses[u];
        ASSERT_EQ(std::make_tuple(use.lo, use.hi, use.triangle, use.forward), expected[u]) << "use " << u;
    }
    size_t edges = 0;
    for (size_t u = 0; u < expected.size(); ++u)
        if (u == 0 || std::get<0>(expected[u]) != std::get<0>(expected[u - 1]) ||
            std::get<1>(expected[u]) != std::get<1>(expected[u - 1]))
            ++edges;
    EXPECT_EQ(table.edge_count(), edges);
}

}  // namespace
}  // namespace fabvdb::volume
