//! Powder slid down at the start of a turn (see settle_powder.h).
#include "powder/settle_powder.h"

#include <algorithm>

namespace fabvdb::powder {

namespace {

//! Below this, a sample counts as empty or full.
constexpr double kTiny = 1e-12;

}  // namespace

void settle_powder(const TurnSamples& samples, uint32_t turn, uint32_t cavity, std::vector<double>& fill) {
    const SampleSlides& slides = samples.later_slides[turn];
    const std::vector<std::array<uint32_t, 26>>& links = samples.later_local_links[cavity];
    // The deepest sample with room one slide down from `i`, kNoSample if none.
    auto next = [&](uint32_t i) {
        for (uint8_t d : slides.steps) {
            const uint32_t j = links[i][d];
            if (j != kNoSample && fill[j] < 1.0 - kTiny) return j;
        }
        return kNoSample;
    };
    for (uint32_t i : slides.order[cavity]) {
        double& here = fill[i];
        while (here > kTiny) {
            uint32_t end = next(i);
            if (end == kNoSample) break;
            for (uint32_t j = next(end); j != kNoSample; j = next(end)) end = j;
            double& there = fill[end];
            const double moved = std::min(here, 1.0 - there);
            there += moved;
            here -= moved;
        }
        if (here < kTiny) here = 0.0;
    }
}

}  // namespace fabvdb::powder
