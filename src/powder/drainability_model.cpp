//! The drainability model (see drainability_model.h).
#include "powder/drainability_model.h"

#include <cmath>

#include <tbb/parallel_for.h>

#include "core/error.h"
#include "powder/best_cleaning_routine.h"
#include "powder/drain_heat_map.h"
#include "powder/hole_tunnel.h"

namespace fabvdb::powder {

namespace {

double sum(const std::vector<double>& values) {
    double total = 0.0;
    for (double v : values) total += v;
    return total;
}

}  // namespace

DrainabilityModel::DrainabilityModel(const CavityPatches& patches, const std::vector<OrientationFlow>& turns,
                                     const OrientationFlow& first, const PowderSamples& powder,
                                     const DrainabilityOptions& options)
    : patches_(patches), powder_(powder), options_(options) {
    if (!(options.effort >= 0.0 && options.effort < 1.0))
        throw Error(FABVDB_ERR_INVALID_ARGUMENT, "the effort rho must be in [0, 1)");
    if (turns.empty()) throw Error(FABVDB_ERR_INVALID_ARGUMENT, "the orientation set is empty");
    later_turns_ = int(std::lround(options.effort / (1.0 - options.effort)));
    samples_ = turn_samples(patches, turns, first, powder, options.repose_radians);
    routines_ = prediction_routines(turns.size(), later_turns_);
    stand_in_.resize(patches.size());
    tbb::parallel_for(size_t(0), patches.size(), [&](size_t j) {
        const uint32_t a = samples_.later_grid.nearest(patches.site[j]);
        stand_in_[j] = a == kNoSample ? uint32_t(j) : powder.rest_patch[samples_.later_grid.sample[a]];
    });
}

double DrainabilityModel::total_volume() const { return powder_.total_volume(); }

bool DrainabilityModel::absorbing(const DrainHole& hole, const Vec3& gravity) const {
    return passes_powder(hole, gravity, options_.repose_radians);
}

DrainabilityModel::Reach DrainabilityModel::reach(const DrainHole& hole, Crater crater) const {
    return hole_reach(samples_, hole, crater, options_.repose_radians);
}

DrainabilityModel::Drain DrainabilityModel::drain(const std::vector<DrainHole>& holes, Crater crater) const {
    std::vector<std::shared_ptr<const Reach>> reaches(holes.size());
    tbb::parallel_for(size_t(0), holes.size(),
                      [&](size_t h) { reaches[h] = std::make_shared<const Reach>(reach(holes[h], crater)); });
    return drain(holes, reaches);
}

DrainabilityModel::Drain DrainabilityModel::drain(const std::vector<DrainHole>& holes,
                                                  const std::vector<std::shared_ptr<const Reach>>& reaches) const {
    return hole_set_drain(samples_, holes, reaches, later_turns_);
}

double DrainabilityModel::residual_with(const Drain& drain, const Reach& extra) const {
    return powder::residual_with(samples_, drain, extra, later_turns_);
}

DrainEvaluation DrainabilityModel::evaluate(const std::vector<DrainHole>& holes) const { return evaluate(drain(holes)); }

double DrainabilityModel::predicted_residual(const Drain& drained) const {
    return sum(residual_after_routines(samples_, drained, routines_, nullptr, nullptr));
}

double DrainabilityModel::routine_residual(const Drain& drained, const Routine& routine) const {
    return sum(residual_after_routines(samples_, drained, {routine}, nullptr, nullptr));
}

std::vector<double> DrainabilityModel::random_routine_residuals(const Drain& drained) const {
    std::vector<double> per_routine;
    residual_after_routines(samples_, drained, routines_, nullptr, &per_routine);
    return per_routine;
}

DrainabilityModel::Routine DrainabilityModel::best_routine(const Drain& drained, int length,
                                                           const Progress& progress) const {
    return best_cleaning_routine(samples_, drained, length, routines_, progress);
}

DrainEvaluation DrainabilityModel::evaluate(const Drain& drained) const { return evaluate(drained, routines_); }

DrainEvaluation DrainabilityModel::evaluate(const Drain& drained, const std::vector<Routine>& routines) const {
    DrainEvaluation result;
    result.total_volume = powder_.total_volume();
    result.drained_first_volume = drained.drained_first_volume;
    std::vector<double> left;
    result.residual_per_cavity = residual_after_routines(samples_, drained, routines, &left, nullptr);
    result.residual_volume = sum(result.residual_per_cavity);
    DrainHeatMap heat_map = drain_heat_map(patches_, powder_, left, stand_in_);
    result.drained_share = std::move(heat_map.drained_share);
    result.initial_per_patch = std::move(heat_map.initial_per_patch);
    result.left_per_patch = std::move(heat_map.left_per_patch);
    return result;
}

}  // namespace fabvdb::powder
