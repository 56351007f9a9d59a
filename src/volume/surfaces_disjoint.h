//! Proof that a cavity surface stays clear of the outer surface: every cavity
//! triangle is tested exactly (CGAL AABB tree, exact predicates) against the
//! outer triangles, and flagged where it touches or crosses one, so a
//! hollowed mesh never leaves with touching or crossing shells. Parallel;
//! throws Error(CANCELLED).
#pragma once

#include <vector>

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::volume {

//! One flag per cavity triangle: 1 where it touches or crosses `outer`.
std::vector<char> cavity_triangles_touching(const Mesh& outer, const Mesh& cavity, Progress& progress);

}  // namespace fabvdb::volume
