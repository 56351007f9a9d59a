//! A two-piece mold around one part (see mold_assembly.h).
#include "surface/mold_assembly.h"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_invoke.h>

#include "core/error.h"
#include "surface/clear_grid_origin.h"
#include "surface/face_sweep.h"
#include "surface/float_rounding.h"
#include "surface/height_field_solid.h"
#include "surface/mesh_boolean.h"
#include "surface/parting_surface.h"
#include "volume/aligned_frame.h"
#include "volume/mesh_shells.h"

namespace fabvdb::surface {

namespace {

double normal_z(const Mesh& mesh, const Triangle& t) {
    const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

// Vertices shared by an upward- and a downward-facing triangle: the part's
// silhouette along Z, which is its parting line.
std::vector<Vec3> silhouette(const Mesh& part) {
    std::vector<char> up(part.vertices.size(), 0), down(part.vertices.size(), 0);
    for (const Triangle& t : part.triangles) {
        const bool faces_up = normal_z(part, t) > 0;
        for (uint32_t v : t) (faces_up ? up : down)[v] = 1;
    }
    std::vector<Vec3> points;
    for (size_t v = 0; v < part.vertices.size(); ++v)
        if (up[v] && down[v]) points.push_back(part.vertices[v]);
    return points;
}

// Lowest and highest z where the vertical line through (x, y) meets the part;
// false when it misses.
bool column_extent(const Mesh& part, double x, double y, double& z_lo, double& z_hi) {
    bool hit = false;
    for (const Triangle& t : part.triangles) {
        const Vec3 &a = part.vertices[t[0]], &b = part.vertices[t[1]], &c = part.vertices[t[2]];
        if (x < std::min({a[0], b[0], c[0]}) || x > std::max({a[0], b[0], c[0]}) ||
            y < std::min({a[1], b[1], c[1]}) || y > std::max({a[1], b[1], c[1]}))
            continue;
        const double det = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        if (det == 0.0) continue;
        const double u = ((x - a[0]) * (c[1] - a[1]) - (y - a[1]) * (c[0] - a[0])) / det;
        const double v = ((b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0])) / det;
        if (u < 0 || v < 0 || u + v > 1) continue;
        const double z = a[2] + u * (b[2] - a[2]) + v * (c[2] - a[2]);
        z_lo = hit ? std::min(z_lo, z) : z;
        z_hi = hit ? std::max(z_hi, z) : z;
        hit = true;
    }
    return hit;
}

Mesh box_mesh(const Vec3& lo, const Vec3& hi) {
    Mesh box;
    for (int i = 0; i < 8; ++i) box.vertices.push_back({(i & 1) ? hi[0] : lo[0], (i & 2) ? hi[1] : lo[1], (i & 4) ? hi[2] : lo[2]});
    const uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads) {
        box.triangles.push_back({q[0], q[1], q[2]});
        box.triangles.push_back({q[0], q[2], q[3]});
    }
    return box;
}

// The mold around `local` (one part, or parts side by side along X, in the
// frame where d is +Z), in that frame; `parting_lines` one per part.
MoldPair assemble_in_frame(const Mesh& local, const std::vector<std::vector<Vec3>>& parting_lines,
                           const MoldOptions& options, Progress& progress) {
    if (!(options.margin > 0)) throw Error(FABVDB_ERR_INVALID_ARGUMENT, "the mold margin must be > 0");
    progress.stage("mold: parting surface");
    const BoundingBox box = bounding_box(local);
    const double margin = options.margin;
    const double step = options.grid_step > 0 ? options.grid_step : margin / 8;

    // The block reaches at least `margin` past the part, and up to a grid
    // step more: its grid lines, which the parting surface's edges and the
    // channels' walls follow, keep as far as they can from the part's
    // vertices. A line at a fixed distance from the part's bounding box
    // would run through its extreme vertices (with the default step, a
    // whole number of steps from the block's side), and on a part meshed on
    // a voxel grid the mold frame keeps, those lie in one plane only within
    // a float step: the exact booleans would leave slivers no double or
    // float coordinates can hold apart.
    Vec3 block_lo, block_hi;
    int block_cells[2];
    std::vector<double> coordinates(local.vertices.size());
    for (int k = 0; k < 2; ++k) {
        for (size_t v = 0; v < local.vertices.size(); ++v) coordinates[v] = local.vertices[v][k];
        block_lo[k] = clear_grid_origin(coordinates, box.min[k] - margin, step);
        block_cells[k] = int(std::ceil((box.max[k] + margin - block_lo[k]) / step));
        block_hi[k] = block_lo[k] + block_cells[k] * step;
    }
    block_lo[2] = box.min[2] - margin;
    block_hi[2] = box.max[2] + margin;

    HeightGrid grid;
    grid.x0 = block_lo[0] - step;
    grid.y0 = block_lo[1] - step;
    grid.step = step;
    grid.nx = block_cells[0] + 2;
    grid.ny = block_cells[1] + 2;
    std::vector<Vec3> parting_line;
    for (const auto& line : parting_lines) parting_line.insert(parting_line.end(), line.begin(), line.end());
    interpolate_parting_surface(parting_line, block_lo[2] + margin / 4, block_hi[2] - margin / 4, {}, grid);
    // Over every cell the parting line crosses, the surface stays a quarter
    // step above each of the line's points in it (a cell's heights are
    // interpolated from its corners, so raising the corners suffices). A
    // surface through the line or a hair beside it would give the booleans
    // points a rounding error apart, and needle triangles there that cross
    // after rounding; instead the bottom piece gets a clean lip of that
    // height along the parting line.
    const double lip = 0.25 * step;
    for (const Vec3& p : parting_line) {
        const int i = std::clamp(int(std::floor((p[0] - grid.x0) / step)), 0, grid.nx - 1);
        const int j = std::clamp(int(std::floor((p[1] - grid.y0) / step)), 0, grid.ny - 1);
        for (int dj = 0; dj < 2; ++dj)
            for (int di = 0; di < 2; ++di) grid.at(i + di, j + dj) = std::max(grid.at(i + di, j + dj), p[2] + lip);
    }
    const MoldFeatureSizes sizes = mold_feature_sizes(margin);
    const MoldFeatures features = place_mold_features(parting_lines, grid, block_lo, block_hi, box.min, box.max, sizes);
    progress.check();

    progress.stage("mold: solids");
    const size_t vertex_count = grid.z.size();
    std::vector<char> block(size_t(grid.nx) * size_t(grid.ny), 0);
    for (int j = 1; j + 1 < grid.ny; ++j)
        for (int i = 1; i + 1 < grid.nx; ++i) block[size_t(j) * size_t(grid.nx) + size_t(i)] = 1;
    // The block halves and the swept volumes reach past the block's top and
    // bottom by different amounts, and a final cut by the block's slab makes
    // those faces: no two solids ever share a plane there, whose overlapping
    // faces would leave near-coincident points after rounding.
    const Mesh block_below =
        height_field_solid(grid, block, std::vector<double>(vertex_count, block_lo[2] - margin), grid.z);
    const Mesh block_above =
        height_field_solid(grid, block, grid.z, std::vector<double>(vertex_count, block_hi[2] + margin));
    const Mesh slab = box_mesh({block_lo[0] - margin, block_lo[1] - margin, block_lo[2]},
                               {block_hi[0] + margin, block_hi[1] + margin, block_hi[2]});

    // Channels straddle the parting surface, their half width measured
    // across it (along Z it grows with the slope: on a steep parting
    // surface a fixed height would pinch the channel to a slit); where they
    // reach over the part they take its whole column, so both pieces stay
    // height fields.
    std::vector<double> channel_lo(vertex_count), channel_hi(vertex_count);
    for (int j = 0; j <= grid.ny; ++j)
        for (int i = 0; i <= grid.nx; ++i) {
            const size_t v = size_t(j) * size_t(grid.nx + 1) + size_t(i);
            const int i0 = std::max(i - 1, 0), i1 = std::min(i + 1, grid.nx);
            const int j0 = std::max(j - 1, 0), j1 = std::min(j + 1, grid.ny);
            const double slope_x = (grid.at(i1, j) - grid.at(i0, j)) / ((i1 - i0) * step);
            const double slope_y = (grid.at(i, j1) - grid.at(i, j0)) / ((j1 - j0) * step);
            const double half_height = sizes.runner_half_width * std::sqrt(1 + slope_x * slope_x + slope_y * slope_y);
            channel_lo[v] = grid.z[v] - half_height;
            channel_hi[v] = grid.z[v] + half_height;
            double z_lo = 0, z_hi = 0;
            if (grid.x(i) >= box.min[0] && grid.x(i) <= box.max[0] && grid.y(j) >= box.min[1] &&
                grid.y(j) <= box.max[1] && column_extent(local, grid.x(i), grid.y(j), z_lo, z_hi)) {
                channel_lo[v] = std::min(channel_lo[v], z_lo - sizes.runner_half_width);
                channel_hi[v] = std::max(channel_hi[v], z_hi + sizes.runner_half_width);
            }
        }
    const Mesh channels = height_field_solid(grid, features.channel_cells, channel_lo, channel_hi);
    const Mesh swept_up = sweep_faces_to_plane(local, true, block_hi[2] + 2 * margin);
    const Mesh swept_down = sweep_faces_to_plane(local, false, block_lo[2] - 2 * margin);
    progress.check();

    // The two pieces are independent: made at once, one per core.
    progress.stage("mold: pieces");
    Mesh bottom, top;
    tbb::parallel_invoke(
        [&] {
            bottom = mesh_boolean(block_below, "the block below the parting surface",
                                  {{BooleanOperation::unite, &swept_down, "the part swept down"},
                                   {BooleanOperation::unite, &features.pins, "the key pins"},
                                   {BooleanOperation::subtract, &swept_up, "the part swept up"},
                                   {BooleanOperation::subtract, &channels, "the runner, sprue and vents"},
                                   {BooleanOperation::intersect, &slab, "the block's slab"}},
                                  progress);
        },
        [&] {
            top = mesh_boolean(block_above, "the block above the parting surface",
                               {{BooleanOperation::unite, &swept_up, "the part swept up"},
                                {BooleanOperation::subtract, &swept_down, "the part swept down"},
                                {BooleanOperation::subtract, &channels, "the runner, sprue and vents"},
                                {BooleanOperation::subtract, &features.holes, "the key holes"},
                                {BooleanOperation::intersect, &slab, "the block's slab"}},
                               progress);
        });

    MoldPair pair;
    pair.top = std::move(top);
    pair.bottom = std::move(bottom);
    pair.channels = channels;
    pair.block_size = {block_hi[0] - block_lo[0], block_hi[1] - block_lo[1], block_hi[2] - block_lo[2]};
    pair.block_center = {0.5 * (block_lo[0] + block_hi[0]), 0.5 * (block_lo[1] + block_hi[1]),
                         0.5 * (block_lo[2] + block_hi[2])};
    pair.gates = features.gates;
    pair.vents = features.vents;
    pair.up = {0, 1, 0};
    return pair;
}

// The pieces as an STL file stores them: float coordinates, rounded without
// folding the slivers the exact booleans leave where solids graze. Crumbs
// the booleans leave there as shells of their own (ycb_mustardbottle: 16
// triangles, 2e-6 mm³, too flat to bound a volume) go first: a shell under
// a millionth of the block's volume is no mold material anyone can print.
void round_pieces_to_float(MoldPair& pair) {
    const double crumb = 1e-6 * pair.block_size[0] * pair.block_size[1] * pair.block_size[2];
    volume::drop_small_or_flat_shells(pair.top, crumb);
    volume::drop_small_or_flat_shells(pair.bottom, crumb);
    pair.top = round_to_float(pair.top, "the top mold piece");
    pair.bottom = round_to_float(pair.bottom, "the bottom mold piece");
}

}  // namespace

