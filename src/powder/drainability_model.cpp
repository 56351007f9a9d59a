//! The drainability model (see drainability_model.h).
#include "powder/drainability_model.h"

#include <cmath>

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>
#include <tbb/parallel_for.h>

#include "core/error.h"

namespace fabvdb::powder {

namespace {

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

std::vector<std::vector<uint32_t>> region_members(const OrientationFlow& flow) {
    std::vector<std::vector<uint32_t>> members;
    for (uint32_t j = 0; j < flow.region.size(); ++j) {
        if (flow.region[j] < 0) continue;
        if (size_t(flow.region[j]) >= members.size()) members.resize(size_t(flow.region[j]) + 1);
        members[size_t(flow.region[j])].push_back(j);
    }
    return members;
}

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

Eigen::VectorXd solve(const SparseMatrix& matrix, const Eigen::VectorXd& rhs) {
    Eigen::BiCGSTAB<SparseMatrix> solver;
    solver.setTolerance(1e-10);
    solver.compute(matrix);
    Eigen::VectorXd x = solver.solve(rhs);
    if (solver.info() != Eigen::Success)
        throw Error(FABVDB_ERR_INTERNAL, "the drainability system did not converge");
    return x;
}

}  // namespace

struct DrainabilityModel::TurnChain {
    SparseMatrix matrix;
};

namespace {

//! I − ρQ for the captured patches; `leave` (if not null) receives r.
SparseMatrix turn_system(const std::vector<OrientationFlow>& turns, const SparseMatrix& chain, double effort,
                         const std::vector<std::vector<char>>& captured, Eigen::VectorXd* leave) {
    const size_t n = size_t(chain.rows());
    const double weight = 1.0 / double(turns.size());
    if (leave) *leave = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(n));
    std::vector<Eigen::Triplet<double>> removed;
    for (size_t k = 0; k < turns.size(); ++k) {
        const StochasticMatrix& settle = turns[k].settle;
        for (size_t i = 0; i < n; ++i)
            for (uint32_t e = settle.row_start[i]; e < settle.row_start[i + 1]; ++e)
                if (captured[k][settle.column[e]]) {
                    if (leave) (*leave)[int(i)] += weight * settle.weight[e];
                    removed.emplace_back(int(i), int(settle.column[e]), weight * settle.weight[e]);
                }
    }
    SparseMatrix captured_part(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
    captured_part.setFromTriplets(removed.begin(), removed.end());
    SparseMatrix identity(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
    identity.setIdentity();
    return identity - effort * (chain - captured_part);
}

}  // namespace

DrainabilityModel::DrainabilityModel(const CavityPatches& patches, const std::vector<OrientationFlow>& turns,
                                     const OrientationFlow& first, const PowderSamples& powder,
                                     const DrainabilityOptions& options)
    : patches_(patches), turns_(turns), first_(first), powder_(powder), options_(options) {
    if (!(options.effort >= 0.0 && options.effort < 1.0))
        throw Error(FABVDB_ERR_INVALID_ARGUMENT, "the effort rho must be in [0, 1)");
    if (turns.empty()) throw Error(FABVDB_ERR_INVALID_ARGUMENT, "the orientation set is empty");
    tan_repose_ = std::tan(options.repose_radians);
    sin_repose_ = std::sin(options.repose_radians);
    for (const OrientationFlow& flow : turns) turn_region_members_.push_back(region_members(flow));
    first_region_members_ = region_members(first);
    first_region_samples_.resize(first_region_members_.size());
    for (uint32_t s = 0; s < powder.position.size(); ++s) {
        const int32_t region = first.region[powder.rest_patch[s]];
        if (region >= 0) first_region_samples_[size_t(region)].push_back(s);
    }
    const size_t n = patches.size();
    const double weight = 1.0 / double(turns.size());
    std::vector<Eigen::Triplet<double>> entries;
    for (const OrientationFlow& flow : turns)
        for (size_t i = 0; i < n; ++i)
            for (uint32_t e = flow.settle.row_start[i]; e < flow.settle.row_start[i + 1]; ++e)
                entries.emplace_back(int(i), int(flow.settle.column[e]), weight * flow.settle.weight[e]);
    auto chain = std::make_shared<TurnChain>();
    chain->matrix.resize(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
    chain->matrix.setFromTriplets(entries.begin(), entries.end());
    chain_ = std::move(chain);
}

bool spaced_from(const DrainHole& candidate, const std::vector<DrainHole>& holes, double min_center_distance) {
    for (const DrainHole& hole : holes) {
        const Vec3 v{candidate.center[0] - hole.center[0], candidate.center[1] - hole.center[1],
                     candidate.center[2] - hole.center[2]};
        if (std::sqrt(dot(v, v)) < min_center_distance) return false;
    }
    return true;
}

bool DrainabilityModel::absorbing(const DrainHole& hole, const Vec3& gravity) const {
    return dot(hole.axis, gravity) > sin_repose_;
}

bool DrainabilityModel::above_cone(const DrainHole& hole, const Vec3& point, const Vec3& gravity) const {
    const Vec3 v{point[0] - hole.center[0], point[1] - hole.center[1], point[2] - hole.center[2]};
    const double height = -dot(v, gravity);
    const double across = std::sqrt(std::max(0.0, dot(v, v) - height * height));
    const double mouth = 0.5 * hole.diameter;
    if (across <= mouth && height >= -mouth) return true;
    return height >= tan_repose_ * across;
}

template <class Visit>
void DrainabilityModel::for_each_captured(const DrainHole& hole, const OrientationFlow& flow,
                                          const std::vector<std::vector<uint32_t>>& members, Visit visit) const {
    if (!absorbing(hole, flow.gravity)) return;
    const int32_t region = flow.region[flow.main_destination[hole.patch]];
    if (region < 0) return;
    for (uint32_t j : members[size_t(region)])
        if (above_cone(hole, patches_.site[j], flow.gravity)) visit(j);
}

template <class Visit>
void DrainabilityModel::for_each_first_turn_sample(const DrainHole& hole, Visit visit) const {
    if (!absorbing(hole, first_.gravity)) return;
    const int32_t region = first_.region[first_.main_destination[hole.patch]];
    if (region < 0) return;
    for (uint32_t s : first_region_samples_[size_t(region)])
        if (above_cone(hole, powder_.position[s], first_.gravity)) visit(s);
}

std::vector<std::vector<char>> DrainabilityModel::captured_turn_patches(const std::vector<DrainHole>& holes) const {
    std::vector<std::vector<char>> captured(turns_.size(), std::vector<char>(patches_.size(), 0));
    for (size_t k = 0; k < turns_.size(); ++k)
        for (const DrainHole& hole : holes)
            for_each_captured(hole, turns_[k], turn_region_members_[k], [&](uint32_t j) { captured[k][j] = 1; });
    return captured;
}

DrainEvaluation DrainabilityModel::evaluate(const std::vector<DrainHole>& holes) const {
    const size_t n = patches_.size();
    DrainEvaluation result;
    result.total_volume = powder_.total_volume();
    result.drained_first.assign(powder_.position.size(), 0);
    for (const DrainHole& hole : holes)
        for_each_first_turn_sample(hole, [&](uint32_t s) { result.drained_first[s] = 1; });
    result.retained_mass.assign(n, 0.0);
    for (size_t s = 0; s < powder_.position.size(); ++s) {
        if (result.drained_first[s])
            result.drained_first_volume += powder_.sample_volume;
        else
            result.retained_mass[powder_.rest_patch[s]] += powder_.sample_volume;
    }

    Eigen::VectorXd leave;
    const SparseMatrix system = turn_system(turns_, chain_->matrix, options_.effort, captured_turn_patches(holes), &leave);
    const Eigen::VectorXd d = solve(system, options_.effort * leave);

    result.drainability.resize(n);
    result.residual_per_cavity.assign(patches_.cavity_count, 0.0);
    for (size_t j = 0; j < n; ++j) {
        result.drainability[j] = std::clamp(d[int(j)], 0.0, 1.0);
        const double stays = result.retained_mass[j] * (1.0 - result.drainability[j]);
        result.residual_per_cavity[patches_.cavity[j]] += stays;
        result.residual_volume += stays;
    }
    return result;
}

std::vector<double> DrainabilityModel::estimate_gains(const std::vector<DrainHole>& holes,
                                                      const DrainEvaluation& current,
                                                      const std::vector<DrainHole>& candidates) const {
    const size_t n = patches_.size();
    const std::vector<std::vector<char>> captured = captured_turn_patches(holes);
    const double weight = 1.0 / double(turns_.size());
    const double rho = options_.effort;

    // Expected discounted presence u = (I − ρQ)^-T m' of the retained powder.
    const SparseMatrix transposed = SparseMatrix(turn_system(turns_, chain_->matrix, options_.effort, captured, nullptr).transpose());
    Eigen::VectorXd retained(static_cast<Eigen::Index>(n));
    for (size_t j = 0; j < n; ++j) retained[int(j)] = current.retained_mass[j];
    const Eigen::VectorXd presence = solve(transposed, retained);

    // Powder arriving on each patch in a turn of each orientation, times its
    // chance of staying if not captured there.
    std::vector<std::vector<float>> arrival_value(turns_.size(), std::vector<float>(n, 0.0f));
    tbb::parallel_for(size_t(0), turns_.size(), [&](size_t k) {
        const StochasticMatrix& settle = turns_[k].settle;
        std::vector<double> arrival(n, 0.0);
        for (size_t i = 0; i < n; ++i)
            for (uint32_t e = settle.row_start[i]; e < settle.row_start[i + 1]; ++e)
                arrival[settle.column[e]] += rho * weight * presence[int(i)] * settle.weight[e];
        for (size_t j = 0; j < n; ++j)
            arrival_value[k][j] = captured[k][j] ? 0.0f : float(arrival[j] * (1.0 - current.drainability[j]));
    });

    std::vector<double> gains(candidates.size(), 0.0);
    tbb::parallel_for(size_t(0), candidates.size(), [&](size_t c) {
        double gain = 0.0;
        for_each_first_turn_sample(candidates[c], [&](uint32_t s) {
            if (!current.drained_first[s])
                gain += powder_.sample_volume * (1.0 - current.drainability[powder_.rest_patch[s]]);
        });
        for (size_t k = 0; k < turns_.size(); ++k)
            for_each_captured(candidates[c], turns_[k], turn_region_members_[k],
                              [&](uint32_t j) { gain += arrival_value[k][j]; });
        gains[c] = gain;
    });
    return gains;
}

}  // namespace fabvdb::powder
