//! `fabvdb repair` as one operation: robust signed distance of a dirty mesh
//! (signed_distance.h), small shells dropped (drop_small_shells.h), the
//! surface extracted (extract_mesh.h) and snapped back onto the input where
//! it is clean (snap_to_mesh.h); surface shells under a voxel's volume
//! (specks of the extraction) are dropped. The output mesh is closed, 2-manifold,
//! outward-oriented and free of self-intersections (checked with exact
//! predicates; walls thinner than a voxel, whose two sides would touch, are
//! grown by half a voxel until it is). A model far from the origin is
//! processed near it (core/centred_frame.h). Throws what its stages
//! throw, and Error(BAD_INPUT) when no shell survives or the surface stays
//! open (the input has no consistent inside); cancellable.
#pragma once

#include <cstdint>

#include <openvdb/openvdb.h>

#include "core/centred_frame.h"
#include "core/mesh.h"
#include "core/progress.h"
#include "volume/signed_distance.h"

namespace fabvdb::volume {

struct RepairOptions {
    SignedDistanceOptions distance;
    //! Extraction adaptivity in [0, 1] (0: uniform triangles).
    double adaptivity = 0.0;
    //! Snap the output onto the input where the input is clean.
    bool snap = true;
    //! Solid shells under this volume (mm³) are dropped from the level set;
    //! 0 keeps all (specks under a voxel's volume still leave the surface).
    double min_shell_volume = 0.0;
    //! false: stop after the level set (no mesh, no snapping).
    bool extract = true;
};

struct RepairResult {
    openvdb::FloatGrid::Ptr grid;
    Mesh mesh;
    SignedDistanceStats distance;  // its timings hold every stage's
    uint64_t shells_kept = 0;  //!< connected pieces of the output surface (of the level set without extraction)
    uint64_t shells_dropped = 0;  //!< shells under min_shell_volume, and specks
    uint64_t snapped_vertices = 0;
};

RepairResult repair(const Mesh& mesh, const RepairOptions& options, Progress& progress);

//! The same on a mesh already moved into `frame` (centred_frame.h), with the
//! result in that frame; its snapped surface is placed where a float file
//! stores it once moved back (snap_to_mesh.h), where floats are finer than
//! a thousandth of a voxel.
RepairResult repair_in_frame(const Mesh& mesh, const RepairOptions& options, const CentredFrame& frame,
                             Progress& progress);

//! The voxel size that puts `resolution` voxels along the longest side of the
//! mesh's bounding box. Throws Error(INVALID_ARGUMENT) for resolution < 8 and
//! Error(BAD_INPUT) for a mesh without extent.
double voxel_size_for_resolution(const Mesh& mesh, int resolution, const std::string& input_name);

}  // namespace fabvdb::volume
