//! Signed distance of a clean solid's surface (closed, edge-manifold,
//! consistently oriented, not self-intersecting: see clean_solid.h), with the
//! nearest triangle of every voxel, negative inside, in mm.
//! Near the surface (every voxel centre within one voxel of a triangle) the
//! distance is exact: triangles are binned by the 8³-voxel blocks their
//! widened bounding box touches, each block is computed on its own (in
//! parallel, no shared writes), and the sign is that of the angle-weighted
//! pseudonormal of the nearest feature (face, edge or corner; Bærentzen and
//! Aanæs 2005: exact on such surfaces). Inward, the band grows in order of
//! distance, a voxel deep at a time, until it is `interior_depth` + 2 voxels
//! deep: a new voxel takes the nearest of its neighbours' nearest triangles,
//! at its exact distance to it (closest-triangle propagation: a distance can
//! only be too large, where the true nearest triangle is no neighbour's: by
//! at most 0.13 mm at 0.75 mm voxels, docs/design/geometry.md). Inactive
//! values are signed by flood fill, the background deeper than the band.
//! Cancellable (Error CANCELLED, no partial grid).
#pragma once

#include <openvdb/openvdb.h>

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::volume {

struct SolidDistance {
    openvdb::FloatGrid::Ptr distance;          //!< level set, voxel size `voxel`, centres at multiples of it
    openvdb::Int32Grid::Ptr closest_triangle;  //!< same active voxels: the triangle the distance is to
};

SolidDistance solid_distance(const Mesh& surface, double voxel, double interior_depth, Progress& progress);

}  // namespace fabvdb::volume
