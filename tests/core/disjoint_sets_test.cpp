//! DisjointSets: the partition after unions equals the connected pieces of
//! the same edges found by a breadth-first search written here; each set's
//! root is its least index whatever the order of the unions; add() extends.
#include <gtest/gtest.h>

#include <algorithm>
#include <queue>
#include <random>
#include <utility>
#include <vector>

#include "core/disjoint_sets.h"

namespace {

std::vector<uint32_t> least_of_piece(size_t n, const std::vector<std::pair<uint32_t, uint32_t>>& edges) {
    std::vector<std::vector<uint32_t>> next(n);
    for (const auto& [a, b] : edges) {
        next[a].push_back(b);
        next[b].push_back(a);
    }
    std::vector<uint32_t> least(n, UINT32_MAX);
    for (uint32_t start = 0; start < n; ++start) {
        if (least[start] != UINT32_MAX) continue;
        std::queue<uint32_t> open;
        open.push(start);
        least[start] = start;  // visited in increasing order: start is the least
        while (!open.empty()) {
            const uint32_t v = open.front();
            open.pop();
            for (uint32_t w : next[v])
                if (least[w] == UINT32_MAX) {
                    least[w] = start;
                    open.push(w);
                }
        }
    }
    return least;
}

}  // namespace

TEST(DisjointSets, RootsAreTheLeastIndexOfEachPieceInAnyOrder) {
    std::mt19937 generator(7);
    const size_t n = 500;
    std::vector<std::pair<uint32_t, uint32_t>> edges;
    for (int e = 0; e < 300; ++e)
        edges.push_back({uint32_t(generator() % n), uint32_t(generator() % n)});
    const std::vector<uint32_t> expected = least_of_piece(n, edges);
    for (int order = 0; order < 3; ++order) {
        std::shuffle(edges.begin(), edges.end(), generator);
        fabvdb::DisjointSets sets(n);
        for (const auto& [a, b] : edges) {
            const uint32_t root = sets.unite(a, b);
            EXPECT_EQ(root, sets.find(a));
            EXPECT_EQ(root, sets.find(b));
        }
        for (uint32_t v = 0; v < n; ++v) EXPECT_EQ(sets.find(v), expected[v]) << "vertex " << v;
    }
}

TEST(DisjointSets, AddExtendsWithSingletons) {
    fabvdb::DisjointSets sets;
    EXPECT_EQ(sets.size(), 0u);
    EXPECT_EQ(sets.add(), 0u);
    EXPECT_EQ(sets.add(), 1u);
    EXPECT_EQ(sets.add(), 2u);
    EXPECT_EQ(sets.find(2), 2u);
    EXPECT_EQ(sets.unite(2, 1), 1u);
    EXPECT_EQ(sets.find(2), 1u);
    EXPECT_EQ(sets.find(0), 0u);
    EXPECT_EQ(sets.size(), 3u);
}
