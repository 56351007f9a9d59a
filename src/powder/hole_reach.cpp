//! What one drain hole drains alone (see hole_reach.h).
#include "powder/hole_reach.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

#include <tbb/parallel_for.h>

#include "powder/hole_tunnel.h"
#include "powder/sample_bits.h"
#include "core/vec3_ops.h"

namespace fabvdb::powder {

namespace {

//! Bits (by rank in the hole's cavity) of the samples that drain through
//! `hole` above its cone of repose: of the chain from `source` (the sample
//! nearest the hole, kNoSample if none) for `gravity`. Empty if none.
std::vector<uint64_t> above_cone(const PowderSamples& powder, const DrainHole& hole, uint32_t source,
                                 const SampleChains& chains, const std::vector<uint32_t>& cavity, const Vec3& gravity,
                                 double repose_radians) {
    std::vector<uint64_t> bits;
    if (source == kNoSample || cavity[source] != hole.cavity || !passes_powder(hole, gravity, repose_radians))
        return bits;
    const std::vector<uint32_t>& sample = chains.by_rank[hole.cavity];
    bits.assign((sample.size() + 63) / 64, 0);
    const CraterCone crater = crater_cone(hole, gravity, repose_radians);
    uint64_t any = 0;
    for (uint32_t a = source; a != kNoSample; a = chains.after_run[a])
        for (uint32_t r = chains.rank[a], end = chains.run_end[a]; r < end;) {
            // A word at a time, in a register: the tests of a run do not wait on each other.
            const uint32_t word_end = std::min(end, (r | 63) + 1);
            uint64_t word = 0;
            for (; r < word_end; ++r) word |= uint64_t(!crater.below(powder.position[sample[r]])) << (r & 63);
            bits[(r - 1) >> 6] |= word;
            any |= word;
        }
    if (!any) bits.clear();
    return bits;
}

//! Calls `visit(sample)` for each later-grid sample that drains through
//! `hole` above the surface of repose it leaves under `gravity` (whose
//! sublevel forest and relief on the later grid are given), and
//! `under(sample)` for each the surface reaches and buries (`source`: the
//! later grid's sample nearest the hole).
template <class Visit, class Under>
void walk_above_surface(const TurnSamples& samples, const DrainHole& hole, uint32_t source, const Vec3& gravity,
                        const SublevelForest& forest, const SampleRelief& relief, double repose_radians, Visit visit,
                        Under under) {
    const PowderSamples& powder = *samples.powder;
    const SampleGrid& grid = samples.later_grid;
    // A source in another cavity (the hole's nearest sample across a thin
    // wall) drains nothing of this one.
    if (source == kNoSample || samples.later_cavity[source] != hole.cavity ||
        !passes_powder(hole, gravity, repose_radians))
        return;
    // Powder can drain only if it reaches the mouth without climbing (the
    // source's ancestors) and lies above the crater's cone; past the highest
    // such sample nothing more drains.
    constexpr float kUnreached = std::numeric_limits<float>::infinity();
    // Samples that are not the source's ancestors are marked −∞ (levels are
    // heights, of either sign); the ancestors start unreached.
    std::vector<float> surface(grid.size(), -kUnreached);
    const CraterCone crater = crater_cone(hole, gravity, repose_radians);
    float top = -kUnreached;
    // The walk stays in the hole's cavity: the sample grid's neighbours may
    // reach across a wall thinner than its stride into another cavity, whose
    // samples count as walls here.
    for (uint32_t a = source; samples.later_cavity[a] == hole.cavity; a = forest.parent[a]) {
        surface[a] = kUnreached;
        if (!crater.below(powder.position[grid.sample[a]])) top = std::max(top, relief.height[a]);
        if (forest.parent[a] == a) break;
    }
    // The surface the powder keeps, found from the crater outwards (Dijkstra
    // over the ancestors): rising with slope θ_r by the horizontal length of
    // each step along paths through the cavity (steps to the 26 cells
    // around, so the surface is nearly round), never below a floor. Powder
    // above it drains. It never lies below the crater's cone.
    const double tan_repose = std::tan(repose_radians);
    const double step = grid.stride * powder.spacing;
    std::array<float, 26> climb;
    for (size_t d = 0; d < 26; ++d) {
        const Vec3 v{step * kLinkOffsets[d][0], step * kLinkOffsets[d][1], step * kLinkOffsets[d][2]};
        climb[d] = float(tan_repose * rise_and_across(v, {0, 0, 0}, gravity).second);
    }
    const double across = rise_and_across(powder.position[grid.sample[source]], crater.apex, gravity).second;
    const double apex = -dot(crater.apex, gravity);
    surface[source] = float(across <= crater.mouth ? apex - crater.mouth : apex + tan_repose * (across - crater.mouth));
    using Entry = std::pair<float, uint32_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    queue.push({surface[source], source});
    while (!queue.empty()) {
        const auto [level, b] = queue.top();
        queue.pop();
        if (level > surface[b]) continue;
        if (level >= top) break;
        // Powder passes only where the surface leaves room above it: past a
        // sample it buries (a flat passage filled to its top by the slope,
        // in a tube longer than its height / tan θ_r) the way is plugged.
        // The mouth itself is open (passes powder), whatever its height.
        if (relief.height[b] > level)
            visit(b);
        else {
            under(b);
            if (b != source) continue;
        }
        for (size_t d = 0; d < 26; ++d) {
            const uint32_t c = samples.later_links[b][d];
            if (c == kNoSample || surface[c] == -kUnreached) continue;
            const float next = std::max(level + climb[d], relief.floor[c]);
            if (next < surface[c]) {
                surface[c] = next;
                queue.push({next, c});
            }
        }
    }
}

}  // namespace

HoleReach hole_reach(const TurnSamples& samples, const DrainHole& hole, Crater crater, double repose_radians) {
    const size_t turns = samples.later_gravity.size();
    HoleReach result;
    result.cavity = hole.cavity;
    const uint32_t source = samples.later_grid.nearest(hole.center);
    if (crater == Crater::cone) {
        result.first = above_cone(*samples.powder, hole, samples.first_grid.nearest(hole.center), samples.first_chains,
                                  samples.first_cavity, samples.first_gravity, repose_radians);
    } else {
        // Above the surface of repose on the later grid; a first-grid sample
        // drains with the later-grid sample nearest it.
        std::vector<char> drains(samples.later_grid.size(), 0);
        walk_above_surface(
            samples, hole, source, samples.first_gravity, samples.first_later_forest, samples.first_later_relief,
            repose_radians, [&](uint32_t a) { drains[a] = 1; }, [](uint32_t) {});
        for (size_t a = 0; a < samples.first_grid.size(); ++a) {
            const uint32_t b = samples.later_of_first[a];
            if (b == kNoSample || !drains[b] || samples.first_cavity[a] != hole.cavity) continue;
            if (result.first.empty()) result.first.assign((size_t(samples.first_count[hole.cavity]) + 63) / 64, 0);
            set_bit(result.first, samples.first_chains.rank[a]);
        }
    }
    result.later.resize(turns);
    result.later_rim.resize(turns);
    const size_t words = (size_t(samples.later_count[hole.cavity]) + 63) / 64;
    tbb::parallel_for(size_t(0), turns, [&](size_t k) {
        if (crater == Crater::cone)
            result.later[k] = above_cone(*samples.powder, hole, source, samples.later_chains[k], samples.later_cavity,
                                         samples.later_gravity[k], repose_radians);
        else {
            auto mark = [&](std::vector<uint64_t>& bits, uint32_t a) {
                if (bits.empty()) bits.assign(words, 0);
                set_bit(bits, samples.later_chains[k].rank[a]);
            };
            walk_above_surface(
                samples, hole, source, samples.later_gravity[k], samples.later_forests[k], samples.later_relief[k],
                repose_radians, [&](uint32_t a) { mark(result.later[k], a); },
                [&](uint32_t a) { mark(result.later_rim[k], a); });
        }
    });
    return result;
}

}  // namespace fabvdb::powder
