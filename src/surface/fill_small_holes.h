//! Filling the small holes of a triangle mesh with smooth patches: each
//! boundary loop (loops touching at a vertex measured together) whose
//! bounding box is at most `max_diameter` across is triangulated, refined
//! to the density of its surroundings and faired (CGAL's
//! triangulate_refine_and_fair_hole, C1 continuity with the surface around
//! it); every input triangle is kept. Returns nothing (the
//! caller repairs otherwise) when the mesh is not an oriented 2-manifold
//! with boundary, when a hole is larger, or when a patch cannot be made or
//! faired. Whether every loop is small enough is told from the edges before
//! the mesh is converted for CGAL (the conversion costs about 5 µs a
//! triangle). Pure; checks `progress` between holes (Error(CANCELLED)).
#pragma once

#include <cstddef>
#include <optional>

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::surface {

struct FilledHoles {
    Mesh mesh;
    size_t holes = 0;            //!< holes filled
    size_t added_triangles = 0;  //!< triangles of the patches
};

std::optional<FilledHoles> fill_small_holes(const Mesh& mesh, double max_diameter, Progress& progress);

}  // namespace fabvdb::surface
