//! The drainability model of DESIGN.md (powder/): given the settle matrices of
//! the turn orientations, the first (printing) orientation's flow and the
//! dropped powder, it evaluates a set of drain holes.
//!
//! - A hole is absorbing for gravity g when its axis is within 90° − θ_r of g
//!   (powder slides down the tunnel). It then drains the powder resting on the
//!   floor region its own powder reaches, wherever that powder lies above the
//!   hole's cone of repose (a crater of slope θ_r around the hole) or in its
//!   mouth.
//! - First turn (the part as printed, full of powder): each powder sample is
//!   tested against the cones, so the crater left around a hole is a volume.
//! - Later turns: the operator turns the part with probability ρ (finite
//!   effort) to an orientation of the set (equal weights); powder moves by
//!   S(g) and leaves where it settles on a captured patch. Drainability
//!   d = ρ(r + Q d) per patch, one sparse solve (BiCGSTAB).
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
    //! samples and later-turn arrivals, each times its chance (1 − d) of
    //! staying otherwise. Parallel over candidates.
    std::vector<double> estimate_gains(const std::vector<DrainHole>& holes, const DrainEvaluation& current,
                                       const std::vector<DrainHole>& candidates) const;

    //! Whether `hole` drains powder resting on `point` for gravity `gravity`
    //! (point above the hole's cone of repose, or in its mouth).
    bool above_cone(const DrainHole& hole, const Vec3& point, const Vec3& gravity) const;
    bool absorbing(const DrainHole& hole, const Vec3& gravity) const;

private:
    //! Captured patches (0/1) per turn orientation, and per sample for the first turn.
    std::vector<std::vector<char>> captured_turn_patches(const std::vector<DrainHole>& holes) const;
    template <class Visit>
    void for_each_captured(const DrainHole& hole, const OrientationFlow& flow,
                           const std::vector<std::vector<uint32_t>>& members, Visit visit) const;
    template <class Visit>
    void for_each_first_turn_sample(const DrainHole& hole, Visit visit) const;

    const CavityPatches& patches_;
    const std::vector<OrientationFlow>& turns_;
    const OrientationFlow& first_;
    const PowderSamples& powder_;
    DrainabilityOptions options_;
    double tan_repose_ = 0.0, sin_repose_ = 0.0;
    //! Patches of each floor region, per turn orientation and for the first.
    std::vector<std::vector<std::vector<uint32_t>>> turn_region_members_;
    std::vector<std::vector<uint32_t>> first_region_members_;
    //! Powder samples per first-orientation floor region.
    std::vector<std::vector<uint32_t>> first_region_samples_;
    //! Σ_g w_g S(g), the turn chain without holes (Eigen, defined in the .cpp).
    struct TurnChain;
    std::shared_ptr<const TurnChain> chain_;
};

}  // namespace fabvdb::powder
