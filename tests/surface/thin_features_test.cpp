// Thin segments: a triangle's thickness is twice its vertices' mean depth;
// triangles under 4ω joined across the given neighbours form candidates, and
// a candidate is thin (numbered in order of its first triangle) only when its
// minimum is under 2ω and its mean under 3ω, each bound exclusive.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "surface/thin_features.h"

namespace {

using fabvdb::Mesh;
using fabvdb::surface::thin_segments;
using Neighbours = std::vector<std::array<int, 3>>;

//! Separate triangles (own vertices), each of thickness `thickness[t]`
//! (all its vertices at half that depth).
struct Strip {
    Mesh mesh;
    std::vector<double> depth;
    explicit Strip(const std::vector<double>& thickness) {
        for (size_t t = 0; t < thickness.size(); ++t) {
            const uint32_t base = uint32_t(mesh.vertices.size());
            mesh.vertices.push_back({double(t), 0, 0});
            mesh.vertices.push_back({double(t) + 1, 0, 0});
            mesh.vertices.push_back({double(t), 1, 0});
            mesh.triangles.push_back({base, base + 1, base + 2});
            for (int k = 0; k < 3; ++k) depth.push_back(thickness[t] / 2);
        }
    }
};

//! Triangle t next to t - 1 and t + 1.
Neighbours chain(size_t n) {
    Neighbours out(n, {-1, -1, -1});
    for (size_t t = 0; t < n; ++t) {
        if (t > 0) out[t][0] = int(t - 1);
        if (t + 1 < n) out[t][2] = int(t + 1);
    }
    return out;
}

TEST(ThinSegments, MinimumAndMeanRule) {
    // ω = 1: candidates are under 4, thin when min < 2 and mean < 3.
    //             | thin: min 1.5, mean 2.5 | | min 1, mean 3.175   | | min 2.5 |
    const Strip strip({5, 1.5, 2.5, 3.5, 5, 1.0, 3.9, 3.9, 3.9, 5, 2.5, 2.5, 5});
    const auto segments = thin_segments(strip.mesh, chain(13), strip.depth, 1.0);
    EXPECT_EQ(segments, (std::vector<int>{-1, 0, 0, 0, -1, -1, -1, -1, -1, -1, -1, -1, -1}));
}

TEST(ThinSegments, NumberedInOrderOfTheirFirstTriangle) {
    const Strip strip({1, 1, 5, 1, 1, 5, 0.5});
    EXPECT_EQ(thin_segments(strip.mesh, chain(7), strip.depth, 1.0), (std::vector<int>{0, 0, -1, 1, 1, -1, 2}));
}

TEST(ThinSegments, JoinedByTheNeighbourTableNotByIndex) {
    // Triangles 0 and 4 are neighbours (1..3 thick, 5 thin and alone);
    // adjacency by index or by shared positions does not matter.
    const Strip strip({1, 9, 9, 9, 3.5, 1});
    Neighbours neighbours(6, {-1, -1, -1});
    neighbours[0] = {4, -1, -1};
    neighbours[4] = {-1, 0, -1};
    // Alone, 4 (3.5) would not be thin; with 0 (1) the mean is 2.25.
    EXPECT_EQ(thin_segments(strip.mesh, neighbours, strip.depth, 1.0), (std::vector<int>{0, -1, -1, -1, 0, 1}));
    EXPECT_EQ(thin_segments(strip.mesh, Neighbours(6, {-1, -1, -1}), strip.depth, 1.0),
              (std::vector<int>{0, -1, -1, -1, -1, 1}));
}

TEST(ThinSegments, BoundsAreExclusive) {
    // Exactly 4ω is no candidate: it splits what would be one segment.
    Strip strip({1, 4, 3.5});
    EXPECT_EQ(thin_segments(strip.mesh, chain(3), strip.depth, 1.0), (std::vector<int>{0, -1, -1}));
    // Minimum exactly 2ω: not thin.
    strip = Strip({2, 2});
    EXPECT_EQ(thin_segments(strip.mesh, chain(2), strip.depth, 1.0), (std::vector<int>{-1, -1}));
    strip = Strip({1.9375, 2});
    EXPECT_EQ(thin_segments(strip.mesh, chain(2), strip.depth, 1.0), (std::vector<int>{0, 0}));
    // Mean exactly 3ω: not thin; a little under: thin.
    strip = Strip({1.5, 3.75, 3.75});
    EXPECT_EQ(thin_segments(strip.mesh, chain(3), strip.depth, 1.0), (std::vector<int>{-1, -1, -1}));
    strip = Strip({1.5, 3.75, 3.5});
    EXPECT_EQ(thin_segments(strip.mesh, chain(3), strip.depth, 1.0), (std::vector<int>{0, 0, 0}));
}

TEST(ThinSegments, ThicknessIsTwiceTheMeanVertexDepth) {
    // One triangle with vertex depths 0.3, 0.6, 0.9: thickness 1.2.
    Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.triangles = {{0, 1, 2}};
    const std::vector<double> depth{0.3, 0.6, 0.9};
    const Neighbours none(1, {-1, -1, -1});
    EXPECT_EQ(thin_segments(mesh, none, depth, 0.61), (std::vector<int>{0}));  // 1.2 < 1.22
    EXPECT_EQ(thin_segments(mesh, none, depth, 0.59), (std::vector<int>{-1}));  // 1.2 ≥ 1.18
    EXPECT_EQ(thin_segments(mesh, none, depth, 0.29), (std::vector<int>{-1}));  // 1.2 ≥ 4 × 0.29: no candidate
}

TEST(ThinSegments, SharedVerticesOfAFan) {
    // A fan of 4 triangles around vertex 0 (depth 0.25), rim depths 0.25, 2.875, 2.875, 0.25, 0.25
    // (exact in binary): thicknesses 2 × 3.375 / 3 = 2.25, 2 × 6 / 3 = 4, 2.25, and 0.5.
    Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {1, -1, 0}};
    mesh.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}};
    const std::vector<double> depth{0.25, 0.25, 2.875, 2.875, 0.25, 0.25};
    const Neighbours fan{{-1, 1, -1}, {0, -1, 2}, {1, -1, 3}, {2, -1, -1}};
    // ω = 1: 0 (2.25) alone is a candidate but not thin; 1 (exactly 4) is none; 2 and 3 (2.25, 0.5) are thin.
    EXPECT_EQ(thin_segments(mesh, fan, depth, 1.0), (std::vector<int>{-1, -1, 0, 0}));
    // ω = 1.2: all under 4.8 join; min 0.5 < 2.4, mean (2.25 + 4 + 2.25 + 0.5) / 4 = 2.25 < 3.6.
    EXPECT_EQ(thin_segments(mesh, fan, depth, 1.2), (std::vector<int>{0, 0, 0, 0}));
}

TEST(ThinSegments, NoTriangles) {
    EXPECT_TRUE(thin_segments(Mesh{}, {}, {}, 1.0).empty());
}

}  // namespace
