//! Greedy drain-hole search with local swaps (see hole_search.h).
#include "powder/hole_search.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include <tbb/parallel_for.h>

#include "core/error.h"
#include "powder/baseline_holes.h"

namespace fabvdb::powder {

namespace {

//! The search's objective: the later turns by the crater's cone, not the
//! surface of repose the prediction uses: holes as good, 2.5 to 5 times
//! faster (bench_drain; docs/design/drainability.md).
constexpr DrainabilityModel::Crater kCrater = DrainabilityModel::Crater::cone;
//! Sites near a hole the prediction's polish weighs; all of them within reach
//! take seconds (bench_drain; docs/design/drainability.md).
constexpr size_t kPolishSites = 8;

double distance(const DrainHole& a, const DrainHole& b) {
    const double x = a.center[0] - b.center[0], y = a.center[1] - b.center[1], z = a.center[2] - b.center[2];
    return std::sqrt(x * x + y * y + z * z);
}

struct Choice {
    size_t candidate = 0;
    double residual = 0.0;
    bool found = false;
};

class Search {
public:
    Search(const DrainabilityModel& model, const std::vector<DrainHole>& candidates, const HoleSearchOptions& options)
        : model_(model), candidates_(candidates), options_(options) {
        // Representatives in candidate order, each farther than the spacing
        // from those before; every candidate joins its nearest.
        for (size_t c = 0; c < candidates.size(); ++c) {
            bool near = false;
            for (size_t r : representatives_)
                near = near || distance(candidates[c], candidates[r]) < options.min_center_distance;
            if (!near) representatives_.push_back(c);
        }
        members_.resize(representatives_.size());
        for (size_t c = 0; c < candidates.size(); ++c) {
            size_t nearest = 0;
            for (size_t r = 1; r < representatives_.size(); ++r)
                if (distance(candidates[c], candidates[representatives_[r]]) <
                    distance(candidates[c], candidates[representatives_[nearest]]))
                    nearest = r;
            members_[nearest].push_back(c);
        }
        bound_.assign(representatives_.size(), std::numeric_limits<double>::infinity());
        reach_.resize(candidates.size());
        surface_reach_.resize(candidates.size());
    }

    //! What the candidates `chosen` drain together, by the search's
    //! objective (kCrater) or by the prediction's (the surface of repose).
    //! Each candidate's reach for either is computed once and kept.
    DrainabilityModel::Drain drain(const std::vector<size_t>& chosen) { return drain(chosen, kCrater, reach_); }
    DrainabilityModel::Drain predicted_drain(const std::vector<size_t>& chosen) {
        return drain(chosen, DrainabilityModel::Crater::surface, surface_reach_);
    }

    //! Residuals of `sites` (candidate indices) added to `drain`'s holes, in parallel.
    std::vector<double> residuals_with(const DrainabilityModel::Drain& drain, const std::vector<size_t>& sites) {
        compute_reaches(sites, kCrater, reach_);
        std::vector<double> residual(sites.size());
        tbb::parallel_for(size_t(0), sites.size(),
                          [&](size_t k) { residual[k] = model_.residual_with(drain, *reach_[sites[k]]); });
        return residual;
    }

    //! The lowest residual among `sites` added to `drain`'s holes.
    Choice best_of(const DrainabilityModel::Drain& drain, const std::vector<size_t>& sites) {
        return lowest(sites, residuals_with(drain, sites));
    }

    bool allowed(size_t c, const std::vector<DrainHole>& holes, int only_cavity) const {
        return (only_cavity < 0 || candidates_[c].cavity == uint32_t(only_cavity)) &&
               spaced_from(candidates_[c], holes, options_.min_center_distance);
    }

    //! The best candidate to add to `drain`'s holes (lazy greedy over the
    //! representatives, then the chosen one's group).
    Choice best_addition(const DrainabilityModel::Drain& drain, double current, int only_cavity) {
        std::vector<size_t> open;
        for (size_t r = 0; r < representatives_.size(); ++r)
            if (allowed(representatives_[r], drain.holes, only_cavity)) open.push_back(r);
        std::sort(open.begin(), open.end(), [&](size_t a, size_t b) { return bound_[a] > bound_[b]; });
        const size_t batch = 8;
        double best_gain = -std::numeric_limits<double>::infinity();
        size_t best = 0;
        for (size_t next = 0; next < open.size();) {
            // A first visit (infinite bound) evaluates every unseen representative at once.
            size_t end = std::min(open.size(), next + batch);
            while (end < open.size() && std::isinf(bound_[open[end]])) ++end;
            std::vector<size_t> sites;
            for (size_t k = next; k < end; ++k) sites.push_back(representatives_[open[k]]);
            const std::vector<double> residual = residuals_with(drain, sites);
            for (size_t k = next; k < end; ++k) {
                bound_[open[k]] = current - residual[k - next];
                if (bound_[open[k]] > best_gain) {
                    best_gain = bound_[open[k]];
                    best = open[k];
                }
            }
            next = end;
            if (next < open.size() && best_gain >= bound_[open[next]]) break;
        }
        if (open.empty()) return {};
        std::vector<size_t> group;
        for (size_t c : members_[best])
            if (allowed(c, drain.holes, only_cavity)) group.push_back(c);
        return best_of(drain, group);
    }

