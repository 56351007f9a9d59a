//! Splits the closed surface of a cavity (triangles facing out of the void)
//! into the connected void regions it bounds, with the volume of each. A
//! region is one outer shell plus the shells of the solid islands floating in
//! it: shells are the surface's connected components, an island is a shell
//! of negative signed volume, and it belongs to the smallest outer shell that
//! contains it (ray parity). Regions come out in the order of their outer
//! shells; volumes are exact for the given triangles (divergence theorem).
#pragma once

#include <vector>

#include "core/mesh.h"

namespace fabvdb::volume {

struct CavityRegion {
    Mesh surface;          //!< its shells, facing out of the void
    double volume = 0.0;   //!< mm³
};

std::vector<CavityRegion> split_cavity_regions(const Mesh& cavity_surface);

}  // namespace fabvdb::volume
