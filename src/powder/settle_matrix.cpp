//! S(g) from T(g) (see settle_matrix.h).
#include "powder/settle_matrix.h"

#include <algorithm>
#include <numeric>

namespace fabvdb::powder {

StochasticMatrix settle_matrix(const StochasticMatrix& transfer, const CavityPatches& patches, const Vec3& gravity,
                               size_t max_entries, float min_weight) {
    const size_t n = transfer.rows();
    std::vector<double> height(n);
    for (size_t i = 0; i < n; ++i)
        height[i] = -(patches.centroid[i][0] * gravity[0] + patches.centroid[i][1] * gravity[1] +
                      patches.centroid[i][2] * gravity[2]);
    std::vector<uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return height[a] < height[b]; });

    std::vector<std::vector<std::pair<uint32_t, float>>> rows(n);
    std::vector<std::pair<uint32_t, float>> merged;
    for (uint32_t i : order) {
        const uint32_t begin = transfer.row_start[i], end = transfer.row_start[i + 1];
        if (end - begin == 1 && transfer.column[begin] == i) {
            rows[i] = {{i, 1.0f}};
            continue;
        }
        merged.clear();
        for (uint32_t e = begin; e < end; ++e)
            for (const auto& [destination, w] : rows[transfer.column[e]])
                merged.push_back({destination, w * transfer.weight[e]});
        std::sort(merged.begin(), merged.end());
        size_t kept = 0;
        for (size_t e = 0; e < merged.size(); ++e) {
            if (kept > 0 && merged[kept - 1].first == merged[e].first)
                merged[kept - 1].second += merged[e].second;
            else
                merged[kept++] = merged[e];
        }
        merged.resize(kept);
        std::sort(merged.begin(), merged.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
        size_t keep = std::min(merged.size(), max_entries);
        while (keep > 1 && merged[keep - 1].second < min_weight) --keep;
        float total = 0.0f;
        for (size_t e = 0; e < keep; ++e) total += merged[e].second;
        rows[i].assign(merged.begin(), merged.begin() + keep);
        for (auto& entry : rows[i]) entry.second /= total;
    }

    StochasticMatrix settle;
    settle.row_start.reserve(n + 1);
    for (size_t i = 0; i < n; ++i) {
        for (const auto& [destination, w] : rows[i]) {
            settle.column.push_back(destination);
            settle.weight.push_back(w);
        }
        settle.row_start.push_back(uint32_t(settle.column.size()));
    }
    return settle;
}

}  // namespace fabvdb::powder
