//! shell_from_mesh: volume::low_res_shell → make_shell → the input on it → thin_segments.
#include "surface/shell_from_mesh.h"

#include <algorithm>

#include "core/stage_clock.h"
#include "surface/nearest_outer_triangles.h"
#include "surface/thin_features.h"

namespace fabvdb::surface {

Shell shell_from_mesh(const Mesh& input, const volume::LowResShellOptions& options, Progress& progress,
                      nlohmann::json* stats) {
    volume::LowResShell low = volume::low_res_shell(input, options, progress);
    StageClock clock(low.seconds);
    const size_t triangle_count = low.outer.triangles.size();
    Shell shell = make_shell(std::move(low.outer), std::move(low.inner), std::vector<int>(triangle_count, -1),
                             low.thickness, options.input_name);
    shell.solid = options.solid;
    shell.input = input;
    shell.input_nearest = nearest_outer_triangles(input, shell.outer);
    clock.lap("input_on_shell");
    if (!options.solid) shell.thin_segment = thin_segments(shell.outer, shell.neighbor, low.depth, low.thickness);
    clock.lap("thin_features");
    if (stats) {
        int segments = 0;
        size_t thin_triangles = 0;
        for (int s : shell.thin_segment) {
            segments = std::max(segments, s + 1);
            thin_triangles += s >= 0;
        }
        *stats = {{"voxel_size", low.voxel_size},
                  {"half_band_voxels", low.half_band_voxels},
                  {"low_res_triangles", shell.triangle_count()},
                  {"low_res_vertices", shell.outer.vertices.size()},
                  {"thin_segments", segments},
                  {"thin_triangles", thin_triangles},
                  {"timings", low.seconds}};
    }
    return shell;
}

}  // namespace fabvdb::surface
