//! What a hole set drains, and the search's objective (see hole_set_drain.h).
#include "powder/hole_set_drain.h"

#include "powder/pile_residual.h"
#include "powder/sample_bits.h"

namespace fabvdb::powder {

namespace {

//! Expected residual share of cavity `cavity` after the later turns from a
//! pile share `start` after the first, with what `drain` (and `extra`, if
//! not null) drains.
double later_residual_share(const TurnSamples& samples, uint32_t cavity, double start, const HoleSetDrain& drain,
                            const HoleReach* extra, int later_turns) {
    const size_t count = samples.later_count[cavity];
    if (!(start > 0.0)) return 0.0;
    if (count == 0) return start;
    // The turns that drain anything; the other turns leave the pile as it is.
    std::vector<PileTurn> moving;
    size_t still = 0;
    std::vector<uint64_t> bits;
    std::vector<uint32_t> before;
    for (size_t k = 0; k < drain.later.size(); ++k) {
        const std::vector<uint64_t>& base = drain.later[k][cavity];
        const bool more = extra && !extra->later[k].empty();
        if (base.empty() && !more) {
            ++still;
            continue;
        }
        if (more) {
            bits = extra->later[k];
            for (size_t w = 0; w < base.size(); ++w) bits[w] |= base[w];
            before = words_before(bits);
        }
        moving.push_back(
            pile_turn(start, count, more ? bits : base, more ? before : drain.later_before[k][cavity]));
    }
    return expected_pile_residual(start, moving, still, later_turns);
}

}  // namespace

HoleSetDrain hole_set_drain(const TurnSamples& samples, const std::vector<DrainHole>& holes,
                            const std::vector<std::shared_ptr<const HoleReach>>& reaches, int later_turns) {
    const uint32_t cavities = samples.cavity_count;
    const size_t turns = samples.later_gravity.size();
    const double sample_volume = samples.powder->sample_volume;
    HoleSetDrain result;
    result.holes = holes;
    result.first.resize(cavities);
    for (uint32_t c = 0; c < cavities; ++c) result.first[c].assign((samples.first_count[c] + 63) / 64, 0);
    result.later.assign(turns, std::vector<std::vector<uint64_t>>(cavities));
    result.reaches = reaches;
    for (const auto& r : reaches) {
        for (size_t w = 0; w < r->first.size(); ++w) result.first[r->cavity][w] |= r->first[w];
        for (size_t k = 0; k < turns; ++k) {
            if (r->later[k].empty()) continue;
            std::vector<uint64_t>& bits = result.later[k][r->cavity];
            if (bits.empty()) bits.assign(r->later[k].size(), 0);
            for (size_t w = 0; w < bits.size(); ++w) bits[w] |= r->later[k][w];
        }
    }
    result.later_before.resize(turns);
    for (size_t k = 0; k < turns; ++k) {
        result.later_before[k].resize(cavities);
        for (uint32_t c = 0; c < cavities; ++c)
            if (!result.later[k][c].empty()) result.later_before[k][c] = words_before(result.later[k][c]);
    }
    result.retained_first.assign(cavities, 0);
    result.residual_per_cavity.assign(cavities, 0.0);
    for (uint32_t c = 0; c < cavities; ++c) {
        const uint32_t count = samples.first_count[c];
        const uint32_t drained = words_before(result.first[c]).back();
        result.drained_first_volume += double(drained) * sample_volume;
        result.retained_first[c] = count - drained;
        if (count > 0)
            result.residual_per_cavity[c] =
                later_residual_share(samples, c, double(result.retained_first[c]) / double(count), result, nullptr,
                                     later_turns) *
                double(count) * sample_volume;
    }
    return result;
}

double residual_with(const TurnSamples& samples, const HoleSetDrain& drain, const HoleReach& extra, int later_turns) {
    const uint32_t c = extra.cavity;
    double others = 0.0;
    for (uint32_t other = 0; other < samples.cavity_count; ++other)
        if (other != c) others += drain.residual_per_cavity[other];
    const uint32_t count = samples.first_count[c];
    if (count == 0) return others;
    size_t fresh = 0;
    for (size_t w = 0; w < extra.first.size(); ++w)
        fresh += size_t(__builtin_popcountll(extra.first[w] & ~drain.first[c][w]));
    const double share = double(drain.retained_first[c] - fresh) / double(count);
    return others + later_residual_share(samples, c, share, drain, &extra, later_turns) * double(count) *
                        samples.powder->sample_volume;
}

}  // namespace fabvdb::powder
