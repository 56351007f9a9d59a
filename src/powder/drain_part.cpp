//! `fabvdb drain` on a mesh (see drain_part.h).
#include "powder/drain_part.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include <openvdb/tools/Composite.h>
#include <openvdb/tools/Interpolation.h>
#include <openvdb/tools/LevelSetUtil.h>
#include <openvdb/tools/GridTransformer.h>
#include <openvdb/tools/MeshToVolume.h>

#include "core/error.h"
#include "core/figure_text.h"
#include "core/stage_clock.h"
#include "core/vec3_ops.h"
#include "surface/mesh_topology.h"
#include "surface/signed_volume.h"
#include "volume/clean_solid.h"
#include "volume/drill_holes.h"
#include "volume/extract_mesh.h"
#include "volume/hollow.h"
#include "volume/input_fidelity.h"
#include "volume/level_set_volume.h"
#include "volume/signed_distance.h"

namespace fabvdb::powder {

namespace {

struct Shells {
    Mesh outer, voids;
};

//! Outward shells (the part) and inward shells (its voids) of a closed mesh.
Shells split_shells(const Mesh& mesh) {
    size_t count = 0;
    const std::vector<uint32_t> component = surface::triangle_components(mesh, count);
    const std::vector<double> volume = surface::component_signed_volumes(mesh, component, count);
    Shells shells;
    shells.outer.vertices = mesh.vertices;
    shells.voids.vertices = mesh.vertices;
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
        (volume[component[t]] < 0.0 ? shells.voids : shells.outer).triangles.push_back(mesh.triangles[t]);
    return shells;
}

//! Whether voids of the level set trap powder the model can see: some value
//! lies inside (below zero) and the surface extraction keeps more than
//! crumbs of it (it drops those as noise).
bool traps_powder(const openvdb::FloatGrid& cavity, Progress& progress) {
    bool inside = false;
    for (auto value = cavity.cbeginValueAll(); value && !inside; ++value) inside = *value < 0.0f;
    return inside && !volume::extract_mesh(cavity, 0.0, progress).triangles.empty();
}

openvdb::FloatGrid::Ptr level_set_of(const Mesh& closed, double voxel) {
    std::vector<openvdb::Vec3s> points;
    std::vector<openvdb::Vec3I> triangles;
    points.reserve(closed.vertices.size());
    for (const Vec3& p : closed.vertices) points.emplace_back(float(p[0]), float(p[1]), float(p[2]));
    for (const Triangle& t : closed.triangles) triangles.emplace_back(t[0], t[1], t[2]);
    return openvdb::tools::meshToLevelSet<openvdb::FloatGrid>(
        *openvdb::math::Transform::createLinearTransform(voxel), points, triangles, 3.0f);
}

//! The cavities that stay open once the connected voids of `cavity` that
//! hold one of `points` on their surface are filled: nullptr when none
//! stays. Adds the filled voids' count and volume (mm³).
//! A ball holding the active voxels of `grid` (its box's centre and half
//! diagonal, a voxel more).
std::pair<Vec3, double> bounding_ball(const openvdb::FloatGrid& grid) {
    const openvdb::CoordBBox box = grid.evalActiveVoxelBoundingBox();
    const openvdb::Vec3d lo = grid.indexToWorld(box.min()), hi = grid.indexToWorld(box.max());
    const Vec3 centre{0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2])};
    return {centre, 0.5 * (hi - lo).length() + grid.voxelSize()[0]};
}

openvdb::FloatGrid::Ptr fill_cavities_at(const openvdb::FloatGrid& cavity, const std::vector<Vec3>& points,
                                         size_t& filled_count, double& filled_volume,
                                         std::vector<std::pair<Vec3, double>>& filled_balls) {
    std::vector<openvdb::FloatGrid::Ptr> voids;
    openvdb::tools::segmentSDF(cavity, voids);
    std::vector<bool> filled(voids.size(), false);
    for (const Vec3& point : points) {
        const openvdb::Vec3d world(point[0], point[1], point[2]);
        size_t nearest = 0;
        double least = std::numeric_limits<double>::infinity();
        for (size_t v = 0; v < voids.size(); ++v) {
            const double value = std::abs(openvdb::tools::BoxSampler::sample(
                voids[v]->tree(), voids[v]->transform().worldToIndex(world)));
            if (value < least) least = value, nearest = v;
        }
        filled[nearest] = true;
    }
    openvdb::FloatGrid::Ptr open;
    for (size_t v = 0; v < voids.size(); ++v) {
        if (filled[v]) {
            ++filled_count;
            filled_volume += volume::level_set_volume(*voids[v]);
            filled_balls.push_back(bounding_ball(*voids[v]));
        } else if (!open) {
            open = voids[v];
        } else {
            openvdb::tools::csgUnion(*open, *voids[v]);
        }
    }
    return open;
}

}  // namespace

