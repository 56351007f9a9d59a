//! Local thickness at points on a level set's surface: twice the radius of the
//! largest ball inside the solid (or inside the gap around it) reached from
//! the point by climbing the distance field to the medial surface. From each
//! point the walk follows the gradient of the distance (−φ for the solid, φ
//! for the gap) in half-voxel steps until it stops rising, then places the
//! ridge between the two straight branches of the distance across it (the
//! field is linear on each side of the medial surface), so a plate, tube or
//! pin of thickness t measures t within a fraction of a voxel at any voxel
//! size, not t less up to a voxel as the grid's highest sample would. At a
//! convex edge the walk runs along the edge's bisector into the medial sheet
//! and at a concave one into the fillet's larger ball, so neither reads thin.
//! Walks stop at `max_radius`: a point there is reported 2·max_radius thick
//! and flagged capped, at once when a ball of max_radius fits along the
//! first gradient (the sample max_radius deep reads at least max_radius).
//! The level set's band on that side must reach max_radius plus four voxels.
//! Costs 7 trilinear samples per capped point, else about 8 per half voxel
//! climbed, in parallel; cancellable.
#pragma once

#include <cstdint>
#include <vector>

#include <openvdb/openvdb.h>

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::volume {

//! Which side of the surface is measured: the material (wall thickness, pin
//! diameter) or the empty space (hole, channel and slot width).
enum class ThicknessSide { solid, gap };

struct LocalThickness {
    std::vector<double> thickness;  //!< per point, mm, at most 2·max_radius
    std::vector<Vec3> centre;       //!< per point, the medial point reached (the ball's centre)
    std::vector<uint8_t> capped;    //!< per point, 1 when the walk reached max_radius
};

LocalThickness local_thickness(const openvdb::FloatGrid& grid, const std::vector<Vec3>& points, ThicknessSide side,
                               double max_radius, Progress& progress);

}  // namespace fabvdb::volume
