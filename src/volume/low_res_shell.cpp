//! low_res_shell: signed_distance_from_mesh → low_res_surface → shell_prisms,
//! with the voxel size from the S_low edge length (and ω, and a closed
//! input's mean thickness) and a narrow band
//! deep enough for the medial depths the thin-feature test needs.
#include "volume/low_res_shell.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/stage_clock.h"
#include "volume/closed_manifold.h"
#include "volume/low_res_surface.h"
#include "volume/memory_estimate.h"
#include "volume/shell_prisms.h"
#include "volume/signed_distance.h"

namespace fabvdb::volume {

LowResShell low_res_shell(const Mesh& input, const LowResShellOptions& options, Progress& progress) {
    if (input.triangles.empty()) throw Error(FABVDB_ERR_BAD_INPUT, options.input_name + ": the mesh has no triangles");
    if (!options.solid && !(options.thickness > 0))
        throw Error(FABVDB_ERR_INVALID_ARGUMENT, "the shell thickness must be > 0");
    LowResShell result;
    StageClock clock(result.seconds);
    const double area = surface_area(input);
    const BoundingBox box = bounding_box(input);
    const double extent = std::max({box.max[0] - box.min[0], box.max[1] - box.min[1], box.max[2] - box.min[2]});
    const double edge = edge_length_for_triangles(area, options.target_triangles);
    if (!(options.solid_depth >= 0)) throw Error(FABVDB_ERR_INVALID_ARGUMENT, "the solid depth must be >= 0");
    const double max_depth = !options.solid             ? 2.0 * options.thickness
                             : options.solid_depth > 0 ? std::min(options.solid_depth, 0.5 * extent)
                                                       : 0.5 * extent;
    result.thickness = options.solid ? max_depth : options.thickness;
    result.voxel_size = options.solid ? 0.5 * edge : std::min(0.5 * edge, options.thickness / 3.0);
    if (area > 0 && is_closed_manifold(input)) {
        const double mean_thickness = 2.0 * std::abs(signed_volume(input)) / area;
        result.voxel_size = std::min(result.voxel_size, std::max(mean_thickness / 2.0, result.voxel_size / 8.0));
    }
    result.half_band_voxels = int(std::ceil(max_depth / result.voxel_size)) + 3;

    SignedDistanceOptions sdf;
    sdf.voxel_size = result.voxel_size;
    sdf.half_band_voxels = result.half_band_voxels;
    sdf.memory_budget_bytes = options.memory_budget_bytes;
    sdf.input_name = options.input_name;
    const openvdb::FloatGrid::Ptr grid = signed_distance_from_mesh(input, sdf, progress);
    clock.lap("signed_distance");
    result.outer = low_res_surface(*grid, options.target_triangles, progress);
    clock.lap("low_res_surface");
    ShellPrisms prisms = shell_prisms(*grid, result.outer.vertices, result.thickness, max_depth, progress);
    result.inner = std::move(prisms.inner);
    result.depth = std::move(prisms.depth);
    if (options.solid) {
        // ω bounds how deep below the surface a solid part reaches: the
        // deepest point of the solid and two voxels more, so that restoring
        // and sweeping a solid part need no band deeper than the part is.
        float lowest = 0.0f;
        for (auto value = grid->cbeginValueOn(); value; ++value) lowest = std::min(lowest, *value);
        result.thickness = std::min(max_depth, -double(lowest) + 2.0 * result.voxel_size);
    }
    clock.lap("shell_prisms");
    return result;
}

}  // namespace fabvdb::volume
