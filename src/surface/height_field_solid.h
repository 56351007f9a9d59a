//! The closed solid between two height fields over a set of grid cells:
//! {(x, y, z) : (x, y) in a marked cell, lower(x, y) ≤ z ≤ upper(x, y)}, the
//! heights given at the grid vertices and interpolated linearly over each
//! cell's two triangles (the same diagonal as height_grid_sheet), with
//! vertical walls along the border of the marked cells. Mold blocks split by
//! the parting surface and channels along it are such solids. The result is
//! closed, 2-manifold and outward, and each of its vertical lines crosses it
//! at most twice. Pure function.
#pragma once

#include <vector>

#include "surface/parting_surface.h"

namespace fabvdb::surface {

//! `cells`: nx·ny flags, cell (i, j) at j·nx + i. `lower`, `upper`: heights at
//! the grid vertices (layout of HeightGrid::z), upper > lower at every vertex
//! of a marked cell. Throws Error(INVALID_ARGUMENT) for sizes that do not
//! match, heights out of order, or two marked cells that touch only at a
//! corner (the solid would not be 2-manifold there).
Mesh height_field_solid(const HeightGrid& grid, const std::vector<char>& cells, const std::vector<double>& lower,
                        const std::vector<double>& upper);

//! Marks cells so that no two marked cells touch only at a corner: where
//! they do, the cell beside both of them with the lower index joins them.
//! Cells are only added, so the result holds every cell it was given; it is
//! what height_field_solid accepts. Returns how many cells were added.
size_t join_corner_contacts(const HeightGrid& grid, std::vector<char>& cells);

}  // namespace fabvdb::surface
