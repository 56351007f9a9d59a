//! `fabvdb repair` as one operation (see repair.h).
#include "volume/repair.h"

#include <algorithm>

#include "core/centred_frame.h"
#include "core/error.h"
#include "core/float_coordinates.h"
#include "core/stage_clock.h"
#include "volume/closed_manifold.h"
#include "volume/crossing_pairs.h"
#include "volume/drop_small_shells.h"
#include "volume/extract_mesh.h"
#include "volume/mesh_shells.h"
#include "volume/rebuild_band.h"
#include "volume/snap_to_mesh.h"

namespace fabvdb::volume {

namespace {

// Extracts the surface and snaps it onto the input where it is clean. Walls
// thinner than a voxel extract as two sheets through the same cells, which
// may touch: such a solid is grown by half a voxel (at most twice) until its
// surface is a closed manifold without crossings; still open then, the
// input has no consistent inside (Error(BAD_INPUT)). With snapping, the
// crossing test of the snapped surface covers the extracted one as well.
// Its stages lap on `clock`. Returns the shells the last extraction dropped
// as noise.
uint64_t extract_clean_surface(const OrientedInput& input, const RepairOptions& options, const CentredFrame& frame,
                               RepairResult& result, StageClock& clock, Progress& progress) {
    uint64_t specks = 0;
    for (int attempt = 0;; ++attempt) {
        const bool last = attempt == 2;
        if (attempt > 0) {
            progress.stage("thicken thin walls");
            result.grid = rebuild_band(*result.grid, 0.5 * result.grid->voxelSize()[0],
                                       options.distance.half_band_voxels, progress);
        }
        result.mesh = extract_mesh(*result.grid, options.adaptivity, progress, &specks);
        const bool manifold = is_closed_manifold(result.mesh);
        clock.lap("extract surface");
        if (!manifold && !last) continue;
        if (!manifold)
            throw Error(FABVDB_ERR_BAD_INPUT,
                        options.distance.input_name +
                            ": has no consistent inside: the surface of its signed distance stays open with its "
                            "walls grown by a voxel (shells oriented every which way, or crossing everywhere); "
                            "mend it in a mesh editor, or give --thicken to take it as a sheet");
        bool crossing = false;
        if (options.snap) {
            // Vertices go where a float file stores them, unless floats are
            // coarser there than a thousandth of a voxel: so far off a
            // model is for OBJ or PLY, which hold doubles.
            const double voxel = result.grid->voxelSize()[0];
            const bool floats_hold = float_step_over(bounding_box(result.mesh), frame) <= 1e-3 * voxel;
            const SnapResult snap = snap_to_mesh(result.mesh, input.mesh, *input.closest_triangle, voxel,
                                                 floats_hold ? &frame : nullptr, progress);
            clock.lap("snap");
            result.snapped_vertices = snap.moved_vertices;
            crossing = snap.self_intersecting;
        } else {
            crossing = !crossing_pairs(result.mesh).empty();
            clock.lap("extract surface");
        }
        if (!crossing || last) return specks;
    }
}

}  // namespace

double voxel_size_for_resolution(const Mesh& mesh, int resolution, const std::string& input_name) {
    if (resolution < 8) throw Error(FABVDB_ERR_INVALID_ARGUMENT, "resolution must be >= 8 voxels");
    const BoundingBox box = bounding_box(mesh);
    const double longest = std::max({box.max[0] - box.min[0], box.max[1] - box.min[1], box.max[2] - box.min[2]});
    if (!(longest > 0.0)) throw Error(FABVDB_ERR_BAD_INPUT, input_name + ": the mesh has no extent (no triangle, or all its points coincide)");
    return longest / resolution;
}

RepairResult repair(const Mesh& mesh, const RepairOptions& options, Progress& progress) {
    const CentredFrame frame = centred_frame(mesh);
    RepairResult result = repair_in_frame(to_local(mesh, frame), options, frame, progress);
    to_world(result.mesh, frame);
    if (!frame.identity())
        result.grid->transform().postTranslate(openvdb::Vec3d(frame.offset[0], frame.offset[1], frame.offset[2]));
    return result;
}

RepairResult repair_in_frame(const Mesh& mesh, const RepairOptions& options, const CentredFrame& frame,
                             Progress& progress) {
    RepairResult result;
    OrientedInput input;
    result.grid = signed_distance_from_mesh(mesh, options.distance, progress, &result.distance,
                                            options.extract && options.snap ? &input : nullptr);
    StageClock clock(result.distance.timings);
    // Without a minimum volume no solid shell is dropped from the grid, and
    // the shells are counted as the connected pieces of the extracted
    // surface: cheaper than segmenting the grid, and what the output holds.
    const bool count_on_surface = options.extract && options.min_shell_volume == 0.0;
    if (!count_on_surface) {
        const ShellCounts shells = drop_small_shells(result.grid, options.min_shell_volume, progress);
        clock.lap("shells");
        result.shells_kept = shells.kept;
        result.shells_dropped = shells.dropped;
        if (shells.kept == 0)
            throw Error(FABVDB_ERR_BAD_INPUT, options.distance.input_name + ": every shell is smaller than the minimum shell volume");
    }
    result.distance.active_voxels = result.grid->activeVoxelCount();
    if (!options.extract) return result;
    const uint64_t specks = extract_clean_surface(input, options, frame, result, clock, progress);
    // Surface shells under a voxel's volume are specks of the extraction
    // (a voxel barely below zero), not pieces of the solid: always dropped.
    const double voxel = result.grid->voxelSize()[0];
    const MeshShellCounts surface_shells = drop_small_or_flat_shells(result.mesh, voxel * voxel * voxel);
    clock.lap("shells");
    result.shells_dropped += specks + surface_shells.dropped;
    if (count_on_surface) result.shells_kept = surface_shells.kept;
    return result;
}

}  // namespace fabvdb::volume
