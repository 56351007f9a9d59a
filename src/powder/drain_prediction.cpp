//! The prediction: powder kept in place save what drains (see drain_prediction.h).
#include "powder/drain_prediction.h"

#include <algorithm>
#include <random>

#include <tbb/parallel_for.h>

#include "powder/sample_bits.h"
#include "powder/settle_powder.h"
#include "core/vec3_ops.h"

namespace fabvdb::powder {

namespace {

//! The prediction's routines and their seed: 64 rank hole sets as well as
//! 128 (bench_drain --sets 16; docs/design/drainability.md).
constexpr size_t kRoutines = 64;
constexpr uint64_t kRoutineSeed = 2026;

}  // namespace

std::vector<Routine> prediction_routines(size_t turns, int later_turns) {
    // A fixed 64-bit Mersenne twister, no library distribution: the same on every machine.
    std::mt19937_64 generator(kRoutineSeed);
    std::vector<Routine> routines(kRoutines);
    for (Routine& routine : routines)
        for (int t = 0; t < later_turns; ++t) routine.push_back(uint32_t(generator() % turns));
    return routines;
}

double CavityPowder::left(const std::vector<double>& fill) const {
    if (count == 0.0) return retained;
    double sum = 0.0;
    for (double v : fill) sum += v;
    return retained * sum / count;
}

CavityPowder cavity_powder(const TurnSamples& samples, const HoleSetDrain& drained, uint32_t c) {
    CavityPowder later;
    later.retained = double(drained.retained_first[c]) * samples.powder->sample_volume;
    later.samples = &samples.later_chains[0].by_rank[c];
    later.start.reserve(later.samples->size());
    for (uint32_t a : *later.samples) {
        later.start.push_back(bit(drained.first[c], samples.first_rank[a]) ? 0.0 : 1.0);
        later.count += later.start.back();
    }
    const size_t turns = samples.later_gravity.size();
    later.open.resize(turns);
    for (size_t k = 0; k < turns; ++k) {
        for (size_t h = 0; h < drained.reaches.size(); ++h)
            if (drained.reaches[h]->cavity == c && !drained.reaches[h]->later[k].empty()) later.open[k].push_back(h);
        const Vec3& gravity = samples.later_gravity[k];
        std::sort(later.open[k].begin(), later.open[k].end(), [&](size_t x, size_t y) {
            return dot(drained.holes[x].center, gravity) > dot(drained.holes[y].center, gravity);
        });
    }
    later.cavity = c;
    return later;
}

void predicted_turn(const TurnSamples& samples, const HoleSetDrain& drained, const CavityPowder& later, uint32_t k,
                    std::vector<double>& fill) {
    settle_powder(samples, k, later.cavity, fill);
    const std::vector<size_t>& open = later.open[k];
    const std::vector<uint32_t>& by_rank = samples.later_chains[k].by_rank[later.cavity];
    auto powder_at = [&](size_t rank) -> double& { return fill[samples.later_local[by_rank[rank]]]; };
    // Each hole takes the powder above its surface of repose (a sample two
    // holes drain goes to the lower), then the powder it took fills its
    // crater's rim, lowest first, before leaving.
    std::vector<double> out(open.size(), 0.0);
    for (size_t o = 0; o < open.size(); ++o) {
        const std::vector<uint64_t>& bits = drained.reaches[open[o]]->later[k];
        for (size_t w = 0; w < bits.size(); ++w)
            for (uint64_t word = bits[w]; word != 0; word &= word - 1) {
                double& powder = powder_at((w << 6) + size_t(__builtin_ctzll(word)));
                out[o] += powder;
                powder = 0.0;
            }
    }
    const std::vector<uint64_t>& all = drained.later[k][later.cavity];
    for (size_t o = 0; o < open.size(); ++o) {
        const std::vector<uint64_t>& rim = drained.reaches[open[o]]->later_rim[k];
        for (size_t w = 0; w < rim.size() && out[o] > 0.0; ++w)
            for (uint64_t word = rim[w] & ~all[w]; word != 0 && out[o] > 0.0; word &= word - 1) {
                double& powder = powder_at((w << 6) + size_t(__builtin_ctzll(word)));
                const double added = std::min(out[o], 1.0 - powder);
                powder += added;
                out[o] -= added;
            }
    }
}

std::vector<double> residual_after_routines(const TurnSamples& samples, const HoleSetDrain& drained,
                                            const std::vector<Routine>& routines, std::vector<double>* left,
                                            std::vector<double>* per_routine) {
    const PowderSamples& powder = *samples.powder;
    std::vector<double> residual(samples.cavity_count, 0.0);
    if (left) left->assign(powder.position.size(), 0.0);
    if (per_routine) per_routine->assign(routines.size(), 0.0);
    for (uint32_t c = 0; c < samples.cavity_count; ++c) {
        const CavityPowder later = cavity_powder(samples, drained, c);
        if (later.count == 0.0) {
            // Only the first-turn grid keeps some: it stays where it lies.
            residual[c] = later.retained;
            if (left)
                for (uint32_t a : samples.first_chains.by_rank[c])
                    if (!bit(drained.first[c], samples.first_rank[a])) (*left)[a] = powder.sample_volume;
            if (per_routine)
                for (double& v : *per_routine) v += later.retained;
            continue;
        }
        // Per routine: the powder left on each later-turn sample at the end.
        std::vector<std::vector<double>> ends(routines.size());
        tbb::parallel_for(size_t(0), routines.size(), [&](size_t r) {
            ends[r] = later.start;
            for (uint32_t k : routines[r]) predicted_turn(samples, drained, later, k, ends[r]);
        });
        // Each later-turn sample left stands for retained / count of the
        // powder the first turn leaves.
        const double scale = later.retained / (later.count * double(routines.size()));
        for (size_t i = 0; i < later.samples->size(); ++i) {
            double sum = 0.0;
            for (const std::vector<double>& end : ends) sum += end[i];
            residual[c] += scale * sum;
            if (left) (*left)[(*later.samples)[i]] = scale * sum;
        }
        if (per_routine)
            for (size_t r = 0; r < routines.size(); ++r) (*per_routine)[r] += later.left(ends[r]);
    }
    return residual;
}

}  // namespace fabvdb::powder
