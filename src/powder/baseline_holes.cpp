//! Lowest-point drain holes (see baseline_holes.h).
#include "powder/baseline_holes.h"

#include <algorithm>
#include <numeric>

namespace fabvdb::powder {

std::vector<size_t> baseline_holes(const std::vector<DrainHole>& candidates, const std::vector<int>& per_cavity,
                                      const Vec3& gravity, double min_center_distance) {
    auto height = [&](const DrainHole& hole) {
        return -(hole.center[0] * gravity[0] + hole.center[1] * gravity[1] + hole.center[2] * gravity[2]);
    };
    std::vector<size_t> order(candidates.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::sort(order.begin(), order.end(),
              [&](size_t a, size_t b) { return height(candidates[a]) < height(candidates[b]); });
    std::vector<DrainHole> holes;
    std::vector<size_t> chosen;
    std::vector<int> taken(per_cavity.size(), 0);
    for (size_t index : order) {
        const DrainHole& candidate = candidates[index];
        if (candidate.cavity >= per_cavity.size() || taken[candidate.cavity] >= per_cavity[candidate.cavity])
            continue;
        if (!spaced_from(candidate, holes, min_center_distance)) continue;
        holes.push_back(candidate);
        chosen.push_back(index);
        ++taken[candidate.cavity];
    }
    return chosen;
}

}  // namespace fabvdb::powder
