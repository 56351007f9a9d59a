//! Planning drain holes for a hollow part, from its level sets: extracts the
//! cavity surface, clusters it into patches, builds the powder flow of every
//! orientation (the first, printing orientation and the operator's set),
//! drops the cavity's powder, finds the candidate sites, searches the holes
//! with their cleaning routine and places the lowest-point baseline with as
//! many holes per cavity. Returns the holes, the routine, the model's
//! evaluation of both sets, per-stage timings. A cavity on which no hole
//! passes cleanly through the wall stops the plan after the candidate
//! sites: it returns a point on each such cavity's surface and nothing else
//! (the caller fills those cavities and plans again).
//! Reports progress; cancellable (Error(CANCELLED), no partial result).
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include <openvdb/openvdb.h>

#include "core/mesh.h"
#include "core/progress.h"
#include "powder/cavity_patches.h"
#include "powder/drainability_model.h"
#include "powder/hole_search.h"
#include "powder/keep_out.h"

namespace fabvdb::powder {

struct DrainPlan;

struct DrainPlanOptions {
    double hole_diameter = 4.0;
    double nominal_wall = 3.0;
    double repose_radians = 0.6108652381980153;  // 35°
    double effort = 0.9;
    //! Gravity directions of the operator's turns; empty: the 162 thesis directions.
    std::vector<Vec3> orientations;
    //! Gravity as printed, the routine's first orientation.
    Vec3 first_gravity{0, 0, -1};
    size_t patch_count = 2000;
    size_t powder_samples = 60000;
    std::string input_name = "mesh";  //!< what messages call the part
    HoleSearchOptions search;
    KeepOut keep_out;
    //! If set, called once the holes are chosen with the model, every
    //! candidate site and the plan so far (holes, baseline and routine;
    //! the model and sites live only during the call): for validation
    //! tools that evaluate hole sets and routines of their own.
    std::function<void(const DrainabilityModel&, const std::vector<DrainHole>& candidates, const DrainPlan& plan)>
        inspect;
};

struct DrainPlan {
    Mesh cavity_surface;
    CavityPatches patches;
    size_t candidate_count = 0;
    //! A point on the surface of each cavity that no candidate site reaches;
    //! when not empty, the rest of the plan is empty.
    std::vector<Vec3> cavities_without_site;
    std::vector<DrainHole> holes;
    DrainEvaluation evaluation;  //!< the prediction under random routines (their mean)
    //! The cleaning routine: the gravity of each later turn (the first,
    //! as printed, is `first_gravity`), and the prediction under it.
    std::vector<Vec3> routine;
    DrainEvaluation routine_evaluation;
    std::vector<double> random_residuals;  //!< mm³, one per random routine of the prediction
    std::vector<DrainHole> baseline;
    DrainEvaluation baseline_evaluation;
    double baseline_routine_residual = 0.0;  //!< mm³, under the lowest-point holes' own routine
    Vec3 first_gravity{0, 0, -1};
    std::map<std::string, double> timings;
};

//! `part` negative inside the part (cavity included), `cavity` negative inside
//! the cavity, `shell` negative in the wall; all level sets in mm.
DrainPlan plan_drain_holes(const openvdb::FloatGrid& part, const openvdb::FloatGrid& cavity,
                           const openvdb::FloatGrid& shell, const DrainPlanOptions& options, Progress& progress);

}  // namespace fabvdb::powder
