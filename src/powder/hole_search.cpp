//! Greedy drain-hole search with local swaps (see hole_search.h).
#include "powder/hole_search.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace fabvdb::powder {

namespace {

struct Choice {
    size_t candidate = 0;
    DrainEvaluation evaluation;
    bool found = false;
};

//! The best allowed candidate to add to `holes`: top estimates checked exactly.
Choice best_addition(const DrainabilityModel& model, const std::vector<DrainHole>& candidates,
                     const std::vector<DrainHole>& holes, const DrainEvaluation& current, int only_cavity,
                     const HoleSearchOptions& options) {
    const std::vector<double> gains = model.estimate_gains(holes, current, candidates);
    std::vector<size_t> allowed;
    for (size_t c = 0; c < candidates.size(); ++c)
        if ((only_cavity < 0 || candidates[c].cavity == uint32_t(only_cavity)) &&
            spaced_from(candidates[c], holes, options.min_center_distance))
            allowed.push_back(c);
    const size_t checks = std::min(allowed.size(), size_t(std::max(1, options.exact_checks)));
    std::partial_sort(allowed.begin(), allowed.begin() + checks, allowed.end(),
                      [&](size_t a, size_t b) { return gains[a] > gains[b]; });
    Choice best;
    for (size_t k = 0; k < checks; ++k) {
        std::vector<DrainHole> trial = holes;
        trial.push_back(candidates[allowed[k]]);
        DrainEvaluation evaluation = model.evaluate(trial);
        if (!best.found || evaluation.residual_volume < best.evaluation.residual_volume) {
            best.candidate = allowed[k];
            best.evaluation = std::move(evaluation);
            best.found = true;
        }
    }
    return best;
}

}  // namespace

HoleSearchResult search_drain_holes(const DrainabilityModel& model, const std::vector<DrainHole>& candidates,
                                    uint32_t cavity_count, const HoleSearchOptions& options, Progress& progress) {
    progress.stage("hole search");
    if (options.hole_count < 0) throw Error(FABVDB_ERR_INVALID_ARGUMENT, "the hole count cannot be negative");
    HoleSearchResult result;
    result.evaluation = model.evaluate(result.holes);
    const bool automatic = options.hole_count == 0;
    const int per_cavity =
        automatic ? options.min_per_cavity
                  : std::min(options.min_per_cavity, options.hole_count / int(std::max<uint32_t>(cavity_count, 1)));
    const int ceiling = automatic ? std::max(options.max_holes, per_cavity * int(cavity_count)) : options.hole_count;

    std::vector<int> count(cavity_count, 0);
    auto add = [&](Choice&& choice) {
        result.holes.push_back(candidates[choice.candidate]);
        ++count[candidates[choice.candidate].cavity];
        result.evaluation = std::move(choice.evaluation);
    };
    for (uint32_t cavity = 0; cavity < cavity_count; ++cavity)
        while (count[cavity] < per_cavity) {
            progress.check();
            Choice choice = best_addition(model, candidates, result.holes, result.evaluation, int(cavity), options);
            if (!choice.found) break;
            add(std::move(choice));
        }
    while (int(result.holes.size()) < ceiling) {
        progress.update(double(result.holes.size()) / double(ceiling + 1));
        if (automatic && result.evaluation.residual_fraction() < options.target_residual_fraction) break;
        Choice choice = best_addition(model, candidates, result.holes, result.evaluation, -1, options);
        if (!choice.found) break;
        if (automatic && choice.evaluation.residual_volume >=
                             result.evaluation.residual_volume - 1e-6 * result.evaluation.total_volume)
            break;
        add(std::move(choice));
    }

    // Local swaps: replace one hole by the best candidate while that helps.
    for (int pass = 0; pass < 2; ++pass) {
        bool improved = false;
        for (size_t h = 0; h < result.holes.size(); ++h) {
            progress.check();
            std::vector<DrainHole> others = result.holes;
            const DrainHole removed = others[h];
            others.erase(others.begin() + long(h));
            const DrainEvaluation without = model.evaluate(others);
            const int only_cavity = count[removed.cavity] <= per_cavity ? int(removed.cavity) : -1;
            Choice choice = best_addition(model, candidates, others, without, only_cavity, options);
            if (!choice.found || choice.evaluation.residual_volume >=
                                     result.evaluation.residual_volume - 1e-6 * result.evaluation.total_volume)
                continue;
            --count[removed.cavity];
            ++count[candidates[choice.candidate].cavity];
            others.insert(others.begin() + long(h), candidates[choice.candidate]);
            result.holes = std::move(others);
            result.evaluation = std::move(choice.evaluation);
            ++result.swaps;
            improved = true;
        }
        if (!improved) break;
    }
    progress.update(1.0);
    return result;
}

}  // namespace fabvdb::powder
