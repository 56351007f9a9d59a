//! The drainability model of DESIGN.md (powder/): given the flows of the
//! turn orientations, the first (printing) orientation's flow and the
//! dropped powder, it evaluates a set of drain holes.
//!
//! - What drains: as printed, powder above each open hole's cone of repose;
//!   in the later turns, powder above the surface of repose rising from the
//!   crater through the cavity (never below a floor, plugged where it fills
//!   a passage). Powder must reach the mouth without climbing
//!   (sublevel_forest.h).
//! - The routine: as printed, then round(ρ / (1 − ρ)) turns to orientations
//!   of the set. The prediction (evaluate) keeps the powder in place between
//!   turns save what drains, refilling crater rims; mean of 64 routines
//!   drawn with a fixed seed.
//! - The hole search's objective (drain, residual_with) gathers the powder
//!   into one pile per cavity instead, so adding a hole is cheap to
//!   evaluate: a turn maps the pile's share x to F_g(x) ≤ x, and the
//!   expected residual share after T random turns is computed on a grid of
//!   pile shares.
//! - The heat map comes from the prediction too: per patch, the share of the
//!   powder resting on it at the start that has left at the end, and the
//!   powder left on it.
//! Takes references to the flows and samples (they must outlive it); costs
//! one sublevel forest per turn to build. The as-printed turn uses every
//! powder sample, later turns a uniform subsample of about 2500. A class
//! because the hole search evaluates many hole sets on the same flows. The
//! derivation and the alternatives measured and rejected are in
//! docs/design/drainability.md.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/mesh.h"
#include "powder/cavity_patches.h"
#include "powder/orientation_flows.h"
#include "powder/powder_drop.h"
#include "powder/sample_grid.h"
#include "powder/sublevel_forest.h"

namespace fabvdb::powder {

struct DrainHole {
    uint32_t patch = 0;  //!< the patch the hole opens on
    Vec3 center{0, 0, 0};  //!< on the cavity surface
    Vec3 axis{0, 0, 1};    //!< unit, from the cavity out through the wall
    double diameter = 4.0;
    double depth = 0.0;    //!< drilled length from `center` along `axis` (through the wall and beyond)
    double through = 0.0;  //!< tunnel length from `center` along `axis` to the outer surface
    uint32_t cavity = 0;
};

//! Whether `candidate`'s centre is at least `min_center_distance` from every hole's.
bool spaced_from(const DrainHole& candidate, const std::vector<DrainHole>& holes, double min_center_distance);

struct DrainabilityOptions {
    double repose_radians = 0.6108652381980153;  // 35°
    double effort = 0.9;                          // ρ
};

struct DrainEvaluation {
    //! Per patch: the share of the powder resting on it at the start that
    //! has left at the end (negative where a crater's rim fills up; a patch
    //! no powder rests on takes its nearest sample's patch's share), and
    //! the powder resting on it at the start and left on it at the end (mm³).
    std::vector<double> drained_share;
    std::vector<double> initial_per_patch, left_per_patch;
    std::vector<double> residual_per_cavity;  //!< mm³
    double drained_first_volume = 0.0;
    double residual_volume = 0.0;
    double total_volume = 0.0;
    double residual_fraction() const { return total_volume > 0 ? residual_volume / total_volume : 0.0; }
};

class DrainabilityModel {
public:
    //! Keeps references to all arguments: they must outlive the model.
    DrainabilityModel(const CavityPatches& patches, const std::vector<OrientationFlow>& turns,
                      const OrientationFlow& first, const PowderSamples& powder, const DrainabilityOptions& options);
    ~DrainabilityModel();

    //! The residual and the heat map (the per-patch shares and powder).
    DrainEvaluation evaluate(const std::vector<DrainHole>& holes) const;

