//! The best cleaning routine by the prediction (see best_cleaning_routine.h).
#include "powder/best_cleaning_routine.h"

#include <algorithm>

#include <tbb/parallel_for.h>

#include "core/vec3_ops.h"

namespace fabvdb::powder {

Routine best_cleaning_routine(const TurnSamples& samples, const HoleSetDrain& drained, int length,
                              const std::vector<Routine>& random, const Progress& progress) {
    const std::vector<Vec3>& gravity = samples.later_gravity;
    std::vector<CavityPowder> later;
    for (uint32_t c = 0; c < samples.cavity_count; ++c) later.push_back(cavity_powder(samples, drained, c));
    using Fill = std::vector<std::vector<double>>;  // per cavity
    auto left_of = [&](const Fill& fill) {
        double sum = 0.0;
        for (size_t c = 0; c < later.size(); ++c) sum += later[c].left(fill[c]);
        return sum;
    };
    auto turn = [&](Fill& fill, uint32_t k) {
        for (size_t c = 0; c < later.size(); ++c) predicted_turn(samples, drained, later[c], k, fill[c]);
    };
    Fill start;
    for (const CavityPowder& cavity : later) start.push_back(cavity.start);
    const double tie = 1e-6 * samples.powder->total_volume();
    auto gravity_before = [&](const Routine& routine, size_t t) {
        return t == 0 ? samples.first_gravity : gravity[routine[t - 1]];
    };
    // Of the turns whose `left` is within `tie` of the least, the one with
    // the smallest tilt from `previous`.
    auto pick = [&](const std::vector<double>& left, const Vec3& previous) {
        const double least = *std::min_element(left.begin(), left.end());
        uint32_t best = 0;
        double best_tilt = -2.0;
        for (size_t k = 0; k < left.size(); ++k) {
            const double cosine = dot(gravity[k], previous);  // larger: a smaller tilt
            if (left[k] <= least + tie && cosine > best_tilt) {
                best_tilt = cosine;
                best = uint32_t(k);
            }
        }
        return best;
    };
    // Greedy: each turn the one that leaves the least after it.
    Routine routine;
    Fill fill = start;
    for (int t = 0; t < length; ++t) {
        std::vector<double> left(gravity.size(), 0.0);
        tbb::parallel_for(size_t(0), gravity.size(), [&](size_t k) {
            if (progress.cancelled()) return;
            Fill next = fill;
            turn(next, uint32_t(k));
            left[k] = left_of(next);
        });
        progress.check();
        routine.push_back(pick(left, gravity_before(routine, routine.size())));
        turn(fill, routine.back());
    }
    auto residual_of = [&](const Routine& candidate) {
        Fill end = start;
        for (uint32_t k : candidate) turn(end, k);
        return left_of(end);
    };
    // The greedy routine can be short-sighted: start from the best of it and
    // the random routines (so it never leaves more than their mean), then
    // change one turn at a time while that leaves less.
    double best = residual_of(routine);
    for (const Routine& candidate : random) {
        if (int(candidate.size()) != length) continue;
        progress.check();
        const double residual = residual_of(candidate);
        if (residual < best - tie) {
            best = residual;
            routine = candidate;
        }
    }
    for (int pass = 0; pass < 2; ++pass) {
        bool improved = false;
        Fill before = start;  // the powder before turn t
        for (size_t t = 0; t < routine.size(); ++t) {
            std::vector<double> left(gravity.size(), 0.0);
            tbb::parallel_for(size_t(0), gravity.size(), [&](size_t k) {
                if (progress.cancelled()) return;
                Fill end = before;
                turn(end, uint32_t(k));
                for (size_t u = t + 1; u < routine.size(); ++u) turn(end, routine[u]);
                left[k] = left_of(end);
            });
            progress.check();
            const uint32_t k = pick(left, gravity_before(routine, t));
            if (left[k] < best - tie) {
                routine[t] = k;
                best = left[k];
                improved = true;
            }
            turn(before, routine[t]);
        }
        if (!improved) break;
    }
    return routine;
}

}  // namespace fabvdb::powder
