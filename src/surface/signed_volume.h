//! Signed volume enclosed by triangles, by the divergence theorem (sum of the
//! tetrahedra each triangle spans with a fixed reference point). Positive for
//! a closed shell whose triangles face outwards, negative for one facing
//! inwards; for an open shell the figure depends on the reference point and
//! means nothing. Pure functions.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/mesh.h"

namespace fabvdb::surface {

//! Signed volume of every component: `triangle_component[t]` is the
//! component (< component_count) of triangle t (see triangle_components()).
std::vector<double> component_signed_volumes(const Mesh& mesh, const std::vector<uint32_t>& triangle_component,
                                             size_t component_count);

}  // namespace fabvdb::surface