    //! The best candidate within half the spacing of `hole` to add to `drain`'s holes.
    Choice best_move(const DrainabilityModel::Drain& drain, const DrainHole& hole, int only_cavity) {
        return best_of(drain, near(hole, drain.holes, only_cavity));
    }

    //! The prediction's residual (mm³) of the candidates `chosen`.
    double predicted(const std::vector<size_t>& chosen) { return model_.predicted_residual(predicted_drain(chosen)); }

    //! best_move by the prediction: the best candidate within half the
    //! spacing of `hole` to add to the candidates `others`, among the
    //! kPolishSites the search's objective ranks best there (a surface
    //! reach costs far more than a cone's).
    Choice best_predicted_move(const std::vector<size_t>& others, const DrainHole& hole, int only_cavity) {
        const DrainabilityModel::Crater surface = DrainabilityModel::Crater::surface;
        std::vector<DrainHole> holes;
        for (size_t c : others) holes.push_back(candidates_[c]);
        std::vector<size_t> sites = near(hole, holes, only_cavity);
        if (sites.size() > kPolishSites) {
            const std::vector<double> by_cone = residuals_with(drain(others), sites);
            std::vector<size_t> order(sites.size());
            for (size_t k = 0; k < order.size(); ++k) order[k] = k;
            std::partial_sort(order.begin(), order.begin() + long(kPolishSites), order.end(),
                              [&](size_t a, size_t b) { return by_cone[a] < by_cone[b]; });
            std::vector<size_t> best_sites;
            for (size_t k = 0; k < kPolishSites; ++k) best_sites.push_back(sites[order[k]]);
            sites = std::move(best_sites);
        }
        compute_reaches(sites, surface, surface_reach_);
        std::vector<double> residual(sites.size());
        tbb::parallel_for(size_t(0), sites.size(), [&](size_t k) {
            std::vector<size_t> with = others;
            with.push_back(sites[k]);
            residual[k] = model_.predicted_residual(drain_of(with, surface_reach_));
        });
        return lowest(sites, residual);
    }

private:
    using Reaches = std::vector<std::shared_ptr<const DrainabilityModel::Reach>>;
    //! The site of `sites` with the lowest `residual` (same order).
    static Choice lowest(const std::vector<size_t>& sites, const std::vector<double>& residual) {
        Choice best;
        for (size_t k = 0; k < sites.size(); ++k)
            if (!best.found || residual[k] < best.residual) best = {sites[k], residual[k], true};
        return best;
    }
    //! The allowed candidates within half the spacing of `hole`.
    std::vector<size_t> near(const DrainHole& hole, const std::vector<DrainHole>& holes, int only_cavity) const {
        std::vector<size_t> sites;
        for (size_t c = 0; c < candidates_.size(); ++c)
            if (distance(candidates_[c], hole) < 0.5 * options_.min_center_distance && allowed(c, holes, only_cavity))
                sites.push_back(c);
        return sites;
    }
    void compute_reaches(const std::vector<size_t>& sites, DrainabilityModel::Crater crater, Reaches& reaches) const {
        tbb::parallel_for(size_t(0), sites.size(), [&](size_t k) {
            if (!reaches[sites[k]])
                reaches[sites[k]] = std::make_shared<const DrainabilityModel::Reach>(model_.reach(candidates_[sites[k]], crater));
        });
    }
    DrainabilityModel::Drain drain(const std::vector<size_t>& chosen, DrainabilityModel::Crater crater, Reaches& reaches) {
        compute_reaches(chosen, crater, reaches);
        return drain_of(chosen, reaches);
    }
    //! What `chosen` drain together from reaches already computed (thread-safe).
    DrainabilityModel::Drain drain_of(const std::vector<size_t>& chosen, const Reaches& reaches) const {
        std::vector<DrainHole> holes;
        Reaches reached;
        for (size_t c : chosen) {
            holes.push_back(candidates_[c]);
            reached.push_back(reaches[c]);
        }
        return model_.drain(holes, reached);
    }

