//! The hole search's pile objective (see pile_residual.h).
#include "powder/pile_residual.h"

#include <algorithm>

#include "powder/sample_bits.h"

namespace fabvdb::powder {

PileTurn pile_turn(double start, size_t count, const std::vector<uint64_t>& drained,
                   const std::vector<uint32_t>& before) {
    PileTurn after;
    for (int b = 0; b <= kPileLevels; ++b) {
        const double pile = start * double(b) / kPileLevels * double(count);  // samples in the pile
        const double left = pile - count_below(drained, before, pile, count);
        after[size_t(b)] = std::clamp(left / (start * double(count)) * kPileLevels, 0.0, double(b));
    }
    return after;
}

double expected_pile_residual(double start, const std::vector<PileTurn>& moving, size_t still, int later_turns) {
    // Each pile after a turn as the level below it and its fraction of the
    // step above, by level before the turn, then turn.
    const size_t turns = moving.size();
    std::vector<int> low(turns * (kPileLevels + 1));
    std::vector<double> fraction(low.size());
    for (size_t k = 0; k < turns; ++k)
        for (size_t b = 0; b <= kPileLevels; ++b) {
            const double u = moving[k][b];
            const size_t i = b * turns + k;
            low[i] = std::min(int(u), kPileLevels - 1);
            fraction[i] = u - low[i];
        }
    const double all = double(turns + still);
    std::vector<double> residual(kPileLevels + 1), next(kPileLevels + 1);
    for (int b = 0; b <= kPileLevels; ++b) residual[size_t(b)] = start * double(b) / kPileLevels;
    for (int t = 0; t < later_turns; ++t) {
        for (int b = 0; b <= kPileLevels; ++b) {
            double sum = double(still) * residual[size_t(b)];
            for (size_t i = size_t(b) * turns; i < size_t(b + 1) * turns; ++i) {
                const double f = fraction[i];
                sum += (1.0 - f) * residual[size_t(low[i])] + f * residual[size_t(low[i] + 1)];
            }
            next[size_t(b)] = sum / all;
        }
        residual.swap(next);
    }
    return residual[kPileLevels];
}

}  // namespace fabvdb::powder
