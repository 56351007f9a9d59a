//! The inner ends of the atomic prisms of the mold decomposition (thesis
//! §3.4.2): each vertex of S_low is pushed into the solid along −∇φ of the
//! level set (re-evaluated at every step, so it follows the distance field)
//! until φ = −ω, or stops where φ stops decreasing (the medial axis) when the
//! solid is thinner than 2ω there. Also returns each vertex's medial depth
//! (the deepest −φ reached, capped at `max_depth`), whose double is the local
//! thickness used to find thin features. The level set's interior band must
//! reach `max_depth` (else depths are capped at the band).
#pragma once

#include <vector>

#include <openvdb/openvdb.h>

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::volume {

struct ShellPrisms {
    std::vector<Vec3> inner;    //!< f_V: one inner vertex per outer vertex
    std::vector<double> depth;  //!< medial depth per vertex, ≤ max_depth
};

ShellPrisms shell_prisms(const openvdb::FloatGrid& grid, const std::vector<Vec3>& outer_vertices, double thickness,
                         double max_depth, Progress& progress);

}  // namespace fabvdb::volume
