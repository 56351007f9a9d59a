//! Drain heat maps from the powder left (see drain_heat_map.h).
#include "powder/drain_heat_map.h"

namespace fabvdb::powder {

DrainHeatMap drain_heat_map(const CavityPatches& patches, const PowderSamples& powder, const std::vector<double>& left,
                            const std::vector<uint32_t>& stand_in) {
    DrainHeatMap result;
    const size_t n = patches.size();
    result.initial_per_patch.assign(n, 0.0);
    result.left_per_patch.assign(n, 0.0);
    for (size_t a = 0; a < powder.position.size(); ++a) {
        result.initial_per_patch[powder.rest_patch[a]] += powder.sample_volume;
        result.left_per_patch[powder.rest_patch[a]] += left[a];
    }
    std::vector<double> cavity_initial(patches.cavity_count, 0.0), cavity_left(patches.cavity_count, 0.0);
    for (size_t j = 0; j < n; ++j) {
        cavity_initial[patches.cavity[j]] += result.initial_per_patch[j];
        cavity_left[patches.cavity[j]] += result.left_per_patch[j];
    }
    auto share = [](double initial, double left) { return initial > 0.0 ? 1.0 - left / initial : 1.0; };
    result.drained_share.resize(n);
    for (size_t j = 0; j < n; ++j) {
        if (result.initial_per_patch[j] > 0.0) {
            result.drained_share[j] = share(result.initial_per_patch[j], result.left_per_patch[j]);
            continue;
        }
        const uint32_t p = stand_in[j];
        result.drained_share[j] = result.initial_per_patch[p] > 0.0
                                      ? share(result.initial_per_patch[p], result.left_per_patch[p])
                                      : share(cavity_initial[patches.cavity[j]], cavity_left[patches.cavity[j]]);
    }
    return result;
}

}  // namespace fabvdb::powder
