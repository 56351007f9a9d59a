//! Whether a triangle mesh already is the clean boundary of a solid, so that
//! hollowing may keep it as the outer surface instead of a voxelized copy:
//! a closed, oriented 2-manifold (closed_manifold.h), no degenerate triangle
//! (exact collinearity), no two triangles crossing (crossing_pairs.h, exact
//! predicates), and the shells oriented so that they bound a volume (outer
//! shells outward, voids inward: CGAL's test, and a positive total volume).
//! Pure; reports progress and throws Error(CANCELLED).
#pragma once

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::volume {

bool is_clean_solid(const Mesh& mesh, Progress& progress);

}  // namespace fabvdb::volume
