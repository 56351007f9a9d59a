//! Mold generation for a decomposed model (thesis §3.6): for every part of
//! the decomposition, in order,
//!  1. detail restoration: its outer surface back from the full-resolution
//!     input's level set (volume/detail_restoration.h); input surface no
//!     restored part holds (thinner than a voxel) back as tubes a voxel
//!     thick in the nearest part (volume/keep_lost_surface.h);
//!  2. moldability enforcement: small gaps along the parting direction closed
//!     by ARAP deformation (overhang_deformation.h), then the part swept into a double height field
//!     along its parting direction, the added volume kept out of the other
//!     parts (the parts already made and the restored ones still to come);
//!     the runs other parts split off a part are handed to those parts and
//!     all are swept again (volume/hand_over_runs.h); each is meshed as an
//!     exact double height field whose column ends on the input surface are
//!     the input's own crossings along the direction (volume/sweep.h,
//!     volume/double_height_field_mesh.h);
//!  3. its two-piece mold: RBF parting surface, gate, runner, sprue, vents,
//!     registration keys, CGAL booleans (mold_assembly.h); or, with
//!     `common_mold`, one mold for all the parts side by side;
//!  4. the parts rounded to float coordinates, as STL files store them,
//!     without crossing triangles (float_rounding.h; the mold pieces are too).
//! Measures what each part added and how closely the parts reproduce the
//! input (distance from the input surface, sampled every voxel, to the
//! nearest part surface), and stops when they are not the input's model.
//! Cancellable between and inside stages; a cancelled run returns nothing.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "core/mesh.h"
#include "core/progress.h"
#include "surface/decomposition_parts.h"
#include "surface/mold_assembly.h"
#include "volume/input_fidelity.h"

namespace fabvdb::surface {

struct MoldGenerationOptions {
    //! Voxel of the level sets, mm; 0: the input's bounding-box diagonal / 250.
    double voxel_size = 0.0;
    //! mm: how far the ARAP deformation may move a surface point to close a
    //! small gap (overhang_deformation.h); 0: half a voxel, which keeps every
    //! moved point within half a voxel of the input (bench_mold; a whole
    //! voxel is too far: docs/design/geometry.md). Gaps wider than twice
    //! this are left to the sweep.
    double max_deformation = 0.0;
    //! false: no deformation, the sweep alone makes the parts moldable.
    bool deform_overhangs = true;
    //! Mold block margin and parting-surface grid step (mold_assembly.h).
    MoldOptions mold;
    //! One mold pair for all the parts in a row instead of one per part.
    bool common_mold = false;
    //! Refuse (Error(OUT_OF_BUDGET)) over this many bytes; 0: no limit.
    uint64_t memory_budget_bytes = 0;
    //! What the input is called in error messages.
    std::string input_name = "input";
};

struct CastPart {
    int id = 0;
    Vec3 direction{0, 0, 1};
    Mesh part;                    //!< closed, a double height field along direction
    MoldPair mold;                //!< empty with common_mold
    Vec3 common_mold_offset{0, 0, 0};  //!< with common_mold: see assemble_common_mold
    double restored_volume = 0;   //!< mm³, after detail restoration
    double volume = 0;            //!< mm³, of `part`
    size_t deformation_handles = 0;     //!< surface vertices pulled across a gap by ARAP
    double deformation_max = 0;         //!< mm, the largest ARAP displacement of a surface vertex
    double deformation_mean = 0;        //!< mm, the mean over the vertices that moved
    double deformed_volume_change = 0;  //!< mm³, volume after ARAP − restored_volume
    double given_volume = 0;      //!< mm³ of its own material handed to other parts (hand_over_runs.h)
    double received_volume = 0;   //!< mm³ handed to it by other parts
    double added_volume = 0;      //!< volume − restored − deformed change − received + given: what the sweep added
    double removed_by_keep_out = 0;  //!< mm³ the sweep would have added inside other parts
    size_t columns_trimmed = 0;   //!< columns the sweep trimmed instead of filling (trim_deep_fills.h)
    double mean_distance = 0;     //!< mm, area-weighted, from the input surface nearest to this part
    double max_distance = 0;
};

struct MoldGeneration {
    std::vector<CastPart> parts;
    MoldPair common_mold;         //!< with common_mold, in row coordinates
    double voxel_size = 0;
    double diagonal = 0;          //!< of the input's bounding box, mm
    double mean_distance = 0;     //!< mm, input vertices to the nearest part surface
    double max_distance = 0;
    //! The fidelity gate on the assembled parts (volume/input_fidelity.h):
    //! far is 1% of the diagonal, and at most 5% of the input's surface may
    //! be; parts that fail are an Error(INTERNAL), never a result.
    volume::Fidelity fidelity;
    volume::FidelityLimits fidelity_limits;
    //! Input triangles with surface the input's level set lost (thinner than
    //! a voxel), kept in a tube a voxel thick (volume/keep_lost_surface.h).
    size_t lost_triangles = 0;
    //! Ids of parts the others took whole in the sweep (slivers with no
    //! column of their own): dropped, with no cast part or mold.
    std::vector<int> vanished_parts;
    std::map<std::string, double> seconds;  //!< per stage
};

//! `input`: the full-resolution model the decomposition was made for.
//! Throws Error(INVALID_ARGUMENT) for options out of range, BAD_INPUT when
//! every part vanishes or one cannot be molded, OUT_OF_BUDGET, CANCELLED.
MoldGeneration generate_molds(const Mesh& input, const DecomposedModel& model, const MoldGenerationOptions& options,
                              Progress& progress);

}  // namespace fabvdb::surface
