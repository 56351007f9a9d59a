//! Printability of a part for one process, as a farm checks an order: each
//! check with a status (pass, warn, fail), its figures in mm and where to
//! look. The solid is the input's robust signed distance (winding numbers,
//! so a dirty mesh is judged as the solid `repair` would make); its surface,
//! extracted at the voxel size, carries the measurements:
//!  - mesh: the input's defects (`info`'s inspection) and the path `repair`
//!    would take (none, mesh level, volumetric);
//!  - units: a size that suggests metres, inches, centimetres (units_guess.h);
//!  - wall_thickness: the local thickness at every surface vertex
//!    (local_thickness.h), regions under the minimum wall with their area and
//!    thinnest point; optionally a heat map (PLY, viridis, and a PNG legend);
//!  - small_features: thin regions whose medial points lie along a line
//!    (pins, posts) under the minimum pin diameter, fins (thin walls held
//!    along one edge only, thin_sheets.h), and solid pieces shorter than the
//!    minimum feature;
//!  - holes: regions where the gap beside the surface (local thickness on the
//!    empty side) is under the minimum hole: holes, channels, slots that close;
//!  - trapped_volumes: sealed cavities (the surface's inward shells) with
//!    their volume, failing where the process needs escape holes;
//!  - overhangs: surface needing support with `up` as the build direction;
//!  - cups (when the profile cures against a vat film): pockets the layers
//!    seal against the film, built along `up` (resin_cups.h);
//!  - build_volume: whether the part fits, as placed or turned (build_fit.h).
//! The verdict is the worst status. Costs the signed distance with a band as
//! deep on each side as its walk's reach (half its warning limit), the narrow
//! band widened by closest points (widen_band.h), one extraction and two
//! walks per surface vertex, most of them a single sample, and for cups one
//! sample per cell of a grid of at most 8M cells; errors as signed_distance_from_mesh (OUT_OF_BUDGET, BAD_INPUT for a
//! mesh enclosing nothing), Error(IO) when the heat map cannot be written;
//! reports progress, cancellable.
#pragma once

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "check/process_profile.h"
#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::check {

struct CheckOptions {
    ProcessProfile profile;
    //! The build direction in the part's frame (need not be unit).
    Vec3 up{0, 0, 1};
    //! The printer's build volume in mm; all zero: not checked.
    Vec3 build_volume{0, 0, 0};
    //! Voxel size in mm; 0: the longest side / `resolution`, kept between
    //! min_wall / 4 and min_wall / 2.
    double voxel_size = 0.0;
    //! Voxels along the longest side that set the automatic voxel size.
    int resolution = 400;
    //! A .ply path for the wall-thickness heat map (and STEM.png), or empty.
    std::string thickness_map;
    //! Refuse (Error(OUT_OF_BUDGET)) beyond this many bytes; 0: no limit.
    uint64_t memory_budget_bytes = 0;
    //! What messages call the input.
    std::string input_name = "mesh";
};

//! The report: verdict, process, voxel_size, checks {name: {status, message,
//! figures...}}, warnings, timings (docs/check.md lists every key).
nlohmann::json check_part(const Mesh& mesh, const CheckOptions& options, Progress& progress);

}  // namespace fabvdb::check
