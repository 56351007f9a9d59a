// triangle_box_pairs against a brute-force O(n²) loop over the triangles'
// boxes written here: the visited pairs are exactly the pairs of distinct
// triangles whose closed boxes overlap, each once, on random triangles of one
// size and of sizes spread over four decades (several grid levels), and
// where boxes only touch; the triangles near marked ones are exactly those
// whose box meets a marked box, including one too large for the grid.
#include "volume/triangle_box_pairs.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <random>
#include <utility>
#include <vector>

#include "support/shapes.h"

namespace fabvdb::volume {
namespace {

using Pairs = std::vector<std::pair<uint32_t, uint32_t>>;

bool boxes_meet(const Mesh& mesh, uint32_t s, uint32_t t) {
    for (int k = 0; k < 3; ++k) {
        const auto range = [&](uint32_t triangle) {
            const Triangle& corners = mesh.triangles[triangle];
            return std::minmax({mesh.vertices[corners[0]][k], mesh.vertices[corners[1]][k], mesh.vertices[corners[2]][k]});
        };
        const auto [s_lo, s_hi] = range(s);
        const auto [t_lo, t_hi] = range(t);
        if (s_hi < t_lo || t_hi < s_lo) return false;
    }
    return true;
}

Pairs brute_force_pairs(const Mesh& mesh) {
    Pairs pairs;
    for (uint32_t i = 0; i < mesh.triangles.size(); ++i)
        for (uint32_t j = i + 1; j < mesh.triangles.size(); ++j)
            if (boxes_meet(mesh, i, j)) pairs.emplace_back(i, j);
    return pairs;
}

// The visited pairs as (min, max), sorted, repeats kept.
Pairs visited_pairs(const Mesh& mesh) {
    Pairs pairs;
    std::mutex mutex;
    for_each_overlapping_box_pair(mesh, [&](uint32_t i, uint32_t j) {
        const std::lock_guard<std::mutex> lock(mutex);
        pairs.emplace_back(std::min(i, j), std::max(i, j));
    });
    std::sort(pairs.begin(), pairs.end());
    return pairs;
}

// `count` random triangles in [0, 10]³, each within a cube of side `size`
// (or, when `spread`, of a side from 0.01 to 10, uniform in its logarithm).
Mesh random_triangles(int count, double size, bool spread, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<std::array<Vec3, 3>> corners;
    for (int t = 0; t < count; ++t) {
        const Vec3 at = {10 * unit(rng), 10 * unit(rng), 10 * unit(rng)};
        const double side = spread ? std::pow(10.0, -2.0 + 3.0 * unit(rng)) : size;
        std::array<Vec3, 3> triangle;
        for (Vec3& p : triangle) p = {at[0] + side * unit(rng), at[1] + side * unit(rng), at[2] + side * unit(rng)};
        corners.push_back(triangle);
    }
    return test::loose_triangles(corners);
}

TEST(TriangleBoxPairs, FewerThanTwoTrianglesVisitNothing) {
    EXPECT_TRUE(visited_pairs(Mesh{}).empty());
    EXPECT_TRUE(visited_pairs(test::loose_triangles({{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}})).empty());
}

TEST(TriangleBoxPairs, BoxesThatTouchOrOverlapAreVisitedOnce) {
    // Boxes [0,1]³-ish: the second touches the first's face x = 1, the third
    // is 0.01 beyond it, the fourth lies inside the first's box.
    const Mesh mesh = test::loose_triangles({{{{0, 0, 0}, {1, 0, 1}, {0, 1, 0}}},
                                             {{{1, 0, 0}, {2, 1, 0}, {2, 0, 1}}},
                                             {{{2.01, 0, 0}, {3, 1, 0}, {3, 0, 1}}},
                                             {{{0.2, 0.2, 0.2}, {0.4, 0.2, 0.2}, {0.2, 0.4, 0.3}}}});
    EXPECT_EQ(visited_pairs(mesh), (Pairs{{0, 1}, {0, 3}}));
}

TEST(TriangleBoxPairs, AClosedBoxMeetsEveryNeighbour) {
    // Each of make_box's 12 triangles has the whole square of its face as its
    // box, so its box meets every other but those of the opposite face, a
    // side away: of the 66 pairs, 3 pairs of opposite faces × 4 are apart.
    const Mesh box = test::make_box({0, 0, 0}, {1, 1, 1});
    const Pairs pairs = visited_pairs(box);
    EXPECT_EQ(pairs, brute_force_pairs(box));
    EXPECT_EQ(pairs.size(), 54u);
}

TEST(TriangleBoxPairs, SameAsBruteForceOnRandomTriangles) {
    for (uint32_t seed = 1; seed <= 3; ++seed) {
        const Mesh even = random_triangles(1500, 1.0, false, seed);
        const Pairs expected = brute_force_pairs(even);
        ASSERT_GT(expected.size(), 200u);
        EXPECT_EQ(visited_pairs(even), expected) << "seed " << seed;
        // Sizes over four decades: a few large triangles over many small ones.
        const Mesh spread = random_triangles(1500, 0.0, true, seed);
        EXPECT_EQ(visited_pairs(spread), brute_force_pairs(spread)) << "seed " << seed;
    }
}

TEST(TriangleBoxPairs, NearMarkedIsEveryTriangleWhoseBoxMeetsAMarkedOne) {
    Mesh mesh = random_triangles(800, 0.0, true, 7);
    // One triangle across the whole cube, whose box meets too many cells of
    // the marked triangles' grid to look them up one by one.
    mesh.vertices.push_back({-1, -1, -1});
    mesh.vertices.push_back({11, 0, 0});
    mesh.vertices.push_back({0, 11, 11});
    const uint32_t last = uint32_t(mesh.vertices.size());
    mesh.triangles.push_back({last - 3, last - 2, last - 1});
    std::vector<char> marked(mesh.triangles.size(), 0);
    EXPECT_TRUE(triangles_near_marked(mesh, marked).empty());
    for (size_t t = 0; t < marked.size(); t += 37) marked[t] = 1;
    std::vector<uint32_t> expected;
    for (uint32_t t = 0; t < mesh.triangles.size(); ++t) {
        bool near = marked[t];
        for (uint32_t m = 0; m < mesh.triangles.size() && !near; ++m) near = marked[m] && boxes_meet(mesh, t, m);
        if (near) expected.push_back(t);
    }
    ASSERT_GT(expected.size(), 2 * size_t(std::count(marked.begin(), marked.end(), 1)));
    EXPECT_EQ(triangles_near_marked(mesh, marked), expected);
    EXPECT_TRUE(std::binary_search(expected.begin(), expected.end(), uint32_t(mesh.triangles.size() - 1)));
}

}  // namespace
}  // namespace fabvdb::volume
