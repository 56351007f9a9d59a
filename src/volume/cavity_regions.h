//! Splits the closed surface of a cavity (triangles facing out of the void)
//! into the connected void regions it bounds, with the volume of each. A
//! region is one outer shell plus the shells of the solid islands floating in
//! it: shells are the surface's connected components, an island is a shell
//! of negative signed volume, and it belongs to the smallest outer shell that
//! contains it (ray parity). An outer shell inside another's lies inside one
//! of that region's islands (`in_island`). Regions come out in the order of
//! their outer shells; volumes are exact for the given triangles (divergence
//! theorem). Costs a ray test of one vertex per shell against the outer
//! shells.
#pragma once

#include <vector>

#include "core/mesh.h"

namespace fabvdb::volume {

struct CavityRegion {
    Mesh surface;               //!< its outer shell, facing out of the void
    Mesh islands;               //!< the shells of the solid islands in it, facing out of the void
    double volume = 0.0;        //!< of the void: the outer shell's less the islands', mm³
    double island_volume = 0.0; //!< of the islands' solid, mm³
    bool in_island = false;     //!< its outer shell lies inside another region's outer shell
};

std::vector<CavityRegion> split_cavity_regions(const Mesh& cavity_surface);

}  // namespace fabvdb::volume
