//! The drain-hole planning pipeline (see drain_plan.h).
#include "powder/drain_plan.h"

#include <cmath>

#include "core/error.h"
#include "core/icosphere.h"
#include "core/stage_clock.h"
#include "powder/hole_candidates.h"
#include "powder/orientation_flows.h"
#include "powder/powder_drop.h"
#include "volume/surface_ray_caster.h"
#include "volume/extract_mesh.h"

namespace fabvdb::powder {

namespace {

Vec3 unit(const Vec3& v) {
    const double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (!(length > 0.0) || !std::isfinite(length))
        throw Error(FABVDB_ERR_INVALID_ARGUMENT, "an orientation is not a non-zero direction");
    return {v[0] / length, v[1] / length, v[2] / length};
}

}  // namespace

DrainPlan plan_drain_holes(const openvdb::FloatGrid& part, const openvdb::FloatGrid& cavity,
                           const openvdb::FloatGrid& shell, const DrainPlanOptions& options, Progress& progress) {
    if (!(options.hole_diameter > 0.0)) throw Error(FABVDB_ERR_INVALID_ARGUMENT, "the hole diameter must be positive");
    if (!(options.repose_radians > 0.0 && options.repose_radians < M_PI / 2))
        throw Error(FABVDB_ERR_INVALID_ARGUMENT, "the angle of repose must be between 0 and 90 degrees");
    DrainPlan plan;
    StageClock clock(plan.timings);

    plan.cavity_surface = volume::extract_mesh(cavity, 0.0, progress);
    if (plan.cavity_surface.triangles.empty()) throw Error(FABVDB_ERR_BAD_INPUT, "the part has no cavity");
    clock.lap("cavity surface");
    progress.stage("patches");
    plan.patches = cluster_cavity_patches(plan.cavity_surface, options.patch_count);
    clock.lap("patches");

    HoleCandidateOptions candidate_options;
    candidate_options.diameter = options.hole_diameter;
    candidate_options.nominal_wall = options.nominal_wall;
    const std::vector<DrainHole> candidates =
        hole_candidates(plan.patches, shell, part, options.keep_out, candidate_options, progress);
    plan.candidate_count = candidates.size();
    std::vector<bool> has_site(plan.patches.cavity_count, false);
    for (const DrainHole& candidate : candidates) has_site[candidate.cavity] = true;
    for (size_t p = 0; p < plan.patches.size(); ++p) {
        const uint32_t c = plan.patches.cavity[p];
        if (has_site[c]) continue;
        has_site[c] = true;  // one point per cavity
        plan.cavities_without_site.push_back(plan.patches.site[p]);
    }
    clock.lap("hole candidates");
    if (!plan.cavities_without_site.empty()) return plan;

    const volume::SurfaceRayCaster caster(plan.cavity_surface);
    std::vector<Vec3> gravities;
    if (options.orientations.empty())
        gravities = thesis_directions().directions;
    else
        for (const Vec3& g : options.orientations) gravities.push_back(unit(g));
    gravities.push_back(unit(options.first_gravity));
    TransferOptions transfer;
    transfer.repose_radians = options.repose_radians;
    std::vector<OrientationFlow> turns = build_orientation_flows(plan.patches, caster, gravities, transfer, progress);
    const OrientationFlow first = std::move(turns.back());
    turns.pop_back();
    clock.lap("transfer and settle matrices");

    const PowderSamples powder =
        drop_cavity_powder(cavity, plan.patches, caster, first, options.powder_samples, options.input_name, progress);
    clock.lap("powder drop");

    DrainabilityOptions model_options;
    model_options.repose_radians = options.repose_radians;
    model_options.effort = options.effort;
    const DrainabilityModel model(plan.patches, turns, first, powder, model_options);
    clock.lap("drainability model");
    HoleSearchOptions search = options.search;
    search.min_center_distance = 2.0 * options.hole_diameter;
    HoleSearchResult found =
        search_drain_holes(model, candidates, plan.patches.cavity_count, first.gravity, search, progress);
    plan.holes = std::move(found.holes);
    plan.evaluation = std::move(found.evaluation);
    for (uint32_t k : found.routine) plan.routine.push_back(model.turn_gravity(k));
    plan.routine_evaluation = std::move(found.routine_evaluation);
    plan.random_residuals = std::move(found.random_residuals);
    plan.baseline = std::move(found.baseline);
    plan.baseline_evaluation = std::move(found.baseline_evaluation);
    plan.baseline_routine_residual = found.baseline_routine_residual;
    plan.first_gravity = first.gravity;
    clock.lap("hole search");
    if (options.inspect) options.inspect(model, candidates, plan);
    return plan;
}

}  // namespace fabvdb::powder
