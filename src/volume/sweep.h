//! Moldability enforcement by sweeping (thesis §3.6.2, DESIGN.md): the part P
//! made a double height field along d is (P swept along +d) ∩ (P swept along
//! −d), i.e. every line parallel to d meets it in one interval, the hull of
//! where it met P. Takes a level set and d; resamples it into a frame whose
//! index z axis is d, takes the running minimum of φ up and down each column,
//! keeps the larger (the intersection); given the input surface, trims
//! instead of filling where a fill would bury it deep (trim_deep_fills.h);
//! rebuilds the narrow band, and removes the volume of the `keep_out` solids
//! (the other parts, sampled on the part's block in their own frames) so
//! nothing is added inside them. Returns a level set on the d-aligned
//! transform (same voxel size, same world space). Cancellable; refuses over
//! the memory budget.
#pragma once

#include <cstdint>
#include <vector>

#include <openvdb/openvdb.h>

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::volume {

struct SweepOptions {
    //! Refuse (Error(OUT_OF_BUDGET)) when the dense column buffer would exceed this; 0: no limit.
    uint64_t memory_budget_bytes = 0;
    //! Level set of the input surface: where filling would bury it deeper
    //! than two voxels, columns are trimmed instead (trim_deep_fills.h).
    //! nullptr: every gap is filled.
    const openvdb::FloatGrid* kept_surface = nullptr;
};

//! Volumes in mm³, measured on the level sets.
struct SweepStats {
    double volume_before = 0;
    double volume_swept = 0;   //!< after sweeping, before the keep-out
    double volume_after = 0;   //!< the result
    double added_volume = 0;   //!< volume_after − volume_before
    double removed_by_keep_out = 0;
    size_t columns_trimmed = 0;  //!< columns that kept one run instead of being filled
};

//! `part`: a level set (GRID_LEVEL_SET, uniform voxels). `direction`: d, any
//! length. `keep_out`: level sets of solids the added volume must avoid (may be
//! empty). Throws Error(INVALID_ARGUMENT) for a non level set or a zero d.
openvdb::FloatGrid::Ptr sweep_double_height_field(const openvdb::FloatGrid& part, const Vec3& direction,
                                                  const std::vector<openvdb::FloatGrid::ConstPtr>& keep_out,
                                                  const SweepOptions& options, Progress& progress,
                                                  SweepStats* stats = nullptr);

//! The linear transform of voxel size `voxel_size` whose index axes are the
//! frame (e1, e2, d) of aligned_frame(direction).
openvdb::math::Transform::Ptr aligned_transform(double voxel_size, const Vec3& direction);

}  // namespace fabvdb::volume
