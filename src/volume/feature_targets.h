//! Where vertices of an extracted surface go so the input's sharp features
//! come back: an extraction cuts sharp edges and corners (a chamfer up to a
//! voxel deep), and snapping each vertex to its closest input point keeps it
//! on a face beside the edge. A sharp edge is an input edge between two
//! triangles whose normals turn by more than ~37 degrees; a corner is an input
//! vertex where three or more sharp edges meet, or two that turn by as much.
//! Each corner draws the surface vertex nearest to it, each sharp edge the
//! vertex nearest to each of its samples (half a reach apart), onto the edge;
//! only vertices within `reach` whose normal faces the feature's triangles
//! are drawn, and to an edge only those whose closest input triangle faces
//! within 60 degrees the way one of its two does (so the edges of a shell inside
//! another, which the surface passes near where they pierce it, draw
//! nothing). The caller keeps the safeguards (no flip, no crossing).
#pragma once

#include <vector>

#include "core/mesh.h"

namespace fabvdb::volume {

struct FeatureTargets {
    //! Per surface vertex: whether it has a target, and the target.
    std::vector<char> has_target;
    std::vector<Vec3> target;
};

//! `surface_normals`: per surface vertex, a normal (any length) pointing out;
//! `nearest_input_normals`: per surface vertex, the unit normal of the input
//! triangle closest to it.
FeatureTargets feature_targets(const Mesh& surface, const std::vector<Vec3>& surface_normals,
                               const std::vector<Vec3>& nearest_input_normals, const Mesh& input, double reach);

}  // namespace fabvdb::volume
