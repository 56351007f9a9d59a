//! The winding number (winding_number.h) at the voxels of one leaf of an
//! unsigned narrow band, taken once per group of voxels with no surface
//! between them instead of once per voxel.
//!
//! Two face or edge neighbours whose distances add up to more than the length
//! between them have no surface between them (meshToVolume gives a voxel
//! within 1.5 voxels of a triangle its exact distance to it); two voxels off
//! the band have none either. Along such links w changes at most by the
//! leaf's gradient bound (winding_gradient_bound.h) times the path, so a group
//! whose w, taken at one voxel, is farther from 1/2 than a margin of 0.1 plus
//! that change lies wholly on one side and shares it. Other groups are taken
//! voxel by voxel, as is a large group whose second sample, 4 voxels away,
//! disagrees about the side. For a closed cycle (closed_cycle.h) the bound is
//! 0 and every group costs one or two evaluations; near the holes of an open
//! input, where the bound is large, every voxel costs one. A leaf that needs
//! more than 16 evaluations takes them through its box's field
//! (WindingNumber::box_field: one walk for the far nodes, interpolated).
#pragma once

#include <openvdb/openvdb.h>

#include "volume/winding_number.h"

namespace fabvdb::volume {

using FloatLeaf = openvdb::FloatTree::LeafNodeType;

//! Inside is w >= 1/2.
constexpr double inside_winding = 0.5;

//! w at every active voxel of `leaf` (unsigned distances) into w[offset];
//! `gradient_bound` bounds |∇w| (1/mm) over the leaf. Values of a group are
//! its sample's. Returns true when every active voxel was evaluated itself.
bool band_leaf_winding(const FloatLeaf& leaf, const WindingNumber& winding, const openvdb::math::Transform& transform,
                       double gradient_bound, float* w);

//! Values for the inactive voxels of a band leaf whose active voxels are
//! signed, from w: (1/2 - w) / |∇w| by central differences of w, clamped to
//! ±background. Voxels whose group lies so far from 1/2 that the value is
//! clamped for certain get ±background from one sample; if any group is not
//! that far, every voxel of the leaf is evaluated (the active ones too unless
//! `band_exact`, band_leaf_winding's answer) so the differences are true.
void off_band_leaf_values(FloatLeaf& leaf, const WindingNumber& winding, const openvdb::math::Transform& transform,
                          double gradient_bound, float background, bool band_exact, float* w);

}  // namespace fabvdb::volume
