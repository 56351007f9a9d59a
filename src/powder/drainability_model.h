//! The drainability model of DESIGN.md (powder/): given the flows of the
//! turn orientations, the first (printing) orientation's flow and the
//! dropped powder, it evaluates sets of drain holes. It holds what every
//! evaluation shares — the samples per turn (turn_samples.h) and the
//! prediction's random routines — and composes the operations:
//! - what a hole drains alone (hole_reach.h), and whether its tunnel passes
//!   powder (hole_tunnel.h);
//! - what a hole set drains and the hole search's objective on it
//!   (hole_set_drain.h, pile_residual.h);
//! - the prediction reported to the user (drain_prediction.h), its cleaning
//!   routine (best_cleaning_routine.h) and heat maps (drain_heat_map.h).
//! The routine: as printed, then round(ρ / (1 − ρ)) turns to orientations
//! of the set. Takes references to the flows and samples (they must outlive
//! it); costs one sublevel forest per turn to build. A class because the
//! hole search evaluates many hole sets on the same flows. The derivation
//! and the alternatives measured and rejected are in
//! docs/design/drainability.md.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "core/mesh.h"
#include "powder/cavity_patches.h"
#include "powder/drain_hole.h"
#include "powder/drain_prediction.h"
#include "powder/hole_reach.h"
#include "powder/hole_set_drain.h"
#include "powder/orientation_flows.h"
#include "powder/powder_drop.h"
#include "powder/turn_samples.h"

namespace fabvdb::powder {

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
    using Crater = powder::Crater;
    using Reach = HoleReach;
    using Drain = HoleSetDrain;
    using Routine = powder::Routine;

    //! Keeps references to all arguments: they must outlive the model.
    DrainabilityModel(const CavityPatches& patches, const std::vector<OrientationFlow>& turns,
                      const OrientationFlow& first, const PowderSamples& powder, const DrainabilityOptions& options);

    //! The prediction's residual and the heat map (the per-patch shares and powder).
    DrainEvaluation evaluate(const std::vector<DrainHole>& holes) const;
    //! What one hole drains alone (hole_reach.h).
    Reach reach(const DrainHole& hole, Crater crater = Crater::surface) const;
    //! What a hole set drains, turn by turn (for incremental evaluation).
    Drain drain(const std::vector<DrainHole>& holes, Crater crater = Crater::surface) const;
    //! The same from the holes' reaches (`reaches[h]` is `holes[h]`'s), so
    //! a search that has them does not walk again.
    Drain drain(const std::vector<DrainHole>& holes, const std::vector<std::shared_ptr<const Reach>>& reaches) const;
    //! The search's objective (mm³) for `drain`'s holes plus the hole of
    //! `extra`, without changing `drain`. Thread-safe.
    double residual_with(const Drain& drain, const Reach& extra) const;
    //! evaluate(holes) from what the holes drain by the surface of repose
    //! (drain(holes, Crater::surface), or the same from their reaches).
    DrainEvaluation evaluate(const Drain& drained) const;
    //! The same for the given routines of later turns, each with equal weight.
    DrainEvaluation evaluate(const Drain& drained, const std::vector<Routine>& routines) const;
    //! evaluate(drained).residual_volume alone (mm³), without the heat map.
    double predicted_residual(const Drain& drained) const;
    //! The prediction's residual (mm³) for one routine of later turns.
    double routine_residual(const Drain& drained, const Routine& routine) const;
    //! The prediction's residual (mm³) for each of its random routines.
    std::vector<double> random_routine_residuals(const Drain& drained) const;
    //! The cleaning routine of `length` later turns (best_cleaning_routine.h),
    //! starting from the prediction's random routines; polls `progress`.
    Routine best_routine(const Drain& drained, int length, const Progress& progress) const;
    //! The later turns of the prediction's routines (round(ρ / (1 − ρ))).
    int later_turns() const { return later_turns_; }
    //! Gravity of turn `k` of the orientation set.
    const Vec3& turn_gravity(uint32_t k) const { return samples_.later_gravity[k]; }
    double total_volume() const;

    //! Whether powder can leave through the hole's tunnel for `gravity` (hole_tunnel.h).
    bool absorbing(const DrainHole& hole, const Vec3& gravity) const;

private:
    const CavityPatches& patches_;
    const PowderSamples& powder_;
    DrainabilityOptions options_;
    int later_turns_ = 9;
    TurnSamples samples_;
    //! The prediction's routines: the turn indices of each.
    std::vector<Routine> routines_;
    //! Per patch: the patch whose share it takes when no powder rests on it
    //! (the patch its nearest later-turn sample rests on; itself if none).
    std::vector<uint32_t> stand_in_;
};

}  // namespace fabvdb::powder
