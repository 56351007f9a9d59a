//! Part-boundary smoothing with snakes (thesis §3.4.5). The boundary between
//! two parts is a snake whose vertices are the S_low vertices on it; a snake
//! vertex moves on S_low (projected onto the closest point of the surface as
//! it was when smoothing started, its inner vertex f_V interpolated there),
//! carrying the adjacent triangles with it, so every part keeps its prisms and
//! stays connected and covering. The objective is eq. 3.3,
//!   E = Σ_P E_P + w_l·E_smooth,
//! E_smooth = mean over the snake vertices of the cosine of the angle between
//! their two snake edges (−1 straight, 1 folded back). Each iteration moves
//! every snake vertex along its smoothing direction (−∇E_smooth, tangent to
//! the surface) by gradient descent on E, whose derivative along that
//! direction is a finite difference (the vertex's triangles' overhang and
//! overlap terms with the current M⁺/M⁻ labels, plus E_smooth); then the
//! moved triangles' overlap terms are measured again and the parting lines of
//! the parts that moved are recomputed. An iteration is kept only if E went
//! down (halving the steps otherwise) and Σ E_P did not rise above γ when it
//! was below. Junctions (where three parts meet) stay in place; steps that
//! would fold a triangle are shortened.
#pragma once

#include <vector>

#include <nlohmann/json.hpp>

#include "core/progress.h"
#include "surface/coarse_decomposition.h"

namespace fabvdb::surface {

//! Smooths the boundaries of `decomposition` for up to
//! options.smoothing_iterations iterations, moving only the snake vertices
//! with selected[v] != 0 (null: all of them). Updates `shell` (moved outer and
//! inner vertices, normals, areas), `terms` (overlaps of the moved triangles)
//! and the parts whose triangles moved. Returns {iterations, smoothness
//! [E_smooth per iteration, first before any move], moldability_energy
//! [Σ E_P likewise], vertices_moved, parts_touched}. Throws Error(CANCELLED).
nlohmann::json smooth_boundaries(Shell& shell, MoldabilityTerms& terms, Decomposition& decomposition,
                                 const DecompositionOptions& options, const std::vector<char>* selected,
                                 Progress& progress);

}  // namespace fabvdb::surface
