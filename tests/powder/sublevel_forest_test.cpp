// The sublevel merge forest against a direct search: on grids with walls and
// random heights, the ancestors of every sample m must be exactly the samples
// s from which a path to m exists through samples no higher than s (found
// here by a breadth-first search per pair, sharing no code with the forest).
#include <gtest/gtest.h>

#include <array>
#include <queue>
#include <random>
#include <vector>

#include "powder/sample_grid.h"
#include "powder/sublevel_forest.h"

namespace {

using Neighbours = std::vector<std::array<uint32_t, 6>>;

//! An n×n×n grid graph without the cells of a wall (x == n/2) except a gap
//! at its top corner; returns the neighbours of the kept cells.
Neighbours walled_grid(int n) {
    auto kept = [&](int x, int y, int z) {
        if (x < 0 || y < 0 || z < 0 || x >= n || y >= n || z >= n) return false;
        return x != n / 2 || (y == n - 1 && z == n - 1);
    };
    std::vector<int> index(size_t(n) * n * n, -1);
    int count = 0;
    for (int x = 0; x < n; ++x)
        for (int y = 0; y < n; ++y)
            for (int z = 0; z < n; ++z)
                if (kept(x, y, z)) index[(size_t(x) * n + y) * n + z] = count++;
    Neighbours neighbours(static_cast<size_t>(count));
    const int step[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (int x = 0; x < n; ++x)
        for (int y = 0; y < n; ++y)
            for (int z = 0; z < n; ++z) {
                if (!kept(x, y, z)) continue;
                auto& mine = neighbours[size_t(index[(size_t(x) * n + y) * n + z])];
                for (int d = 0; d < 6; ++d) {
                    const int a = x + step[d][0], b = y + step[d][1], c = z + step[d][2];
                    mine[size_t(d)] = kept(a, b, c) ? uint32_t(index[(size_t(a) * n + b) * n + c])
                                                    : fabvdb::powder::kNoSample;
                }
            }
    return neighbours;
}

//! Whether a path from `from` to `to` stays within samples no higher than `from`.
bool reaches_without_climbing(const Neighbours& neighbours, const std::vector<float>& height, uint32_t from,
                              uint32_t to) {
    std::vector<char> seen(height.size(), 0);
    std::queue<uint32_t> open;
    open.push(from);
    seen[from] = 1;
    while (!open.empty()) {
        const uint32_t a = open.front();
        open.pop();
        if (a == to) return true;
        for (uint32_t b : neighbours[a])
            if (b != fabvdb::powder::kNoSample && !seen[b] &&
                (height[b] < height[from] || (height[b] == height[from] && b <= from))) {
                seen[b] = 1;
                open.push(b);
            }
    }
    return false;
}

TEST(SublevelForest, AncestorsAreThePowderThatReachesWithoutClimbing) {
    const Neighbours neighbours = walled_grid(6);
    std::mt19937 generator(3);
    std::uniform_real_distribution<float> uniform(0.0f, 10.0f);
    for (int trial = 0; trial < 3; ++trial) {
        std::vector<float> height(neighbours.size());
        for (float& h : height) h = uniform(generator);
        const fabvdb::powder::SublevelForest forest = fabvdb::powder::sublevel_forest(neighbours, height);
        ASSERT_EQ(forest.order.size(), height.size());
        for (size_t r = 1; r < forest.order.size(); ++r)
            EXPECT_LE(height[forest.order[r - 1]], height[forest.order[r]]);
        size_t joined = 0;
        for (uint32_t m = 0; m < height.size(); m += 7) {
            std::vector<char> ancestor(height.size(), 0);
            for (uint32_t a = m;; a = forest.parent[a]) {
                ancestor[a] = 1;
                EXPECT_GE(height[forest.parent[a]], height[a]);
                if (forest.parent[a] == a) break;
            }
            for (uint32_t s = 0; s < height.size(); ++s) {
                ASSERT_EQ(bool(ancestor[s]), reaches_without_climbing(neighbours, height, s, m)) << s << " to " << m;
                joined += ancestor[s] && s != m;
            }
        }
        EXPECT_GT(joined, 0u);
    }
}

}  // namespace