    const DrainabilityModel& model_;
    const std::vector<DrainHole>& candidates_;
    const HoleSearchOptions& options_;
    std::vector<size_t> representatives_;
    std::vector<std::vector<size_t>> members_;
    std::vector<double> bound_;  //!< per representative: its last gain (an upper bound on the next)
    Reaches reach_, surface_reach_;  //!< per candidate, once needed
};

//! The holes chosen so far, as candidates, through the phases of the
//! search: the greedy additions, the swaps by the search's objective, the
//! routine's target (automatic mode) and the prediction's judgement.
class Placement {
public:
    Placement(const DrainabilityModel& model, const std::vector<DrainHole>& candidates, uint32_t cavity_count,
              const HoleSearchOptions& options, Progress& progress)
        : model_(model), candidates_(candidates), cavity_count_(cavity_count), options_(options), progress_(progress),
          search_(model, candidates, options), count_(cavity_count, 0) {
        drain_ = search_.drain(chosen_);
        for (double v : drain_.residual_per_cavity) residual_ += v;
        total_ = model.total_volume();
        negligible_ = 1e-6 * total_;
        automatic_ = options.hole_count == 0;
        per_cavity_ = automatic_ ? options.min_per_cavity
                                 : std::min(options.min_per_cavity,
                                            options.hole_count / int(std::max<uint32_t>(cavity_count, 1)));
        ceiling_ = automatic_ ? std::max(options.max_holes, per_cavity_ * int(cavity_count)) : options.hole_count;
    }

    bool automatic() const { return automatic_; }

    //! Phase 1: the best holes one at a time, first the minimum in each
    //! cavity, then anywhere up to the count (automatic: until the residual
    //! is under the target or a hole no longer helps).
    void add_greedily() {
        for (uint32_t cavity = 0; cavity < cavity_count_; ++cavity)
            while (count_[cavity] < per_cavity_) {
                progress_.check();
                const Choice choice = search_.best_addition(drain_, residual_, int(cavity));
                if (!choice.found) break;
                add(choice);
            }
        while (int(chosen_.size()) < ceiling_) {
            progress_.update(double(chosen_.size()) / double(ceiling_ + 1));
            if (automatic_ && residual_ < options_.target_residual_fraction * total_) break;
            if (!add_best()) break;
        }
    }

    //! Phase 2: local swaps by the search's objective.
    void swap_by_objective(HoleSearchResult& result) {
        swap_holes(residual_, result, [&](const std::vector<size_t>& others, const DrainHole& moved) {
            const int only_cavity = count_[moved.cavity] <= per_cavity_ ? int(moved.cavity) : -1;
            return search_.best_move(search_.drain(others), moved, only_cavity);
        });
    }

    //! Phase 3, automatic mode: the prediction is the surface of repose's,
    //! which keeps more than the cone the search compares. Holes are added
    //! (by the cone's gain) while the prediction under the cleaning routine
    //! for them is over the target, then the hole whose loss the prediction
    //! (random routines) feels least is dropped while the routine's
    //! prediction stays under it: the fewest holes that meet it.
    void meet_routine_target() {
        const double target = options_.target_residual_fraction * total_;
        while (int(chosen_.size()) < ceiling_ && routine_kept(chosen_) >= target) {
            progress_.check();
            if (!add_best()) break;
        }
        for (;;) {
            progress_.check();
            Choice drop;
            for (size_t h = 0; h < chosen_.size(); ++h) {
                if (count_[candidates_[chosen_[h]].cavity] <= per_cavity_) continue;
                std::vector<size_t> others = chosen_;
                others.erase(others.begin() + long(h));
                const double without = search_.predicted(others);
                if (!drop.found || without < drop.residual) drop = {h, without, true};
            }
            if (!drop.found) break;
            std::vector<size_t> fewer = chosen_;
            fewer.erase(fewer.begin() + long(drop.candidate));
            if (routine_kept(fewer) >= target) break;
            --count_[candidates_[chosen_[drop.candidate]].cavity];
            chosen_ = std::move(fewer);
        }
    }

