//! Boolean operations on closed triangle meshes by CGAL corefinement with
//! exact constructions (Epeck): a first solid combined with a sequence of
//! others (union, difference, intersection), the intermediate results kept
//! exact, rounded to doubles once at the end (triangles that rounding makes
//! degenerate, and needles with an edge under 1e-4 mm, are collapsed away).
//! Every input is validated first with exact predicates on its doubles (a
//! 2-manifold surface, closed, not self-intersecting, facing outward,
//! bounding a volume); a defect throws
//! Error(BAD_INPUT) naming the input and the defect. The result is closed and
//! 2-manifold (CGAL refuses otherwise: Error(BAD_INPUT) naming the step).
//! Checks cancellation between steps and reports no progress of its own, so
//! several can run at once on different meshes (CGAL's exact kernel is
//! thread-safe with its default number type, boost's gmp_rational).
#pragma once

#include <string>
#include <vector>

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::surface {

enum class BooleanOperation { unite, subtract, intersect };

struct BooleanStep {
    BooleanOperation operation;
    const Mesh* operand;
    std::string name;  //!< what the operand is called in error messages
};

//! first ∘ step₁ ∘ step₂ … applied left to right.
Mesh mesh_boolean(const Mesh& first, const std::string& first_name, const std::vector<BooleanStep>& steps,
                  const Progress& progress);

}  // namespace fabvdb::surface
