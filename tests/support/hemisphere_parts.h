//! A two-part labelling of a shell (surface/shell.h) for the decomposition
//! tests: part 0 the triangles whose outward normal has n_z ≥ 0, part 1 the
//! rest. On a sphere these are the upper and lower hemispheres, each one
//! edge-connected piece.
#pragma once

#include <vector>

#include "surface/shell.h"

namespace fabvdb::test {

inline std::vector<int> hemisphere_parts(const surface::Shell& shell) {
    std::vector<int> part_of_triangle(shell.triangle_count());
    for (size_t t = 0; t < shell.triangle_count(); ++t) part_of_triangle[t] = shell.normal[t][2] >= 0 ? 0 : 1;
    return part_of_triangle;
}

}  // namespace fabvdb::test
