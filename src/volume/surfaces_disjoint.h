//! Proof that a cavity surface stays clear of the outer surface: every cavity
//! triangle is tested exactly (CGAL AABB tree, exact predicates) against the
//! outer triangles; any contact throws Error(INTERNAL) naming the count, so a
//! hollowed mesh never leaves with touching or crossing shells.
#pragma once

#include <string>

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::volume {

void require_disjoint_surfaces(const Mesh& outer, const Mesh& cavity, const std::string& what, Progress& progress);

}  // namespace fabvdb::volume
