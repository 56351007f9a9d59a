//! Cups of a bottom-up resin print: the empty pockets that the layers seal
//! against the vat film as they are added, so each peel pulls on a vacuum
//! (suction) and the pocket holds resin. The part is built along `up` from
//! the build plate (its lowest point along `up`); when layer k is cured the
//! film lies on its top, so the resin in the empty space of layers 0..k can
//! only reach the vat around the part through that empty space itself.
//! Definition: an empty cell of layer k belongs to a cup when, within the
//! empty cells of layers 0..k, it is not connected (through faces) to the
//! outside of the part's box, the side of the box toward the plate included
//! (the part stands on supports, so resin flows under it). A pocket that
//! opens toward the plate therefore drains and is no cup; one that opens
//! only toward the vat is one from its floor to its opening. Cells sealed
//! to the end (the surface's inner shells, which `trapped_volumes` reports)
//! are left out. A cup is a face-connected set of such cells.
//! The solid is read from `grid` (a level set, negative inside, its inside
//! flood-filled) at the centres of cubic cells of a grid aligned with `up`
//! over the print-frame box of `surface_points`: the cell is the grid's
//! voxel, coarsened so the box holds at most `max_cells` cells. A wall at
//! least a cell thick always separates (its cells block every face path);
//! a vent narrower than two cells may read closed.
//! Costs one voxel read per cell, a trilinear sample only within a cell
//! diagonal of the surface (parallel), and one sweep of the layers
//! labelling each layer's empty regions (union-find over regions, not
//! cells), memory one byte per cell; cancellable.
#pragma once

#include <cstdint>
#include <vector>

#include <openvdb/openvdb.h>

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::check {

struct Cup {
    double volume = 0.0;        //!< mm³: cells × cell³
    Vec3 center{0, 0, 0};       //!< the cells' centroid, in the part's frame
    BoundingBox box;            //!< the part-frame box around the cells' print-frame box
    double opening_area = 0.0;  //!< mm²: the cells whose neighbour toward the vat is open space
    Vec3 opening_center{0, 0, 0};  //!< those cells' centroid, in the part's frame
};

struct CupSearch {
    std::vector<Cup> cups;  //!< largest first
    double cell = 0.0;      //!< mm, the cell size used
};

//! The cups of the solid `grid` built along `up` (need not be unit, not
//! zero), each of at least `min_volume` mm³ and 8 cells (fewer is the
//! cells' noise along a surface, not a pocket).
CupSearch find_cups(const openvdb::FloatGrid& grid, const std::vector<Vec3>& surface_points, const Vec3& up,
                    uint64_t max_cells, double min_volume, Progress& progress);

}  // namespace fabvdb::check
