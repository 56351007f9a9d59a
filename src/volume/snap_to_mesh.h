//! Snapping of an extracted surface back onto the input it came from, so
//! clean regions keep sub-voxel fidelity and sharp edges survive better. A
//! vertex moves to its closest point on the input when that point is within
//! `max_distance`, the input triangle there lies along the surface around
//! the vertex (normals within 60°, either way: an input triangle across the
//! surface, as at a hole's rim or inside, attracts nothing; an inverted one
//! still does), and no triangle around it flips or degenerates. Vertices nearest
//! to the input's sharp edges and corners go onto them instead
//! (feature_targets.h), so the extraction's chamfers disappear. Moves that would
//! make two triangles cross (crossing_pairs.h) are undone; crossings where
//! no vertex moved, i.e. of the surface as given, are reported. Topology is
//! unchanged. With `float_frame`, every vertex is placed where a float file
//! stores it: the surface is given in that frame's local coordinates, and
//! the tests above see the positions as stored (float_coordinates.h), so
//! rounding on writing makes no new crossing (the corners of a triangle
//! that rounding would flatten keep their computed position, for the
//! writer's float rounding to place); nullptr keeps the positions as
//! computed. Closest points are found from `closest_triangle` (per voxel
//! near the input, its nearest input triangle: OrientedInput in
//! signed_distance.h) by NearestTriangle (nearest_triangle.h), which needs
//! `input` welded. Parallel; reports progress; throws Error(CANCELLED).
#pragma once

#include <cstdint>

#include <openvdb/openvdb.h>

#include "core/centred_frame.h"
#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::volume {

struct SnapResult {
    uint64_t moved_vertices = 0;
    //! Whether triangles of the surface cross where no vertex moved.
    bool self_intersecting = false;
};

SnapResult snap_to_mesh(Mesh& surface, const Mesh& input, const openvdb::Int32Grid& closest_triangle,
                        double max_distance, const CentredFrame* float_frame, Progress& progress);

}  // namespace fabvdb::volume
