//! Memory a narrow-band level set of a mesh will take, estimated before any
//! allocation from the surface area: active voxels ~ area / voxel² × band
//! width, times the bytes the conversion holds per active voxel at its peak
//! (distance grid, closest-triangle grid, winding numbers, tree overhead).
//! Also the smallest voxel size that fits a budget, for the refusal message.
#pragma once

#include <cstdint>

#include "core/mesh.h"

namespace fabvdb::volume {

//! Total area of the mesh's triangles in mm² (duplicates counted: an upper bound).
double surface_area(const Mesh& mesh);
//! Estimated active voxels of a band of `half_band_voxels` on each side.
uint64_t estimate_active_voxels(double area, double voxel_size, int half_band_voxels);
//! Estimated peak bytes of building such a level set.
uint64_t estimate_level_set_bytes(double area, double voxel_size, int half_band_voxels);
//! The voxel size (rounded up to two significant digits) whose estimate fits `budget_bytes`.
double voxel_size_for_budget(double area, int half_band_voxels, uint64_t budget_bytes);

}  // namespace fabvdb::volume