    //! Phase 4: the prediction (random routines) judges the holes against as
    //! many lowest-point ones, keeps the better, polishes them by swaps and
    //! evaluates both sets (see hole_search.h).
    void judge(const Vec3& first_gravity, HoleSearchResult& result) {
        double kept = search_.predicted(chosen_);
        const std::vector<size_t> lowest =
            baseline_holes(candidates_, count_, first_gravity, options_.min_center_distance);
        const double lowest_kept = search_.predicted(lowest);
        if (lowest_kept < kept) {
            chosen_ = lowest;
            kept = lowest_kept;
        }
        swap_holes(kept, result, [&](const std::vector<size_t>& others, const DrainHole& moved) {
            return search_.best_predicted_move(others, moved, int(moved.cavity));
        });
        const DrainabilityModel::Drain drained = search_.predicted_drain(chosen_);
        result.evaluation = model_.evaluate(drained);
        result.routine = model_.best_routine(drained, model_.later_turns(), progress_);
        result.routine_evaluation = model_.evaluate(drained, {result.routine});
        result.random_residuals = model_.random_routine_residuals(drained);
        const DrainabilityModel::Drain lowest_drained = search_.predicted_drain(lowest);
        result.baseline_evaluation = model_.evaluate(lowest_drained);
        result.baseline_routine_residual = model_.routine_residual(
            lowest_drained, model_.best_routine(lowest_drained, model_.later_turns(), progress_));
        for (size_t c : chosen_) result.holes.push_back(candidates_[c]);
        for (size_t c : lowest) result.baseline.push_back(candidates_[c]);
    }

private:
    void add(const Choice& choice) {
        chosen_.push_back(choice.candidate);
        ++count_[candidates_[choice.candidate].cavity];
        drain_ = search_.drain(chosen_);
        residual_ = choice.residual;
    }

    //! Adds the best hole anywhere; false when there is none, or (automatic)
    //! when it no longer helps.
    bool add_best() {
        const Choice choice = search_.best_addition(drain_, residual_, -1);
        if (!choice.found || (automatic_ && choice.residual >= residual_ - negligible_)) return false;
        add(choice);
        return true;
    }

    //! Local swaps: moves one hole to a better site nearby while that lowers
    //! `current`; `best_move(others, moved)` finds the best site for `moved`
    //! beside the holes `others`.
    template <typename BestMove>
    void swap_holes(double& current, HoleSearchResult& result, BestMove best_move) {
        for (int pass = 0; pass < 2; ++pass) {
            bool improved = false;
            for (size_t h = 0; h < chosen_.size(); ++h) {
                progress_.check();
                std::vector<size_t> others = chosen_;
                others.erase(others.begin() + long(h));
                const DrainHole& moved = candidates_[chosen_[h]];
                const Choice choice = best_move(others, moved);
                if (!choice.found || choice.residual >= current - negligible_) continue;
                --count_[moved.cavity];
                ++count_[candidates_[choice.candidate].cavity];
                chosen_[h] = choice.candidate;
                current = choice.residual;
                ++result.swaps;
                improved = true;
            }
            if (!improved) break;
        }
    }

    //! The prediction under the cleaning routine the holes would get.
    double routine_kept(const std::vector<size_t>& holes) {
        const DrainabilityModel::Drain drained = search_.predicted_drain(holes);
        return model_.routine_residual(drained, model_.best_routine(drained, model_.later_turns(), progress_));
    }

    const DrainabilityModel& model_;
    const std::vector<DrainHole>& candidates_;
    const uint32_t cavity_count_;
    const HoleSearchOptions& options_;
    Progress& progress_;
    Search search_;
    std::vector<size_t> chosen_;  //!< the holes, as candidates
    std::vector<int> count_;      //!< holes per cavity
    DrainabilityModel::Drain drain_;
    double residual_ = 0.0;  //!< by the search's objective
    double total_ = 0.0, negligible_ = 0.0;
    bool automatic_ = false;
    int per_cavity_ = 0, ceiling_ = 0;
};

}  // namespace

HoleSearchResult search_drain_holes(const DrainabilityModel& model, const std::vector<DrainHole>& candidates,
                                    uint32_t cavity_count, const Vec3& first_gravity, const HoleSearchOptions& options,
                                    Progress& progress) {
    progress.stage("hole search");
    if (options.hole_count < 0) throw Error(FABVDB_ERR_INVALID_ARGUMENT, "the hole count cannot be negative");
    HoleSearchResult result;
    Placement placement(model, candidates, cavity_count, options, progress);
    placement.add_greedily();
    placement.swap_by_objective(result);
    if (placement.automatic()) placement.meet_routine_target();
    placement.judge(first_gravity, result);
    progress.update(1.0);
    return result;
}

}  // namespace fabvdb::powder
