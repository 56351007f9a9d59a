//! Powder coming to rest in its basins (see settle_in_basins.h).
#include "powder/settle_in_basins.h"

#include <algorithm>

#include "powder/sample_grid.h"

namespace fabvdb::powder {

std::vector<uint32_t> slide_targets(const std::vector<std::array<uint32_t, 6>>& neighbours, const SublevelForest& forest) {
    std::vector<uint32_t> target(forest.order.size());
    for (uint32_t a : forest.order) {
        uint32_t lowest = a;
        for (uint32_t b : neighbours[a])
            if (b != kNoSample && forest.rank[b] < forest.rank[lowest]) lowest = b;
        target[a] = lowest == a ? a : target[lowest];
    }
    return target;
}

BasinFill::BasinFill(size_t sample_count)
    : own_(sample_count), water_(sample_count), room_(sample_count), kept_(sample_count), lack_(sample_count),
      share_(sample_count) {}

double BasinFill::settle(const std::vector<uint32_t>& samples, const SublevelForest& forest,
                         const std::vector<uint32_t>& slide_to, const std::vector<uint64_t>& no_room,
                         std::vector<double>& fill) {
    for (size_t i = 0; i < samples.size(); ++i) {
        const uint32_t a = samples[i];
        own_[a] = !no_room.empty() && ((no_room[i >> 6] >> (i & 63)) & 1u) ? 0.0 : 1.0;
        water_[a] = kept_[a] = lack_[a] = 0.0;
        room_[a] = own_[a];
    }
    double given = 0.0;
    for (uint32_t a : samples) {
        water_[slide_to[a]] += fill[a];
        given += fill[a];
    }
    // Up the forest: the powder and the room of each subtree.
    for (uint32_t a : samples) {
        const uint32_t up = forest.parent[a];
        if (up == a) continue;
        water_[up] += water_[a];
        room_[up] += room_[a];
        kept_[up] += std::min(water_[a], room_[a]);
        lack_[up] += std::max(0.0, room_[a] - water_[a]);
    }
    // Down the forest: a subtree holds its own powder up to its room, plus
    // its share of the spill from its siblings; its children fill first
    // (they lie lower), the sample itself takes the rest.
    double kept = 0.0;
    for (auto it = samples.rbegin(); it != samples.rend(); ++it) {
        const uint32_t a = *it;
        const uint32_t up = forest.parent[a];
        double held = std::min(water_[a], room_[a]);
        if (up != a) held += share_[up] * std::max(0.0, room_[a] - water_[a]);
        const double spill = std::max(0.0, held - kept_[a]);
        share_[a] = lack_[a] > 0.0 ? std::min(1.0, spill / lack_[a]) : 0.0;
        fill[a] = std::clamp(spill - std::min(spill, lack_[a]), 0.0, own_[a]);
        kept += fill[a];
    }
    return std::max(0.0, given - kept);
}

}  // namespace fabvdb::powder
