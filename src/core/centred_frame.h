//! Working near the origin on a model stored far from it (UTM or survey
//! coordinates, tens of kilometres off): voxel grids and their extracted
//! meshes carry single-precision coordinates, which at 10 km are a
//! millimetre apart, so operations run on the model moved by `offset` and
//! their results are moved back. Along an axis where the model lies farther
//! from the origin than its own extent, the offset is its bounding-box
//! centre: every input coordinate a then lies within a factor 2 of it, so
//! a − offset is exact (Sterbenz) and moving back gives a again, bit for
//! bit; along other axes the offset is 0. Pure.
#pragma once

#include "core/mesh.h"

namespace fabvdb {

struct CentredFrame {
    Vec3 offset{0, 0, 0};  //!< local = world − offset
    bool identity() const { return offset[0] == 0.0 && offset[1] == 0.0 && offset[2] == 0.0; }
};

CentredFrame centred_frame(const Mesh& mesh);
//! The mesh moved into the frame (vertices − offset).
Mesh to_local(Mesh mesh, const CentredFrame& frame);
//! Moves a mesh of the frame back (vertices + offset), in place.
void to_world(Mesh& mesh, const CentredFrame& frame);

}  // namespace fabvdb
