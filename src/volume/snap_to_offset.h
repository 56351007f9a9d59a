//! Puts the vertices of an extracted cavity surface on the exact inner offset
//! of the outer surface: each vertex's true distance to the outer triangles is
//! measured (see nearest_triangle.h: the closest triangles recorded in the
//! voxels around it, and a descent over their neighbours) and the vertex is
//! moved along the distance gradient to depth `wall` (mode exact), or only
//! when it is shallower than `wall` (mode at_least, for a cavity rounded by a
//! closing distance). A move that would flip a triangle is undone, so the
//! surface keeps its orientation and topology. Accuracy does not depend on
//! the voxel size: the wall at every vertex is the requested one.
#pragma once

#include <cstddef>

#include <openvdb/openvdb.h>

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::volume {

enum class OffsetSnap { exact, at_least };

struct SnapStats {
    double min_depth = 0;   //!< smallest distance of a cavity vertex to the outer surface after snapping
    size_t moved = 0;       //!< vertices moved
    size_t kept_back = 0;   //!< vertices left in place because moving them flipped a triangle
};

//! `closest_triangle`: the nearest outer triangle of every voxel of a band
//! that covers the cavity vertices (see solid_distance.h).
SnapStats snap_to_offset(Mesh& cavity, const Mesh& outer, const openvdb::Int32Grid& closest_triangle, double wall,
                         OffsetSnap mode, Progress& progress);

}  // namespace fabvdb::volume
