//! The per-direction moldability terms of the thesis (§3.4.2, §3.4.5), computed
//! once for the 162 candidate parting directions: the overhang term U(t, d) of
//! an outer triangle, and for each of the 81 direction axes (d and −d project
//! alike) every pair of outer triangles whose projections along the axis
//! overlap with (n₁·d)(n₂·d) ≥ 0, with the overlap area |p_d(t₁) ∩ p_d(t₂)|.
//! Pairs are found with bounding-box early rejection on a 2-D grid and their
//! areas by convex clipping; axes are processed in parallel (TBB). After
//! boundary smoothing moves vertices, the pairs of the moved triangles are
//! measured again.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/icosphere.h"
#include "core/progress.h"
#include "surface/shell.h"

namespace fabvdb::surface {

struct MoldabilityTerms {
    SphereDirections directions;          //!< the 162 candidates
    std::vector<int> axis_of_direction;   //!< direction index -> axis index (81 axes)
    std::vector<Vec3> axes;               //!< one direction of each opposite pair
    //! Per axis, per outer triangle (CSR): the triangles its projection overlaps
    //! and the overlap areas in unit-cube units (each pair listed from both sides).
    struct Overlaps {
        std::vector<uint32_t> offset;
        std::vector<uint32_t> partner;
        std::vector<float> area;
        //! Shared projected areas up to this (in the projection's units
        //! squared: 1e-9 of the mean box size squared when measured) are
        //! not kept; an update of a few triangles keeps it.
        double negligible = 0;
    };
    std::vector<Overlaps> overlaps;
    size_t pair_count = 0;  //!< overlapping pairs summed over the axes
    double draft = 0;       //!< draft angle φ in radians

    const Overlaps& overlaps_along(int direction) const { return overlaps[axis_of_direction[direction]]; }
};

//! Throws Error(CANCELLED) via `progress`.
MoldabilityTerms compute_moldability_terms(const Shell& shell, double draft_radians, Progress& progress);

//! Measures again, along the given axes (indices into terms.axes), the
//! overlaps of the `changed` triangles (after their vertices moved); the
//! other pairs are kept. Axes in parallel. A few changed triangles (an
//! edit's, a smoothing step's) cost O(N) cheap tests per axis (bounding
//! spheres against the changed ones' cylinder along the axis) and a shift
//! of the axis' lists in place, not a pass over all pairs.
void update_moldability_terms(const Shell& shell, const std::vector<uint32_t>& changed, const std::vector<int>& axes,
                              MoldabilityTerms& terms);

//! |p_d(a) ∩ p_d(b)| along `axis` for two triangles given by their corners
//! (in the corners' units squared).
double projected_overlap(const std::array<Vec3, 3>& a, const std::array<Vec3, 3>& b, const Vec3& axis);

//! U(t, d) of the thesis for a visible triangle of unit normal n and area `area`:
//! −cos(min(θ + φ, π))·|p_d(t)| when θ = ∠(n, d) > π/2 − φ, else 0.
double overhang_term(const Vec3& n, double area, const Vec3& d, double draft);

}  // namespace fabvdb::surface