    //! What drains in the later turns: powder above the surface of repose
    //! (the prediction), or above the crater's cone (more, and far cheaper
    //! to find: the hole search's objective).
    enum class Crater { surface, cone };
    //! What one hole drains alone: bits over its cavity's first-turn
    //! samples, and per turn over its cavity's later-turn samples, lowest
    //! first (each empty where it drains nothing).
    struct Reach {
        uint32_t cavity = 0;
        std::vector<uint64_t> first;
        std::vector<std::vector<uint64_t>> later;
        //! Per turn, the same bits of the samples its surface of repose
        //! reaches and buries (the crater's rim), by Crater::surface only.
        std::vector<std::vector<uint64_t>> later_rim;
    };
    Reach reach(const DrainHole& hole, Crater crater = Crater::surface) const;
    //! What a hole set drains, turn by turn (for incremental evaluation).
    struct Drain {
        std::vector<DrainHole> holes;
        //! Per cavity: bits of the first-turn samples drained, lowest first.
        std::vector<std::vector<uint64_t>> first;
        //! Per turn and cavity: bits of the drained samples, lowest first
        //! (empty: none), and the set bits before each word.
        std::vector<std::vector<std::vector<uint64_t>>> later;
        std::vector<std::vector<std::vector<uint32_t>>> later_before;
        //! What each hole drains alone (`holes[h]`'s is `reaches[h]`), shared
        //! with whoever computed it.
        std::vector<std::shared_ptr<const Reach>> reaches;
        std::vector<uint32_t> retained_first;  //!< per cavity: samples left after the first turn
        std::vector<double> residual_per_cavity;  //!< mm³
        double drained_first_volume = 0.0;
    };
    Drain drain(const std::vector<DrainHole>& holes, Crater crater = Crater::surface) const;
    //! The same from the holes' reaches (`reaches[h]` is `holes[h]`'s), so
    //! a search that has them does not walk again.
    Drain drain(const std::vector<DrainHole>& holes, const std::vector<std::shared_ptr<const Reach>>& reaches) const;
    //! Residual volume (mm³) of `drain`'s holes plus the hole of `extra`,
    //! without changing `drain`. Thread-safe.
    double residual_with(const Drain& drain, const Reach& extra) const;
    //! evaluate(holes) from what the holes drain by the surface of repose
    //! (drain(holes, Crater::surface), or the same from their reaches).
    DrainEvaluation evaluate(const Drain& drained) const;
    //! The same for the given routines of later turns (turn indices into the
    //! orientation set), each with equal weight.
    using Routine = std::vector<uint32_t>;
    DrainEvaluation evaluate(const Drain& drained, const std::vector<Routine>& routines) const;
    //! evaluate(drained).residual_volume alone (mm³), without the heat map.
    double predicted_residual(const Drain& drained) const;
    //! The prediction's residual (mm³) for one routine of later turns.
    double routine_residual(const Drain& drained, const Routine& routine) const;
    //! The prediction's residual (mm³) for each of its random routines.
    std::vector<double> random_routine_residuals(const Drain& drained) const;
    //! A cleaning routine of `length` later turns that leaves little powder
    //! by the prediction: the turns chosen one after the other, each the
    //! one that leaves the least after it, or the best of the prediction's
    //! random routines if that leaves less (so never more than their mean),
    //! then each turn in turn changed to the best one while that leaves
    //! less (two passes). Among turns within a millionth of the cavity of
    //! the least, the one with the smallest tilt from the previous gravity.
    //! Costs about 162 × length² turns of the prediction.
    Routine best_routine(const Drain& drained, int length) const;
    //! The later turns of the prediction's routines (round(ρ / (1 − ρ))).
    int later_turns() const { return later_turns_; }
    //! Gravity of turn `k` of the orientation set.
    const Vec3& turn_gravity(uint32_t k) const { return turns_[k].gravity; }
    double total_volume() const;