MoldPair assemble_mold(const Mesh& part, const Vec3& direction, const MoldOptions& options, Progress& progress) {
    const volume::AlignedFrame frame = volume::aligned_frame(direction);
    const Mesh local = volume::rotate_mesh(part, frame, false);
    MoldPair pair = assemble_in_frame(local, {silhouette(local)}, options, progress);
    pair.top = volume::rotate_mesh(pair.top, frame, true);
    pair.bottom = volume::rotate_mesh(pair.bottom, frame, true);
    pair.channels = volume::rotate_mesh(pair.channels, frame, true);
    round_pieces_to_float(pair);
    pair.block_center = frame.to_world(pair.block_center);
    for (Vec3& gate : pair.gates) gate = frame.to_world(gate);
    for (Vec3& vent : pair.vents) vent = frame.to_world(vent);
    pair.up = frame.e2;
    return pair;
}

MoldPair assemble_common_mold(const std::vector<Mesh>& parts, const std::vector<Vec3>& directions,
                              const MoldOptions& options, Progress& progress, std::vector<Vec3>& offsets) {
    if (parts.empty() || parts.size() != directions.size())
        throw Error(FABVDB_ERR_INVALID_ARGUMENT, "a common mold needs one direction per part");
    Mesh row;
    std::vector<std::vector<Vec3>> parting_lines;
    offsets.clear();
    double next_x = 0;
    for (size_t p = 0; p < parts.size(); ++p) {
        Mesh local = volume::rotate_mesh(parts[p], volume::aligned_frame(directions[p]), false);
        const BoundingBox box = bounding_box(local);
        // A margin between neighbours, bottoms on one line, mid-heights level.
        const Vec3 offset{next_x - box.min[0], -box.min[1], -0.5 * (box.min[2] + box.max[2])};
        next_x += box.max[0] - box.min[0] + options.margin;
        for (Vec3& v : local.vertices) v = {v[0] + offset[0], v[1] + offset[1], v[2] + offset[2]};
        offsets.push_back(offset);
        parting_lines.push_back(silhouette(local));
        append(row, local);
    }
    MoldPair pair = assemble_in_frame(row, parting_lines, options, progress);
    round_pieces_to_float(pair);
    return pair;
}

}  // namespace fabvdb::surface
