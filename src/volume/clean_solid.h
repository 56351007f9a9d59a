//! Whether a triangle mesh already is the clean boundary of a solid, so that
//! hollowing may keep it as the outer surface instead of a voxelized copy:
//! every edge shared by exactly two triangles running it in opposite
//! directions (closed, edge-manifold, consistently oriented), no degenerate
//! triangle, no self-intersection (CGAL, exact predicates), and the shells
//! oriented so that they bound a volume (outer shells outward, voids inward).
//! Pure; reports progress and throws Error(CANCELLED).
#pragma once

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::volume {

bool is_clean_solid(const Mesh& mesh, Progress& progress);

}  // namespace fabvdb::volume
