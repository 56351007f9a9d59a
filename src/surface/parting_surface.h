//! The parting surface of a two-piece mold (thesis §3.6.3): in the frame where
//! the parting direction is +Z, a smooth height field z = f(x, y) through the
//! parting line by Gaussian radial basis function interpolation,
//!   f(p) = c + Σᵢ wᵢ exp(−|p − pᵢ|² / σ²),  (K + λI) w = z − c,
//! with c the mean height, sampled at the vertices of a regular grid over the
//! mold block (so it extends to the border, flattening to c far from the
//! line) and clamped to the block's height range. Pure function.
#pragma once

#include <cstddef>
#include <vector>

#include "core/mesh.h"

namespace fabvdb::surface {

//! Heights at the vertices of a regular grid: vertex (i, j), 0 ≤ i ≤ nx,
//! 0 ≤ j ≤ ny, is at (x0 + i·step, y0 + j·step, z[j·(nx+1) + i]).
struct HeightGrid {
    double x0 = 0, y0 = 0, step = 1;
    int nx = 0, ny = 0;
    std::vector<double> z;
    double x(int i) const { return x0 + i * step; }
    double y(int j) const { return y0 + j * step; }
    double& at(int i, int j) { return z[size_t(j) * size_t(nx + 1) + size_t(i)]; }
    double at(int i, int j) const { return z[size_t(j) * size_t(nx + 1) + size_t(i)]; }
};

struct PartingSurfaceOptions {
    //! Gaussian width σ in mm; 0: a fifth of the diagonal of the line's (x, y) extent.
    double kernel_width = 0.0;
    //! λ, relative to the kernel's value at 0 (1).
    double regularization = 1e-6;
    //! The line is resampled to at most this many constraints, evenly by arc length.
    size_t max_constraints = 800;
};

//! `parting_line`: points (frame coordinates) along the closed parting
//! line(s), in order (consecutive points are neighbours). `grid` gives x0, y0,
//! step, nx, ny; its heights are filled, clamped to [z_min, z_max].
//! Throws Error(BAD_INPUT) for fewer than 3 points, INVALID_ARGUMENT for an
//! empty grid or z_min ≥ z_max.
void interpolate_parting_surface(const std::vector<Vec3>& parting_line, double z_min, double z_max,
                                 const PartingSurfaceOptions& options, HeightGrid& grid);

//! The height grid as an open triangulated sheet (two triangles per cell,
//! facing +Z).
Mesh height_grid_sheet(const HeightGrid& grid);

}  // namespace fabvdb::surface
