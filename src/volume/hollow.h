//! Hollowing for printing: keeps a wall of thickness `wall` under the outer
//! surface and empties the rest. The input may be dirty (it then goes through
//! the repair pipeline, repair.h, whose surface is clean); a clean closed
//! input keeps its own outer triangles, and one whose only defect is a few
//! crossing triangles keeps the exact boundary of its shells' union, cut out
//! of its own triangles (resolve_crossings.h). The cavity is the interior offset by
//! −wall, opened by the closing distance like PrusaSlicer's, and at least by
//! one voxel (offset by −(wall + opening), the core's distance rebuilt by fast
//! sweeping, then by +opening): void slivers thinner than two voxels, whose
//! two sides could not both be snapped, are dropped. The distances come from
//! the outer triangles themselves (exact near the surface, propagated inward
//! with each voxel's nearest triangle: solid_distance.h); the cavity is
//! extracted and its vertices snapped to the exact offset of the outer
//! triangles.
//! Guarantees: outer shells face out, cavity shells face in, every shell is
//! closed and no cavity triangle touches the outer surface (checked exactly);
//! the outer surface is the input's model (input_fidelity.h: a union of
//! crossing shells that is not is replaced by the repaired surface, a
//! repaired surface that is not is repaired again at up to two halvings of
//! the voxel, faithful_repair.h, and one that still is not stops the
//! hollowing with Error(INTERNAL));
//! regions thinner than 2·(wall + opening) stay solid (a part thinner than
//! that everywhere comes back solid, with a warning); voids under
//! `min_cavity_volume` are filled. An optional gyroid strut infill is carved out of the cavity
//! (see gyroid_infill.h) before extraction. Cancellable; the memory budget is
//! checked before any grid is built. A part far from the origin is hollowed
//! near it (core/centred_frame.h).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <openvdb/openvdb.h>

#include "core/mesh.h"
#include "core/progress.h"
#include "volume/gyroid_infill.h"
#include "volume/input_fidelity.h"

namespace fabvdb::volume {

struct HollowOptions {
    double wall = 0.0;               //!< mm, > 0
    double closing = 0.0;            //!< mm, >= 0
    double voxel_size = 0.0;         //!< mm; 0: automatic (see automatic_hollow_voxel)
    double adaptivity = 0.0;         //!< [0, 1], of the cavity extraction
    double min_cavity_volume = 0.0;  //!< mm³: smaller voids are filled
    GyroidStruts infill;             //!< cell 0: no infill
    uint64_t memory_budget_bytes = 0;  //!< 0: no limit
    std::string input_name = "mesh";   //!< for messages
};

struct HollowResult {
    Mesh mesh;                   //!< outer shells, then the cavity shells
    //! Where the outer surface comes from: "input" (the input's own triangles),
    //! "resolved" (the input's triangles with their crossings cut out) or
    //! "repaired" (the repair pipeline's surface).
    std::string outer_surface;
    //! How the outer surface stands to the input (input_fidelity.h): held to
    //! exact_limits when resolved, voxel_limits when repaired (a repaired
    //! surface that fails is an Error(INTERNAL)); not measured when it is
    //! the input's own.
    Fidelity fidelity;
    FidelityLimits fidelity_limits;
    double voxel_size = 0.0;
    //! mm, the voxel a repaired outer surface was made at: voxel_size, or
    //! finer where that lost thin features (faithful_repair.h); 0 otherwise.
    double outer_surface_voxel = 0.0;
    double volume_solid = 0.0;   //!< mm³ enclosed by the outer surface
    double volume_shell = 0.0;   //!< mm³ of material left
    std::vector<double> cavity_volumes;         //!< mm³ per void kept
    std::vector<double> filled_cavity_volumes;  //!< mm³ per void filled (under the minimum, or touching the outside)
    double min_wall_at_vertices = 0.0;          //!< smallest cavity-vertex distance to the outer surface
    std::map<std::string, double> timings;      //!< seconds per stage
    //! What the caller should tell the user: a part too thin for a cavity
    //! anywhere comes back solid, with a warning saying so.
    std::vector<std::string> warnings;
};

//! wall / 4, so the cavity's rounded concave parts (radius >= wall) are
//! resolved to a small fraction of a voxel; the snap makes the wall exact.
double automatic_hollow_voxel(double wall);

HollowResult hollow(const Mesh& input, const HollowOptions& options, Progress& progress);

//! The shell as a level set (negative in the material) at `voxel_size`: the
//! signed distance of a hollowed mesh's surfaces.
openvdb::FloatGrid::Ptr shell_level_set(const Mesh& hollowed, double voxel_size, Progress& progress);

}  // namespace fabvdb::volume
