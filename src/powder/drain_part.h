//! `fabvdb drain` end to end on a mesh: the input's level sets (a solid is
//! hollowed with `wall` by volume::hollow; an input that already is a hollow
//! shell — it has inward-facing shells that bound a void — is used as is),
//! the drain-hole plan (powder/drain_plan.h), the holes drilled through the
//! shell in the level set (volume::drill_holes) and the drilled part
//! extracted as the output mesh, checked to be the input's model but for
//! the holes and the cavities filled (volume/input_fidelity.h). A part too thin for a cavity needs no holes:
//! it comes back solid, with a warning. Reports progress; cancellable; a cancelled
//! or failed call returns nothing.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include <openvdb/openvdb.h>

#include "core/mesh.h"
#include "core/progress.h"
#include "powder/drain_plan.h"
#include "volume/input_fidelity.h"

namespace fabvdb::powder {

struct DrainPartOptions {
    double wall = 3.0;          //!< mm, for a solid input
    double voxel_size = 0.0;    //!< mm; 0: wall / 4
    uint64_t memory_budget_bytes = 0;
    std::string input_name = "mesh";
    DrainPlanOptions plan;      //!< plan.nominal_wall and plan.input_name are set from here
};

struct DrainPartResult {
    //! The drilled part; a part without a cavity (too thin for one under the
    //! wall) comes back solid and undrilled, `has_cavity` false, with no
    //! shell and an empty plan, and a warning says so.
    Mesh drilled;
    bool has_cavity = false;
    std::vector<std::string> warnings;
    bool input_was_hollow = false;
    double voxel_size = 0.0;
    //! mm, the voxel the drilled part was meshed at: voxel_size, or the
    //! outer surface's where hollowing refined it to keep thin features,
    //! or up to two halvings of that where the drilled part was not the
    //! input's model at it (folds narrower than two voxels closed).
    double surface_voxel = 0.0;
    openvdb::FloatGrid::Ptr shell;  //!< undrilled, negative in the wall
    DrainPlan plan;
    //! Balls (centre, radius, mm) holding the cavities left solid, too small
    //! or thin for a hole (the input's own voids among them).
    std::vector<std::pair<Vec3, double>> filled_cavities;
    //! How the drilled part stands to the input (volume/input_fidelity.h),
    //! what the drills took and the cavities filled left out; a part that is
    //! not the input's model is an Error(INTERNAL), never a result.
    volume::Fidelity fidelity;
    volume::FidelityLimits fidelity_limits;
    std::map<std::string, double> timings;  //!< all stages, seconds
};

DrainPartResult drain_part(const Mesh& input, const DrainPartOptions& options, Progress& progress);

//! Whether the mesh already is a hollow shell: a clean solid
//! (volume/clean_solid.h) with a component facing inward (negative signed
//! volume), the boundary of a void. A dirty mesh with inverted shells is
//! not one: it is repaired and hollowed. Throws Error(CANCELLED).
bool is_hollow_shell(const Mesh& mesh, Progress& progress);

}  // namespace fabvdb::powder
