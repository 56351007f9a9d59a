//! The drainability model (see drainability_model.h).
#include "powder/drainability_model.h"

#include <algorithm>
#include <cmath>

#include <Eigen/SparseCore>
#include <tbb/blocked_range.h>
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

//! When ranking candidates (exact evaluations use everything): wet patches
//! probed per basin, and first-turn powder samples per basin.
constexpr size_t kGainProbes = 12;
constexpr size_t kGainSamples = 4096;
//! Chain moves lighter than this share of a patch's powder are dropped (kept in place).
constexpr double kChainPrune = 2e-3;

//! y = matrix · x, rows in parallel.
Eigen::VectorXd multiply(const SparseMatrix& matrix, const Eigen::VectorXd& x) {
    Eigen::VectorXd y(matrix.rows());
    const int* outer = matrix.outerIndexPtr();
    const int* inner = matrix.innerIndexPtr();
    const double* value = matrix.valuePtr();
    tbb::parallel_for(tbb::blocked_range<Eigen::Index>(0, matrix.rows(), 256),
                      [&](const tbb::blocked_range<Eigen::Index>& rows) {
                          for (Eigen::Index i = rows.begin(); i < rows.end(); ++i) {
                              double sum = 0.0;
                              for (int e = outer[i]; e < outer[i + 1]; ++e) sum += value[e] * x[inner[e]];
                              y[i] = sum;
                          }
                      });
    return y;
}

//! Solves (base + effort · captured) x = rhs by BiCGSTAB with a Jacobi
//! preconditioner, applying the two parts one after the other so the system
//! is never assembled (the base is the large, fixed part). For the transposed
//! system pass the transposes.
Eigen::VectorXd solve(const SparseMatrix& base, const SparseMatrix& captured, double effort,
                      const Eigen::VectorXd& rhs) {
    auto apply = [&](const Eigen::VectorXd& x) -> Eigen::VectorXd {
        return multiply(base, x) + effort * (captured * x);
    };
    const Eigen::VectorXd inverse_diagonal = (base.diagonal() + effort * captured.diagonal()).cwiseInverse();
    const double tolerance = 1e-7 * rhs.norm();
    Eigen::VectorXd x = inverse_diagonal.cwiseProduct(rhs);
    Eigen::VectorXd r = rhs - apply(x);
    const Eigen::VectorXd shadow = r;
    Eigen::VectorXd p = Eigen::VectorXd::Zero(rhs.size()), v = p;
    double rho = 1.0, alpha = 1.0, omega = 1.0;
    for (int iteration = 0; iteration < 1000 && r.norm() > tolerance; ++iteration) {
        const double rho_next = shadow.dot(r);
        if (rho_next == 0.0) break;
        const double beta = (rho_next / rho) * (alpha / omega);
        rho = rho_next;
        p = r + beta * (p - omega * v);
        const Eigen::VectorXd y = inverse_diagonal.cwiseProduct(p);
        v = apply(y);
        alpha = rho / shadow.dot(v);
        const Eigen::VectorXd s = r - alpha * v;
        const Eigen::VectorXd z = inverse_diagonal.cwiseProduct(s);
        const Eigen::VectorXd t = apply(z);
        const double tt = t.dot(t);
        omega = tt > 0.0 ? t.dot(s) / tt : 0.0;
        x += alpha * y + omega * z;
        r = s - omega * t;
        if (omega == 0.0) break;
    }
    if (!(r.norm() <= 1e-5 * rhs.norm()))
        throw Error(FABVDB_ERR_INTERNAL, "the drainability system did not converge");
    return x;
}

}  // namespace

struct DrainabilityModel::TurnChain {
    SparseMatrix base;  //!< I − ρ Σ_g w_g S(g): the chain without holes
    SparseMatrix base_transposed;
};

