//! Whether a triangle mesh already is the clean boundary of a solid, so that
//! hollowing may keep it as the outer surface instead of a voxelized copy:
//! a closed, oriented 2-manifold (closed_manifold.h), no degenerate triangle
//! (exact collinearity), no two triangles crossing (crossing_pairs.h, exact
//! predicates), and the shells oriented so that they bound a volume (outer
//! shells outward, voids inward: a positive volume, and for several shells
//! CGAL's nesting test), not flat (a mean thickness 2V/A of at least 1e-4 of
//! the diagonal, and no shell under that and under 1% of its own size). When crossing triangles are the only defect found,
//! their pairs come back too (resolve_crossings.h can remove them).
//! Pure; reports progress and throws Error(CANCELLED).
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::volume {

struct SolidCheck {
    bool clean = false;  //!< the mesh is the clean boundary of a solid
    //! The crossing pairs when the mesh is a closed oriented manifold without
    //! degenerate triangles but some of its triangles cross; else empty.
    std::vector<std::pair<uint32_t, uint32_t>> crossings;
};

//! `candidates` (per triangle; empty: all) limits the crossing test to pairs
//! with a candidate in them, for a caller that knows the others do not cross.
SolidCheck check_solid(const Mesh& mesh, Progress& progress, const std::vector<char>& candidates = {});

}  // namespace fabvdb::volume
