//! The drainability model of DESIGN.md (powder/): given the settle matrices of
//! the turn orientations, the first (printing) orientation's flow and the
//! dropped powder, it evaluates a set of drain holes.
//!
//! - A hole is absorbing for gravity g when its axis is within 90° − θ_r of g
//!   (powder slides down the tunnel). Powder above the hole's cone of repose
//!   (a crater of slope θ_r rising from the rim of its mouth) drains.
//! - First turn (the part as printed, full of powder): each powder sample is
//!   tested against the cones of the holes in the basin it settles in.
//! - Later turns: the operator turns the part with probability ρ (finite
//!   effort) to an orientation of the set (equal weights); powder moves by
//!   S(g) and gathers as a pool in the basin where it settles. The pool has a
//!   volume: it fills the basin (the up-facing patches draining into it, as
//!   a height field) to the level that holds the powder retained after the
//!   first turn, and the part of it above the cones of the basin's holes
//!   leaves. That fraction of the powder settling in the basin leaves; the
//!   rest stays for the next turn. Drainability d = ρ(r + Q d) per patch,
//!   one sparse solve (BiCGSTAB).
//! - Residual = cavity volume − first-turn drain − Σ retained mass · d.
//! A class because the hole search evaluates many hole sets on the same flows.
#pragma once

#include <cstdint>
#include <vector>

#include <memory>

#include "core/mesh.h"
#include "powder/cavity_patches.h"
#include "powder/orientation_flows.h"
#include "powder/powder_drop.h"

namespace fabvdb::powder {

struct DrainHole {
    uint32_t patch = 0;  //!< the patch the hole opens on
    Vec3 center{0, 0, 0};  //!< on the cavity surface
    Vec3 axis{0, 0, 1};    //!< unit, from the cavity out through the wall
    double diameter = 4.0;
    double depth = 0.0;    //!< drilled length from `center` along `axis` (through the wall and beyond)
    uint32_t cavity = 0;
};

//! Whether `candidate`'s centre is at least `min_center_distance` from every hole's.
bool spaced_from(const DrainHole& candidate, const std::vector<DrainHole>& holes, double min_center_distance);

struct DrainabilityOptions {
    double repose_radians = 0.6108652381980153;  // 35°
    double effort = 0.9;                          // ρ
};

struct DrainEvaluation {
    std::vector<double> drainability;  //!< per patch
    std::vector<char> drained_first;   //!< per powder sample
    std::vector<double> retained_mass; //!< per patch, after the first turn (mm³)
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

    DrainEvaluation evaluate(const std::vector<DrainHole>& holes) const;

    //! First-order gain in drained volume (mm³) of adding each candidate to
    //! `holes`, whose evaluation is `current`: newly captured first-turn
    //! samples, and per turn orientation the rise of the basin's leaving
    //! fraction times the powder arriving there, each times its chance
    //! (1 − d) of staying otherwise. Parallel over candidates.
    std::vector<double> estimate_gains(const std::vector<DrainHole>& holes, const DrainEvaluation& current,
                                       const std::vector<DrainHole>& candidates) const;

    //! Whether `hole` drains powder at `point` for gravity `gravity` (point
    //! above the hole's cone of repose, or in its mouth).
    bool above_cone(const DrainHole& hole, const Vec3& point, const Vec3& gravity) const;
    //! Height (along −gravity) of the hole's cone of repose above `point`'s spot.
    double cone_height(const DrainHole& hole, const Vec3& point, const Vec3& gravity) const;
    bool absorbing(const DrainHole& hole, const Vec3& gravity) const;

private:
    //! Up-facing patches draining into one basin (floor region) of one turn
    //! orientation, lowest first: the basin as a height field.
    struct Basin {
        std::vector<uint32_t> patch;
        std::vector<double> height, horizontal_area;
    };
    //! Pool volume per basin per turn orientation: the powder retained after
    //! the first turn, moved by S(g).
    std::vector<std::vector<double>> pool_volumes(const std::vector<double>& retained_mass) const;
    //! Fraction of a pool of `volume` in basin `basin` of turn `turn` that
    //! lies above the cone of at least one of `holes`, measured on every wet
    //! patch (max_probes 0) or on about `max_probes` of them spread in height.
    double pool_drain_fraction(size_t turn, size_t basin, double volume,
                               const std::vector<const DrainHole*>& holes, size_t max_probes) const;
    //! Leaving fraction per patch per turn orientation for a hole set.
    std::vector<std::vector<float>> turn_capture(const std::vector<DrainHole>& holes,
                                                 const std::vector<std::vector<double>>& pools) const;
    //! The basin of `flow` that `hole` drains, or −1 (not absorbing, or no basin).
    int32_t drained_basin(const DrainHole& hole, const OrientationFlow& flow) const;
    template <class Visit>
    void for_each_first_turn_sample(const DrainHole& hole, Visit visit) const;

    const CavityPatches& patches_;
    const std::vector<OrientationFlow>& turns_;
    const OrientationFlow& first_;
    const PowderSamples& powder_;
    DrainabilityOptions options_;
    double tan_repose_ = 0.0, sin_repose_ = 0.0;
    //! Patches of each floor region, per turn orientation.
    std::vector<std::vector<std::vector<uint32_t>>> turn_region_members_;
    std::vector<std::vector<Basin>> turn_basins_;
    //! Powder samples per first-orientation floor region.
    std::vector<std::vector<uint32_t>> first_region_samples_;
    //! I − ρ Σ_g w_g S(g), the turn chain without holes (Eigen, defined in the .cpp).
    struct TurnChain;
    std::shared_ptr<const TurnChain> chain_;
};

}  // namespace fabvdb::powder