    //! Whether powder can leave through the hole's tunnel for `gravity`.
    bool absorbing(const DrainHole& hole, const Vec3& gravity) const;

private:
    //! The cone of repose a hole leaves for one gravity: rising with slope
    //! θ_r from the rim of the mouth (a steep tunnel; in its mouth powder
    //! drains down to one radius below the centre) or from the outer lip.
    struct Cone {
        Vec3 apex{0, 0, 0}, gravity{0, 0, -1};
        double mouth = 0.0, tan_repose = 0.0;
        //! Whether powder at `point` stays (under the cone).
        bool below(const Vec3& point) const;
    };
    Cone cone(const DrainHole& hole, const Vec3& gravity) const;
    //! Whether the tunnel is steeper than the angle of repose for `gravity`.
    bool steep(const DrainHole& hole, const Vec3& gravity) const;
    //! The lowest point of the hole's outer mouth for `gravity`.
    Vec3 outer_lip(const DrainHole& hole, const Vec3& gravity) const;
    //! The later-turn samples for one gravity: height along −gravity, and
    //! the height of the floor each rests on: halfway to the lowest empty
    //! cell around it down the way (a step with a part along gravity that
    //! holds no sample), −∞ if none.
    struct Relief {
        std::vector<float> height, floor;
    };
    Relief later_relief(const Vec3& gravity) const;
    //! A sublevel forest's ancestor chains as runs of samples of consecutive
    //! ranks within their cavity (lowest first), so that a walk up a chain
    //! reads its samples in order: the chain from sample a begins with the
    //! samples of ranks rank[a] to run_end[a] − 1 and goes on from
    //! after_run[a] (kNoSample: it ends there, at the root or where the
    //! chain would leave the cavity).
    struct Chains {
        std::vector<uint32_t> rank, run_end, after_run;
        //! Per cavity: the powder samples by rank.
        std::vector<std::vector<uint32_t>> by_rank;
    };
    Chains chains(const SampleGrid& grid, const SublevelForest& forest, const std::vector<uint32_t>& cavity) const;
    //! Bits (by rank in the hole's cavity) of the samples that drain through
    //! `hole` above its cone of repose: of the chain from `source` (the
    //! sample nearest the hole, kNoSample if none) for `gravity`. Empty if none.
    std::vector<uint64_t> above_cone(const DrainHole& hole, uint32_t source, const Chains& chains,
                                     const std::vector<uint32_t>& cavity, const Vec3& gravity) const;
    //! Calls `visit(sample)` for each sample that drains through `hole`
    //! above the surface of repose it leaves, of the later-turn grid for
    //! turn `turn` (`source`: the grid's sample nearest the hole).
    template <class Visit, class Under>
    void walk_above_surface(const DrainHole& hole, uint32_t source, size_t turn, Visit visit, Under under) const;
    //! Expected residual share of cavity `cavity` after the later turns from
    //! a pile share `start` after the first, with what `drain` (and `extra`,
    //! if not null) drains.
    double later_residual_share(uint32_t cavity, double start, const Drain& drain, const Reach* extra) const;
    //! One cavity's powder as the first turn leaves it for the later turns:
    //! its later-turn samples (powder samples, in the order later_local_
    //! indexes), 1 on each the first turn left, how many, the volume they
    //! stand for, and per turn the cavity's holes that drain anything,
    //! lowest first.
    struct Later {
        uint32_t cavity = 0;
        const std::vector<uint32_t>* samples = nullptr;
        std::vector<double> start;
        double count = 0.0, retained = 0.0;
        std::vector<std::vector<size_t>> open;
        //! The volume (mm³) `fill` stands for.
        double left(const std::vector<double>& fill) const;
    };
    Later later_powder(const Drain& drained, uint32_t cavity) const;
    //! One later turn `k` on `fill` (see the top: the powder keeps its place, save what drains).
    void later_turn(const Drain& drained, const Later& later, uint32_t k, std::vector<double>& fill) const;
    //! The prediction's expected residual (mm³) per cavity after the later
    //! turns of `routines` (the mean): the powder kept where it lies, save
    //! what drains (see the top). `left` (if not null) receives the mean
    //! powder left on each powder sample at the end (mm³; zero on samples
    //! the later turns skip); `per_routine` (if not null) each routine's
    //! residual summed over the cavities (mm³).
    std::vector<double> kept_in_place(const Drain& drained, const std::vector<Routine>& routines,
                                      std::vector<double>* left, std::vector<double>* per_routine) const;

    const CavityPatches& patches_;
    const std::vector<OrientationFlow>& turns_;
    const OrientationFlow& first_;
    const PowderSamples& powder_;
    DrainabilityOptions options_;
    double tan_repose_ = 0.0, sin_repose_ = 0.0;
    int later_turns_ = 9;
    SampleGrid first_grid_, later_grid_;
    //! Per later-turn sample: the samples of the 26 cells around it (see sample_links in the .cpp).
    std::vector<std::array<uint32_t, 26>> later_links_;
    std::vector<SublevelForest> later_forests_;
    Chains first_chains_;
    std::vector<Chains> later_chains_;
    std::vector<Relief> later_relief_;
    //! Per sample of each grid: its cavity. Per cavity: sample count of each grid.
    std::vector<uint32_t> first_cavity_, later_cavity_;
    std::vector<uint32_t> first_count_, later_count_;
    //! Per powder sample: its rank among its cavity's first-turn samples,
    //! and its place in its cavity's later-turn samples (kNoSample if none).
    std::vector<uint32_t> first_rank_, later_local_;
    //! The prediction's routines: the turn indices of each.
    std::vector<Routine> routines_;
    //! Per patch: the later-turn sample nearest its site (kNoSample if none).
    std::vector<uint32_t> patch_sample_;
};

}  // namespace fabvdb::powder
