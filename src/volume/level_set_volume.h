//! The volume inside a level set, in world units cubed: OpenVDB's measure
//! over the grid's voxels, 0 for a grid without active voxels (which the
//! measure refuses). A grid in a rotated frame (an aligned sweep grid) is
//! measured with a plain scale transform of its voxel size: the volume does
//! not depend on the rotation, and OpenVDB's measure refuses some exactly
//! cubic rotated frames of small voxels as non-uniform (its test normalises
//! by the determinant's cube root and checks for a unitary matrix; e.g. 2.5
//! and 10 µm voxels at some angles — a part a few millimetres across).
//! Costs one pass over the active voxels; the tree is shared, not copied.
#pragma once

#include <openvdb/openvdb.h>

namespace fabvdb::volume {

double level_set_volume(const openvdb::FloatGrid& grid);

}  // namespace fabvdb::volume
