//! The sublevel merge forest (see sublevel_forest.h).
#include "powder/sublevel_forest.h"

#include <algorithm>
#include <numeric>

#include "powder/sample_grid.h"

namespace fabvdb::powder {

SublevelForest sublevel_forest(const std::vector<std::array<uint32_t, 6>>& neighbours, const std::vector<float>& height) {
    const size_t n = height.size();
    SublevelForest forest;
    forest.order.resize(n);
    std::iota(forest.order.begin(), forest.order.end(), 0u);
    std::sort(forest.order.begin(), forest.order.end(), [&](uint32_t a, uint32_t b) {
        return height[a] < height[b] || (height[a] == height[b] && a < b);
    });
    forest.rank.resize(n);
    for (uint32_t r = 0; r < n; ++r) forest.rank[forest.order[r]] = r;
    forest.parent.resize(n);
    // Union-find over the samples added so far; `top` is the latest sample
    // of each component (its root in the forest).
    std::vector<uint32_t> set(n), top(n);
    auto find = [&](uint32_t a) {
        while (set[a] != a) a = set[a] = set[set[a]];
        return a;
    };
    for (uint32_t s : forest.order) {
        set[s] = s;
        top[s] = s;
        forest.parent[s] = s;
        for (uint32_t neighbour : neighbours[s]) {
            if (neighbour == kNoSample || forest.rank[neighbour] > forest.rank[s]) continue;
            const uint32_t root = find(neighbour), mine = find(s);
            if (root == mine) continue;
            forest.parent[top[root]] = s;
            set[root] = mine;
        }
    }
    return forest;
}

}  // namespace fabvdb::powder