bool is_hollow_shell(const Mesh& mesh, Progress& progress) {
    size_t count = 0;
    const std::vector<uint32_t> component = surface::triangle_components(mesh, count);
    const std::vector<double> volume = surface::component_signed_volumes(mesh, component, count);
    double outer = 0.0, voids = 0.0;
    for (double v : volume) (v < 0 ? voids : outer) += std::abs(v);
    // The exact solid check last: a part without inward shells (the usual
    // input) is hollowed, and hollowing runs that check itself.
    return voids > 1e-6 * outer && voids > 0.0 && volume::check_solid(mesh, progress).clean;
}

namespace {

//! Halvings of the voxel the drilled part is meshed at, where at its own
//! it was not the input's model (folds narrower than two voxels closed).
constexpr int kSurfaceRefinements = 2;

//! The drilled part against the input (volume/input_fidelity.h), but for
//! what the drills took and the cavities filled (the input's own voids
//! among them); its volume is the material's, not the solid's.
void measure_drained(const Mesh& input, DrainPartResult& result, StageClock& clock, Progress& progress) {
    result.fidelity_limits = volume::voxel_limits(result.voxel_size);
    result.fidelity_limits.volume = false;
    result.fidelity_limits.exempt = result.filled_cavities;
    // Each drilled cylinder (from half a diameter behind the centre to its
    // depth, as drilled), covered by balls of the hole's diameter every radius.
    for (const DrainHole& hole : result.plan.holes) {
        const double radius = 0.5 * hole.diameter, length = radius + hole.depth;
        const Vec3 start = hole.center - radius * hole.axis;
        for (double along = 0.0;; along = std::min(along + radius, length)) {
            result.fidelity_limits.exempt.push_back({start + along * hole.axis, hole.diameter});
            if (along >= length) break;
        }
    }
    result.fidelity = volume::measure_fidelity(input, result.drilled, result.fidelity_limits, progress);
    clock.lap("fidelity");
}

//! The part's level set less the cavity's, at `voxel`: the part from its
//! outer shells, the cavity resampled from the planning grid.
openvdb::FloatGrid::Ptr shell_at(const Mesh& outer, const openvdb::FloatGrid& cavity, double voxel) {
    const openvdb::FloatGrid::Ptr part = level_set_of(outer, voxel);
    const openvdb::FloatGrid::Ptr resampled = openvdb::FloatGrid::create(part->background());
    resampled->setTransform(part->transform().copy());
    resampled->setGridClass(openvdb::GRID_LEVEL_SET);
    openvdb::tools::resampleToMatch<openvdb::tools::BoxSampler>(cavity, *resampled);
    return openvdb::tools::csgDifferenceCopy(*part, *resampled);
}

DrainPartResult hollow_plan_and_drill(const Mesh& input, const DrainPartOptions& options, Progress& progress) {
    if (!(options.wall > 0.0) || !std::isfinite(options.wall))
        throw Error(FABVDB_ERR_INVALID_ARGUMENT, "the wall must be > 0 mm");
    validate_mesh(input, options.input_name);
    if (input.triangles.empty()) throw Error(FABVDB_ERR_BAD_INPUT, options.input_name + ": no triangles");
    openvdb::initialize();
    DrainPartResult result;
    StageClock clock(result.timings);
    const double voxel = options.voxel_size > 0.0 ? options.voxel_size : volume::automatic_hollow_voxel(options.wall);
    result.voxel_size = voxel;

    // A closed mesh of the part's outer shells and its voids' shells (inward).
    Mesh shells_mesh;
    // The voxel the drilled part is meshed at: the outer surface's, finer
    // than the hollowing's where that lost thin features (faithful_repair.h).
    double surface_voxel = voxel;
    result.input_was_hollow = is_hollow_shell(input, progress);
    if (result.input_was_hollow) {
        volume::SignedDistanceOptions distance;
        distance.voxel_size = voxel;
        distance.memory_budget_bytes = options.memory_budget_bytes;
        distance.input_name = options.input_name;
        shells_mesh = volume::extract_mesh(*volume::signed_distance_from_mesh(input, distance, progress), 0.0, progress);
        clock.lap("signed distance");
    } else {
        volume::HollowOptions hollow;
        hollow.wall = options.wall;
        hollow.voxel_size = voxel;
        hollow.memory_budget_bytes = options.memory_budget_bytes;
        hollow.input_name = options.input_name;
        volume::HollowResult hollowed = volume::hollow(input, hollow, progress);
        shells_mesh = std::move(hollowed.mesh);
        result.warnings = std::move(hollowed.warnings);
        if (hollowed.outer_surface_voxel > 0.0) surface_voxel = std::min(voxel, hollowed.outer_surface_voxel);
        clock.lap("hollow");
    }
    result.surface_voxel = surface_voxel;
    progress.stage("level sets");
    const Shells shells = split_shells(shells_mesh);
    if (shells.voids.triangles.empty()) {
        result.warnings.push_back(options.input_name +
                                  ": the part has no cavity, so no powder is trapped: no drain holes are needed and "
                                  "the part is returned solid, undrilled");
        result.drilled = std::move(shells_mesh);
        measure_drained(input, result, clock, progress);
        return result;
    }
    openvdb::FloatGrid::Ptr cavity = level_set_of(shells.voids, voxel);
    if (!traps_powder(*cavity, progress)) {
        result.warnings.push_back(options.input_name +
                                  ": the part's voids are thinner than a voxel, so no powder is trapped: no drain "
                                  "holes are needed and the part is returned undrilled");
        result.drilled = std::move(shells_mesh);
        measure_drained(input, result, clock, progress);
        return result;
    }
    const openvdb::FloatGrid::Ptr part = level_set_of(shells.outer, voxel);
    DrainPlanOptions plan_options = options.plan;
    plan_options.nominal_wall = options.wall;
    plan_options.input_name = options.input_name;
    size_t filled_count = 0;
    double filled_volume = 0.0;
    for (;;) {
        result.shell = openvdb::tools::csgDifferenceCopy(*part, *cavity);
        progress.check();
        clock.lap("level sets");
        result.plan = plan_drain_holes(*part, *cavity, *result.shell, plan_options, progress);
        clock.add_laps(result.plan.timings);
        if (result.plan.cavities_without_site.empty()) break;
        cavity = fill_cavities_at(*cavity, result.plan.cavities_without_site, filled_count, filled_volume,
                                  result.filled_cavities);
        if (cavity && !traps_powder(*cavity, progress)) cavity.reset();
        if (!cavity) break;
    }
    if (filled_count > 0) {
        std::ostringstream message;
        message << options.input_name << ": " << filled_count << (filled_count == 1 ? " cavity" : " cavities")
                << " (" << filled_volume << " mm^3) too small or thin for a drain hole of "
                << plan_options.hole_diameter << " mm to pass cleanly through the wall "
                << (filled_count == 1 ? "is" : "are") << " left solid"
                << (cavity ? "" : ": the part is returned solid, undrilled") << " (a smaller hole diameter may fit)";
        result.warnings.push_back(message.str());
    }
    if (!cavity) {
        result.shell.reset();
        result.plan = DrainPlan{};
        result.drilled = shells.outer;
        measure_drained(input, result, clock, progress);
        return result;
    }
    result.has_cavity = true;

    std::vector<volume::DrillCylinder> cylinders;
    for (const DrainHole& hole : result.plan.holes) {
        volume::DrillCylinder cylinder;
        const double back = 0.5 * hole.diameter;
        for (int k = 0; k < 3; ++k) {
            cylinder.start[k] = hole.center[k] - back * hole.axis[k];
            cylinder.end[k] = hole.center[k] + hole.depth * hole.axis[k];
        }
        cylinder.radius = 0.5 * hole.diameter;
        cylinders.push_back(cylinder);
    }
    // Planned at the hollowing's voxel; drilled into the part and the final
    // cavity taken to the outer surface's voxel when that is finer, and
    // finer again where the drilled part was not the input's model.
    for (int refinement = 0;; ++refinement) {
        openvdb::FloatGrid::ConstPtr shell = result.shell;
        if (surface_voxel < voxel) {
            shell = shell_at(shells.outer, *cavity, surface_voxel);
            progress.check();
            clock.lap("level sets at the surface's voxel");
        }
        result.surface_voxel = surface_voxel;
        const openvdb::FloatGrid::Ptr drilled = volume::drill_holes(*shell, cylinders, progress);
        clock.lap("drill");
        result.drilled = volume::extract_mesh(*drilled, 0.0, progress);
        clock.lap("extract");
        measure_drained(input, result, clock, progress);
        if (refinement == kSurfaceRefinements || !volume::finer_may_pass(result.fidelity, result.fidelity_limits))
            return result;
        result.warnings.push_back(options.input_name + ": at voxel " + figure_text(surface_voxel) +
                                  " mm the drilled part was not the input's model (" + result.fidelity.defect +
                                  "), so it was meshed again at " + figure_text(0.5 * surface_voxel) + " mm");
        surface_voxel *= 0.5;
    }
}

}  // namespace

DrainPartResult drain_part(const Mesh& input, const DrainPartOptions& options, Progress& progress) {
    DrainPartResult result = hollow_plan_and_drill(input, options, progress);
    volume::require_faithful(result.fidelity, options.input_name, "drained part");
    return result;
}

}  // namespace fabvdb::powder
