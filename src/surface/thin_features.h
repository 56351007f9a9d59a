//! Thin features of the mold decomposition (thesis §3.4.2): parts of S_low
//! where the solid is so thin that a shell of thickness ω would have touching
//! walls; they are cast solid and never cut. A triangle's local thickness is
//! twice the mean medial depth of its vertices (shape diameter from the
//! distance field). Candidate segments are the edge-connected triangles
//! thinner than 4ω; a segment is thin, as in the thesis, when its minimal
//! thickness is below 2ω and its mean thickness below 3ω.
#pragma once

#include <array>
#include <vector>

#include "core/mesh.h"

namespace fabvdb::surface {

//! Per triangle: the id of its thin segment (0, 1, ...), or −1.
//! `neighbor`: per triangle, the triangles across its three edges.
std::vector<int> thin_segments(const Mesh& outer, const std::vector<std::array<int, 3>>& neighbor,
                               const std::vector<double>& vertex_depth, double thickness);

}  // namespace fabvdb::surface
