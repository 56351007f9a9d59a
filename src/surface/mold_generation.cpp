//! Mold generation for a decomposed model (see mold_generation.h).
#include "surface/mold_generation.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/stage_clock.h"
#include "surface/float_rounding.h"
#include "surface/input_to_parts_distance.h"
#include "surface/overhang_deformation.h"
#include "volume/detail_restoration.h"
#include "volume/double_height_field_mesh.h"
#include "volume/hand_over_runs.h"
#include "volume/keep_lost_surface.h"
#include "volume/signed_distance.h"
#include "volume/sweep.h"

namespace fabvdb::surface {

namespace {

// Each part given its outer surface back from the input (restore_part_details)
// and the input surface no part holds kept as tubes (keep_lost_surface).
std::vector<openvdb::FloatGrid::Ptr> restored_parts(const Mesh& input, const openvdb::FloatGrid::Ptr& input_grid,
                                                    const DecomposedModel& model, int half_band_voxels,
                                                    const MoldGenerationOptions& options, MoldGeneration& result,
                                                    StageClock& clock, Progress& progress) {
    std::vector<Mesh> solids;
    for (const DecomposedPart& part : model.parts) solids.push_back(part.solid);
    // δ, how far the input may lie outside its low-res part: ω, and no less
    // than the default ω (3% of the longest side), which a solid part's ω,
    // as deep as the part is thick, may be far under.
    const BoundingBox box = bounding_box(input);
    const double longest = std::max({box.max[0] - box.min[0], box.max[1] - box.min[1], box.max[2] - box.min[2]});
    volume::DetailRestorationOptions restoration;
    restoration.shell_thickness = model.shell_thickness;
    restoration.reach = std::max(model.shell_thickness, 0.03 * longest);
    restoration.input_name = options.input_name;
    std::vector<openvdb::FloatGrid::Ptr> restored =
        volume::restore_part_details(*input_grid, solids, restoration, progress);
    clock.lap("detail restoration");
    // Input surface no restored part holds (fins, sheets and tips thinner
    // than a voxel, or left so by the split between two parts) comes back a
    // voxel thick in the part nearest to it, if within δ of it as restoration
    // reaches; a voxel out is within the level sets' own rounding of sharp
    // edges (bench/corpus; docs/design/geometry.md).
    volume::KeepLostSurfaceOptions keep;
    keep.tolerance = result.voxel_size;
    keep.radius = result.voxel_size;
    keep.reach = restoration.reach;
    keep.solid = input_grid.get();
    keep.half_band_voxels = half_band_voxels;
    volume::LostSurface lost;
    restored = volume::keep_lost_surface(restored, input, keep, progress, &lost);
    result.lost_triangles = lost.lost_triangles;
    clock.lap("lost surface");
    return restored;
}

// Small gaps closed by deformation before anything is swept; each part's
// gaps must be empty of the other parts (as restored or as deformed).
std::vector<OverhangDeformation> deform_parts(std::vector<openvdb::FloatGrid::Ptr>& parts,
                                              const DecomposedModel& model, double voxel_size,
                                              const MoldGenerationOptions& options, Progress& progress) {
    std::vector<OverhangDeformation> deformations(model.parts.size());
    OverhangDeformationOptions deformation_options;
    deformation_options.max_displacement = options.max_deformation > 0 ? options.max_deformation : 0.5 * voxel_size;
    for (size_t p = 0; p < model.parts.size(); ++p) {
        std::vector<openvdb::FloatGrid::ConstPtr> others;
        for (size_t q = 0; q < model.parts.size(); ++q)
            if (q != p) others.push_back(parts[q]);
        deformations[p] = deform_overhangs(*parts[p], model.parts[p].direction, others, deformation_options, progress);
        parts[p] = deformations[p].part;
    }
    return deformations;
}

// Every part made a double height field along its direction: parts in
// order, each keeping out of the parts made before it (as made) and of those
// still to come (as its own material), so no two overlap; then the runs that
// other parts split off a part go to those parts, and all are swept again
// from the new split.
struct SweptParts {
    std::vector<openvdb::FloatGrid::Ptr> made;
    std::vector<volume::SweepStats> stats;
    volume::HandOver handed;
};

SweptParts swept_parts(const std::vector<openvdb::FloatGrid::Ptr>& parts, const DecomposedModel& model,
                       const openvdb::FloatGrid& input_grid, const MoldGenerationOptions& options, StageClock& clock,
                       Progress& progress) {
    volume::SweepOptions sweep_options;
    sweep_options.memory_budget_bytes = options.memory_budget_bytes;
    sweep_options.kept_surface = &input_grid;
    SweptParts swept;
    swept.stats.resize(model.parts.size());
    const auto sweep_all = [&](const std::vector<openvdb::FloatGrid::Ptr>& own) {
        std::vector<openvdb::FloatGrid::Ptr> made(model.parts.size());
        for (size_t p = 0; p < model.parts.size(); ++p) {
            std::vector<openvdb::FloatGrid::ConstPtr> keep_out;
            for (size_t q = 0; q < model.parts.size(); ++q)
                if (q != p) keep_out.push_back(q < p ? made[q] : own[q]);
            made[p] = volume::sweep_double_height_field(*own[p], model.parts[p].direction, keep_out, sweep_options,
                                                        progress, &swept.stats[p]);
        }
        return made;
    };
    swept.made = sweep_all(parts);
    clock.lap("sweep");
    swept.handed = volume::hand_over_unkept_runs(parts, swept.made, &input_grid, progress);
    clock.lap("hand-over");
    if (std::any_of(swept.handed.given.begin(), swept.handed.given.end(), [](double v) { return v > 0; })) {
        swept.made = sweep_all(swept.handed.parts);
        clock.lap("second sweep");
    }
    return swept;
}

// The cast parts' figures, measured on them as their STL files store them:
// the distance from the input (overall and per part) and the fidelity gate.
void measure_cast_parts(const Mesh& input, const MoldGenerationOptions& options, MoldGeneration& result,
                        Progress& progress) {
    std::vector<const Mesh*> cast_parts;
    for (const CastPart& cast : result.parts) cast_parts.push_back(&cast.part);
    const InputToParts fidelity = input_to_parts_distance(input, cast_parts, result.voxel_size, progress);
    result.max_distance = fidelity.max;
    result.mean_distance = fidelity.mean;
    for (size_t p = 0; p < result.parts.size(); ++p) {
        result.parts[p].max_distance = fidelity.part_max[p];
        result.parts[p].mean_distance = fidelity.part_mean[p];
    }
    Mesh assembled;
    for (const Mesh* part : cast_parts) append(assembled, *part);
    result.fidelity_limits.distance = 0.01 * result.diagonal;
    result.fidelity_limits.far_share = 0.05;
    result.fidelity_limits.volume = false;  // a shell's parts hold its wall, not the solid
    result.fidelity = volume::measure_fidelity(input, assembled, result.fidelity_limits, progress);
    volume::require_faithful(result.fidelity, options.input_name, "set of cast parts");
}

}  // namespace

MoldGeneration generate_molds(const Mesh& input, const DecomposedModel& model, const MoldGenerationOptions& options,
                              Progress& progress) {
    if (model.parts.empty()) throw Error(FABVDB_ERR_BAD_INPUT, "the decomposition has no parts");
    if (!(options.voxel_size >= 0) || !std::isfinite(options.voxel_size))
        throw Error(FABVDB_ERR_INVALID_ARGUMENT, "the voxel size must be >= 0");
    if (!(options.max_deformation >= 0) || !std::isfinite(options.max_deformation))
        throw Error(FABVDB_ERR_INVALID_ARGUMENT, "the maximum deformation must be >= 0");
    MoldGeneration result;
    result.diagonal = bounding_box(input).diagonal();
    result.voxel_size = options.voxel_size > 0 ? options.voxel_size : result.diagonal / 250.0;
    StageClock clock(result.seconds);

    // The input's band reaches below the shell, so the inner surface at depth
    // ω is in it.
    volume::SignedDistanceOptions distance;
    distance.voxel_size = result.voxel_size;
    distance.half_band_voxels = int(std::ceil(model.shell_thickness / result.voxel_size)) + 3;
    distance.memory_budget_bytes = options.memory_budget_bytes;
    distance.input_name = options.input_name;
    const openvdb::FloatGrid::Ptr input_grid = volume::signed_distance_from_mesh(input, distance, progress);
    clock.lap("input level set");

    std::vector<openvdb::FloatGrid::Ptr> restored =
        restored_parts(input, input_grid, model, distance.half_band_voxels, options, result, clock, progress);
    std::vector<OverhangDeformation> deformations(model.parts.size());
    if (options.deform_overhangs) {
        deformations = deform_parts(restored, model, result.voxel_size, options, progress);
        clock.lap("overhang deformation");
    }
    const SweptParts swept = swept_parts(restored, model, *input_grid, options, clock, progress);

    // The parts' surfaces are read off the input where they hold it.
    const volume::SurfaceRayCaster input_rays(input);
    volume::InputSurface input_surface;
    input_surface.level_set = input_grid.get();
    input_surface.mesh = &input;
    input_surface.rays = &input_rays;
    input_surface.orientation = signed_volume(input) < 0 ? -1 : 1;
    for (size_t p = 0; p < model.parts.size(); ++p) {
        CastPart cast;
        cast.id = model.parts[p].id;
        cast.direction = model.parts[p].direction;
        cast.part = volume::double_height_field_mesh(*swept.made[p], progress, &input_surface);
        if (cast.part.triangles.empty()) {
            // A sliver the other parts took whole: nothing of its own to cast.
            result.vanished_parts.push_back(cast.id);
            continue;
        }
        const OverhangDeformation& deformation = deformations[p];
        const volume::SweepStats& stats = swept.stats[p];
        cast.deformed_volume_change = deformation.volume_after - deformation.volume_before;
        cast.given_volume = swept.handed.given[p];
        cast.received_volume = swept.handed.received[p];
        cast.restored_volume = stats.volume_before - cast.deformed_volume_change - cast.received_volume +
                               cast.given_volume;
        cast.deformation_handles = deformation.handles;
        cast.deformation_max = deformation.max_displacement;
        cast.deformation_mean = deformation.mean_displacement;
        cast.removed_by_keep_out = stats.removed_by_keep_out;
        cast.columns_trimmed = stats.columns_trimmed;
        clock.lap("part surface");
        if (!options.common_mold) {
            cast.mold = assemble_mold(cast.part, cast.direction, options.mold, progress);
            clock.lap("mold assembly");
        }
        result.parts.push_back(std::move(cast));
        progress.stage("mold: parts");
        progress.update(double(p + 1) / double(model.parts.size()));
    }
    if (result.parts.empty())
        throw Error(FABVDB_ERR_BAD_INPUT, options.input_name + ": every part vanished in the sweep, each taken by "
                                                              "the others: the decomposition leaves nothing to cast");
    if (options.common_mold) {
        std::vector<Mesh> parts;
        std::vector<Vec3> directions, offsets;
        for (const CastPart& cast : result.parts) {
            parts.push_back(cast.part);
            directions.push_back(cast.direction);
        }
        result.common_mold = assemble_common_mold(parts, directions, options.mold, progress, offsets);
        for (size_t p = 0; p < offsets.size(); ++p) result.parts[p].common_mold_offset = offsets[p];
        clock.lap("mold assembly");
    }
    // The parts as their STL files store them; the molds were made around
    // the exact parts (rounding first could turn a triangle at the
    // silhouette over and move the parting line).
    for (CastPart& cast : result.parts) {
        cast.part = round_to_float(cast.part, "part " + std::to_string(cast.id));
        cast.volume = signed_volume(cast.part);
        cast.added_volume = cast.volume - cast.restored_volume - cast.deformed_volume_change -
                            cast.received_volume + cast.given_volume;
    }
    measure_cast_parts(input, options, result, progress);
    clock.lap("distance to the input");
    return result;
}

}  // namespace fabvdb::surface
