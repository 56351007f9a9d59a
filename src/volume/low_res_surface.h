//! The low-resolution surface S_low of the mold decomposition (thesis §3.4.2):
//! the zero iso-surface of a level set, extracted and then remeshed
//! isotropically (CGAL) to about `target_triangles` well-shaped triangles.
//! Its shells enclosing less than (edge / 2)³ at the remeshing edge length
//! (crumbs: sub-voxel bubbles of the level set, a few triangles each) are
//! dropped, and so are its voids (inward shells: a cast part cannot hold a
//! closed void, the decomposition fills them). Guarantees an outward-oriented triangle mesh of the level set's
//! surface (closed wherever the level set is); cancellable between stages.
#pragma once

#include <cstddef>

#include <openvdb/openvdb.h>

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::volume {

Mesh low_res_surface(const openvdb::FloatGrid& grid, size_t target_triangles, Progress& progress);

//! The edge length at which a surface of `area` has about `target_triangles`
//! equilateral triangles (the remeshing target; callers pick voxel sizes from it).
double edge_length_for_triangles(double area, size_t target_triangles);

}  // namespace fabvdb::volume