namespace {

//! Σ_g w_g S(g) diag(capture_g), the part of the chain that leaves through
//! the holes (the system is base + ρ · this); `leave` (if not null) receives
//! its row sums r.
SparseMatrix captured_part(const std::vector<OrientationFlow>& turns, size_t n,
                           const std::vector<std::vector<float>>& capture, Eigen::VectorXd* leave) {
    const double weight = 1.0 / double(turns.size());
    if (leave) *leave = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(n));
    std::vector<Eigen::Triplet<double>> removed;
    for (size_t k = 0; k < turns.size(); ++k) {
        const StochasticMatrix& settle = turns[k].settle;
        for (size_t i = 0; i < n; ++i)
            for (uint32_t e = settle.row_start[i]; e < settle.row_start[i + 1]; ++e) {
                const float fraction = capture[k][settle.column[e]];
                if (fraction <= 0.0f) continue;
                const double w = weight * settle.weight[e] * fraction;
                if (leave) (*leave)[int(i)] += w;
                removed.emplace_back(int(i), int(settle.column[e]), w);
            }
    }
    SparseMatrix part(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
    part.setFromTriplets(removed.begin(), removed.end());
    return part;
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
    for (const OrientationFlow& flow : turns) {
        turn_region_members_.push_back(region_members(flow));
        std::vector<Basin> basins(turn_region_members_.back().size());
        std::vector<std::vector<std::pair<double, uint32_t>>> sorted(basins.size());
        for (uint32_t j = 0; j < patches.size(); ++j) {
            const int32_t region = flow.region[flow.main_destination[j]];
            const double up = -dot(patches.normal[j], flow.gravity);
            if (region >= 0 && up > 0.0) sorted[size_t(region)].push_back({-dot(patches.site[j], flow.gravity), j});
        }
        for (size_t r = 0; r < basins.size(); ++r) {
            std::sort(sorted[r].begin(), sorted[r].end());
            for (const auto& [height, j] : sorted[r]) {
                basins[r].patch.push_back(j);
                basins[r].height.push_back(height);
                basins[r].horizontal_area.push_back(patches.area[j] * -dot(patches.normal[j], flow.gravity));
            }
        }
        turn_basins_.push_back(std::move(basins));
    }
    first_region_samples_.resize(region_members(first).size());
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
    SparseMatrix averaged(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
    averaged.setFromTriplets(entries.begin(), entries.end());
    // Moves of less than kChainPrune of a patch's powder stay put instead:
    // the chain keeps a fraction of its entries, and the solves speed up as much.
    entries.clear();
    for (Eigen::Index i = 0; i < averaged.outerSize(); ++i) {
        double stays = 1.0;
        for (SparseMatrix::InnerIterator entry(averaged, i); entry; ++entry)
            if (entry.value() >= kChainPrune && entry.col() != i) {
                entries.emplace_back(int(i), int(entry.col()), -options.effort * entry.value());
                stays -= entry.value();
            }
        entries.emplace_back(int(i), int(i), 1.0 - options.effort * std::max(0.0, stays));
    }
    auto chain = std::make_shared<TurnChain>();
    chain->base.resize(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
    chain->base.setFromTriplets(entries.begin(), entries.end());
    chain->base_transposed = chain->base.transpose();
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

double DrainabilityModel::cone_height(const DrainHole& hole, const Vec3& point, const Vec3& gravity) const {
    // The crater's cone of repose rises from the rim of the mouth, not its centre.
    const Vec3 v{point[0] - hole.center[0], point[1] - hole.center[1], point[2] - hole.center[2]};
    const double height = -dot(v, gravity);
    const double across = std::sqrt(std::max(0.0, dot(v, v) - height * height));
    const double mouth = 0.5 * hole.diameter;
    const double hole_height = -dot(hole.center, gravity);
    return across <= mouth ? hole_height - mouth : hole_height + tan_repose_ * (across - mouth);
}

bool DrainabilityModel::above_cone(const DrainHole& hole, const Vec3& point, const Vec3& gravity) const {
    return -dot(point, gravity) >= cone_height(hole, point, gravity);
}

int32_t DrainabilityModel::drained_basin(const DrainHole& hole, const OrientationFlow& flow) const {
    if (!absorbing(hole, flow.gravity)) return -1;
    return flow.region[flow.main_destination[hole.patch]];
}

template <class Visit>
void DrainabilityModel::for_each_first_turn_sample(const DrainHole& hole, Visit visit) const {
    const int32_t region = drained_basin(hole, first_);
    if (region < 0) return;
    for (uint32_t s : first_region_samples_[size_t(region)])
        if (above_cone(hole, powder_.position[s], first_.gravity)) visit(s);
}

std::vector<std::vector<double>> DrainabilityModel::pool_volumes(const std::vector<double>& retained_mass) const {
    std::vector<std::vector<double>> pools(turns_.size());
    tbb::parallel_for(size_t(0), turns_.size(), [&](size_t k) {
        const OrientationFlow& flow = turns_[k];
        pools[k].assign(turn_basins_[k].size(), 0.0);
        for (size_t i = 0; i < retained_mass.size(); ++i) {
            if (retained_mass[i] <= 0.0) continue;
            for (uint32_t e = flow.settle.row_start[i]; e < flow.settle.row_start[i + 1]; ++e) {
                const int32_t region = flow.region[flow.settle.column[e]];
                if (region >= 0) pools[k][size_t(region)] += retained_mass[i] * flow.settle.weight[e];
            }
        }
    });
    return pools;
}

double DrainabilityModel::pool_drain_fraction(size_t turn, size_t basin_index, double volume,
                                              const std::vector<const DrainHole*>& holes, size_t max_probes) const {
    const Basin& basin = turn_basins_[turn][basin_index];
    const size_t count = basin.patch.size();
    if (count == 0 || holes.empty()) return 0.0;
    // A pool too small to measure is a film on the lowest patch.
    volume = std::max(volume, 1e-3 * powder_.sample_volume);
    // The level: the pool fills the height field from its lowest patch up.
    double level = basin.height[0], below_area = 0.0, held = 0.0;
    size_t wet = 0;
    while (true) {
        below_area += basin.horizontal_area[wet];
        ++wet;
        const double next = wet < count ? basin.height[wet] : HUGE_VAL;
        const double room = below_area > 0.0 ? below_area * (next - level) : 0.0;
        if (held + room >= volume || wet == count) {
            level += below_area > 0.0 ? (volume - held) / below_area : 0.0;
            break;
        }
        held += room;
        level = next;
    }
    // What the cones keep: per wet patch, the pool up to the lowest cone
    // (every `stride`-th wet patch, standing for its neighbours in height).
    const Vec3& gravity = turns_[turn].gravity;
    const size_t stride = max_probes > 0 ? (wet + max_probes - 1) / max_probes : 1;
    double kept = 0.0, probed_depth = 0.0;
    for (size_t w = 0; w < wet; w += stride) {
        double top = level;
        for (const DrainHole* hole : holes)
            top = std::min(top, cone_height(*hole, patches_.site[basin.patch[w]], gravity));
        kept += basin.horizontal_area[w] * std::max(0.0, top - basin.height[w]);
        probed_depth += basin.horizontal_area[w] * (level - basin.height[w]);
    }
    return probed_depth > 0.0 ? std::clamp(1.0 - kept / probed_depth, 0.0, 1.0) : 0.0;
}

std::vector<std::vector<float>> DrainabilityModel::turn_capture(
    const std::vector<DrainHole>& holes, const std::vector<std::vector<double>>& pools) const {
    std::vector<std::vector<float>> capture(turns_.size(), std::vector<float>(patches_.size(), 0.0f));
    tbb::parallel_for(size_t(0), turns_.size(), [&](size_t k) {
        std::vector<std::pair<int32_t, const DrainHole*>> drained;
        for (const DrainHole& hole : holes) {
            const int32_t basin = drained_basin(hole, turns_[k]);
            if (basin >= 0) drained.push_back({basin, &hole});
        }
        std::sort(drained.begin(), drained.end());
        for (size_t a = 0; a < drained.size();) {
            size_t b = a;
            std::vector<const DrainHole*> together;
            while (b < drained.size() && drained[b].first == drained[a].first) together.push_back(drained[b++].second);
            const size_t basin = size_t(drained[a].first);
            const float fraction = float(pool_drain_fraction(k, basin, pools[k][basin], together, 0));
            for (uint32_t j : turn_region_members_[k][basin]) capture[k][j] = fraction;
            a = b;
        }
    });
    return capture;
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
    const SparseMatrix captured =
        captured_part(turns_, n, turn_capture(holes, pool_volumes(result.retained_mass)), &leave);
    const Eigen::VectorXd d = solve(chain_->base, captured, options_.effort, options_.effort * leave);

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
    const std::vector<std::vector<double>> pools = pool_volumes(current.retained_mass);
    const std::vector<std::vector<float>> capture = turn_capture(holes, pools);
    const double weight = 1.0 / double(turns_.size());
    const double rho = options_.effort;

    // Expected discounted presence u = (I − ρQ)^-T m' of the retained powder.
    Eigen::VectorXd retained(static_cast<Eigen::Index>(n));
    for (size_t j = 0; j < n; ++j) retained[int(j)] = current.retained_mass[j];
    const Eigen::VectorXd presence =
        solve(chain_->base_transposed, SparseMatrix(captured_part(turns_, n, capture, nullptr).transpose()),
              options_.effort, retained);

    // Per turn orientation and basin: the powder arriving there in a turn
    // times its chance of staying otherwise, and the holes draining it.
    std::vector<std::vector<double>> arrival_value(turns_.size());
    std::vector<std::vector<std::vector<const DrainHole*>>> basin_holes(turns_.size());
    tbb::parallel_for(size_t(0), turns_.size(), [&](size_t k) {
        const OrientationFlow& flow = turns_[k];
        arrival_value[k].assign(turn_basins_[k].size(), 0.0);
        basin_holes[k].resize(turn_basins_[k].size());
        for (size_t i = 0; i < n; ++i)
            for (uint32_t e = flow.settle.row_start[i]; e < flow.settle.row_start[i + 1]; ++e) {
                const uint32_t j = flow.settle.column[e];
                if (flow.region[j] < 0) continue;
                arrival_value[k][size_t(flow.region[j])] +=
                    rho * weight * presence[int(i)] * flow.settle.weight[e] * (1.0 - current.drainability[j]);
            }
        for (const DrainHole& hole : holes) {
            const int32_t basin = drained_basin(hole, flow);
            if (basin >= 0) basin_holes[k][size_t(basin)].push_back(&hole);
        }
    });

    // First-turn powder still in the part, per basin of the printing
    // orientation: at most kGainSamples samples each, standing for the rest.
    std::vector<std::vector<uint32_t>> undrained(first_region_samples_.size());
    std::vector<double> undrained_weight(first_region_samples_.size(), 0.0);
    for (size_t region = 0; region < first_region_samples_.size(); ++region) {
        std::vector<uint32_t> all;
        for (uint32_t s : first_region_samples_[region])
            if (!current.drained_first[s]) all.push_back(s);
        const size_t stride = (all.size() + kGainSamples - 1) / kGainSamples;
        for (size_t e = 0; e < all.size(); e += std::max<size_t>(stride, 1)) undrained[region].push_back(all[e]);
        undrained_weight[region] = powder_.sample_volume * double(std::max<size_t>(stride, 1));
    }

    std::vector<double> gains(candidates.size(), 0.0);
    tbb::parallel_for(size_t(0), candidates.size(), [&](size_t c) {
        double gain = 0.0;
        const int32_t first_basin = drained_basin(candidates[c], first_);
        if (first_basin >= 0)
            for (uint32_t s : undrained[size_t(first_basin)])
                if (above_cone(candidates[c], powder_.position[s], first_.gravity))
                    gain += undrained_weight[size_t(first_basin)] * (1.0 - current.drainability[powder_.rest_patch[s]]);
        for (size_t k = 0; k < turns_.size(); ++k) {
            const int32_t basin = drained_basin(candidates[c], turns_[k]);
            if (basin < 0 || arrival_value[k][size_t(basin)] <= 0.0) continue;
            std::vector<const DrainHole*> together = basin_holes[k][size_t(basin)];
            const double before =
                together.empty() ? 0.0 : capture[k][turn_region_members_[k][size_t(basin)].front()];
            together.push_back(&candidates[c]);
            const double after =
                pool_drain_fraction(k, size_t(basin), pools[k][size_t(basin)], together, kGainProbes);
            gain += std::max(0.0, after - before) * arrival_value[k][size_t(basin)];
        }
        gains[c] = gain;
    });
    return gains;
}

}  // namespace fabvdb::powder
