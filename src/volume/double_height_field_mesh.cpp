//! Exact double-height-field surface of a swept level set (see
//! double_height_field_mesh.h).
#include "volume/double_height_field_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include <openvdb/tools/Dense.h>
#include <openvdb/tools/Interpolation.h>
#include <tbb/parallel_for.h>

#include "volume/column_runs.h"
#include "core/vec3_ops.h"
#include "volume/mesh_shells.h"

namespace fabvdb::volume {

namespace {

//! One index column: where it is inside, and how near it comes when it is not.
struct Column {
    bool inside = false;
    float lo = 0, hi = 0;    //!< index z of the inside run's ends
    float minimum = 0;       //!< smallest value along the column
    float at_minimum = 0;    //!< index z where it is smallest
};

//! How far (index units, voxels) a run end on the input surface may be from
//! the input's crossing it moves to: the level set's zero is within a voxel
//! of the surface except at sharp edges and corners, which it cuts by up to
//! 0.95 of a voxel.
constexpr double snap_reach = 1.5;

//! Where a line along the column axis crosses the input: index z, and which
//! way the input's outside lies (+1 toward +d, −1 toward −d, 0 grazing).
struct Crossing {
    double z;
    int facing;
};

//! Lines along the block's index z axis against the input's triangles.
class InputLines {
public:
    InputLines(const InputSurface& input, const openvdb::math::Transform& transform, const openvdb::Coord& origin,
               size_t nz)
        : input_(input), transform_(transform), origin_(origin), nz_(nz) {
        const openvdb::Vec3d a = transform.indexToWorld(openvdb::Vec3d(0, 0, 0));
        const openvdb::Vec3d b = transform.indexToWorld(openvdb::Vec3d(0, 0, 1));
        axis_ = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    }

    //! The crossings of the line at block offsets (x, y), ordered by z; one
    //! per place where the line passes from one side of the surface to the
    //! other (a crossing through an edge that two triangles report once).
    std::vector<Crossing> crossings(double x, double y) const {
        const openvdb::Vec3d o =
            transform_.indexToWorld(openvdb::Vec3d(origin_.x() + x, origin_.y() + y, double(origin_.z()) - 2));
        const std::vector<RayHit> hits =
            input_.rays->all_hits({o[0], o[1], o[2]}, axis_, 0.0, double(nz_) + 4.0);
        std::vector<Crossing> result;
        for (const RayHit& hit : hits) {
            const Triangle& t = input_.mesh->triangles[hit.triangle];
            const Vec3 n = cross(input_.mesh->vertices[t[1]] - input_.mesh->vertices[t[0]],
                                 input_.mesh->vertices[t[2]] - input_.mesh->vertices[t[0]]);
            const double along = dot(n, axis_) * input_.orientation;
            const int facing = along > 0 ? 1 : along < 0 ? -1 : 0;
            const double z = double(origin_.z()) - 2 + hit.t;
            if (!result.empty() && result.back().facing == facing && z - result.back().z < 1e-4) continue;
            result.push_back({z, facing});
        }
        return result;
    }

private:
    const InputSurface& input_;
    const openvdb::math::Transform& transform_;
    openvdb::Coord origin_;
    size_t nz_;
    Vec3 axis_;
};

//! The crossing facing `facing` nearest to `z` within snap_reach, or `z`.
double nearest_crossing(const std::vector<Crossing>& crossings, double z, int facing) {
    double best = z, best_distance = snap_reach;
    for (const Crossing& c : crossings)
        if (c.facing == facing && std::abs(c.z - z) <= best_distance) best = c.z, best_distance = std::abs(c.z - z);
    return best;
}

//! Whether a crossing lies within [lo − snap_reach, hi + snap_reach]; if so
//! `middle` receives the middle of the lowest and highest such crossing.
bool crosses_within(const std::vector<Crossing>& crossings, double lo, double hi, double* middle) {
    double low = INFINITY, high = -INFINITY;
    for (const Crossing& c : crossings)
        if (c.z >= lo - snap_reach && c.z <= hi + snap_reach) low = std::min(low, c.z), high = std::max(high, c.z);
    if (low > high) return false;
    if (middle) *middle = 0.5 * (low + high);
    return true;
}

//! The column's kept run (column_runs.h) and its minimum.
Column scan_column(const float* column, size_t nz, float z0, const SurfaceCrossings& crossings, int i, int j) {
    Column c;
    size_t k_min = 0;
    for (size_t k = 1; k < nz; ++k)
        if (column[k] < column[k_min]) k_min = k;
    c.minimum = column[k_min];
    c.at_minimum = z0 + float(k_min);
    const std::vector<Run> runs = inside_runs(column, nz);
    if (runs.empty()) return c;
    const Run& kept = runs[kept_run(runs, crossings, i, j)];
    c.inside = true;
    c.lo = z0 + float(zero_crossing(column, kept.start - 1));
    c.hi = z0 + float(zero_crossing(column, kept.end - 1));
    return c;
}

//! Moves each inside column's ends that lie on the input surface (the
//! input's level set within snap_reach voxels of zero there) to the input's
//! nearest crossing facing the same way, when one is within snap_reach and
//! the column stays a run of positive length.
void snap_to_input(std::vector<Column>& columns, int ny, const openvdb::math::Transform& transform,
                   const openvdb::Coord& origin, const openvdb::FloatGrid& level_set, const InputLines& lines,
                   Progress& progress) {
    const double reach = snap_reach * level_set.voxelSize()[0];
    tbb::parallel_for(tbb::blocked_range<size_t>(0, columns.size(), 256), [&](const tbb::blocked_range<size_t>& r) {
        if (progress.cancelled()) return;
        const openvdb::FloatGrid::ConstAccessor accessor = level_set.getConstAccessor();
        const auto on_input = [&](int i, int j, double z) {
            const openvdb::Vec3d world =
                transform.indexToWorld(openvdb::Vec3d(origin.x() + i, origin.y() + j, z));
            return std::abs(openvdb::tools::BoxSampler::sample(accessor, level_set.worldToIndex(world))) <= reach;
        };
        for (size_t c = r.begin(); c != r.end(); ++c) {
            Column& column = columns[c];
            if (!column.inside) continue;
            const int i = int(c / size_t(ny)), j = int(c % size_t(ny));
            const bool low_on_input = on_input(i, j, column.lo), high_on_input = on_input(i, j, column.hi);
            if (!low_on_input && !high_on_input) continue;
            const std::vector<Crossing> crossings = lines.crossings(i, j);
            const double lo = low_on_input ? nearest_crossing(crossings, column.lo, -1) : column.lo;
            const double hi = high_on_input ? nearest_crossing(crossings, column.hi, 1) : column.hi;
            if (hi - lo < 1e-3) continue;
            column.lo = float(lo);
            column.hi = float(hi);
        }
    });
    progress.check();
}

}  // namespace

Mesh double_height_field_mesh(const openvdb::FloatGrid& swept, Progress& progress, const InputSurface* input) {
    progress.stage("mold: part surface");
    openvdb::CoordBBox box = swept.evalActiveVoxelBoundingBox();
    if (box.empty()) return Mesh{};
    box.expand(1);
    const openvdb::Coord dim = box.dim();
    const int nx = dim.x(), ny = dim.y();
    const size_t nz = size_t(dim.z());
    std::vector<Column> columns(size_t(nx) * size_t(ny));
    {
        openvdb::tools::Dense<float> dense(box);
        openvdb::tools::copyToDense(swept, dense);
        progress.check();
        const float* data = dense.data();
        const float z0 = float(box.min().z());
        const openvdb::FloatGrid* kept_surface = input ? input->level_set : nullptr;
        const SurfaceCrossings crossings(swept.transform(), box.min(), kept_surface);
        for (size_t c = 0; c < columns.size(); ++c) {
            const int i = int(c / size_t(ny)), j = int(c % size_t(ny));
            columns[c] = scan_column(data + c * nz, nz, z0, crossings, i, j);
        }
    }
    progress.update(0.3);
    std::optional<InputLines> lines;
    if (input && input->rays && input->mesh && input->level_set) {
        lines.emplace(*input, swept.transform(), box.min(), nz);
        snap_to_input(columns, ny, swept.transform(), box.min(), *input->level_set, *lines, progress);
    }
    progress.update(0.5);
    const auto column_at = [&](int i, int j) -> const Column& { return columns[size_t(i) * size_t(ny) + size_t(j)]; };

    Mesh mesh;
    const openvdb::math::Transform& transform = swept.transform();
    const auto add_vertex = [&](double i, double j, double z) {
        const openvdb::Vec3d p =
            transform.indexToWorld(openvdb::Vec3d(i + box.min().x(), j + box.min().y(), z));
        mesh.vertices.push_back({p[0], p[1], p[2]});
        return uint32_t(mesh.vertices.size() - 1);
    };
    const uint32_t none = UINT32_MAX;
    std::vector<uint32_t> top(columns.size(), none), bottom(columns.size(), none);
    const auto column_vertices = [&](int i, int j) {
        const size_t c = size_t(i) * size_t(ny) + size_t(j);
        if (top[c] == none) {
            top[c] = add_vertex(i, j, columns[c].hi);
            bottom[c] = add_vertex(i, j, columns[c].lo);
        }
        return std::array<uint32_t, 2>{top[c], bottom[c]};
    };
    // Contour vertex on the grid edge from column (i, j) along x (axis 0) or y (axis 1).
    std::vector<uint32_t> contour(2 * columns.size(), none);
    const auto contour_vertex = [&](int i, int j, int axis) {
        uint32_t& id = contour[2 * (size_t(i) * size_t(ny) + size_t(j)) + size_t(axis)];
        if (id != none) return id;
        const int i2 = i + (axis == 0), j2 = j + (axis == 1);
        const Column &a = column_at(i, j), &b = column_at(i2, j2);
        const Column& in = a.inside ? a : b;
        const Column& out = a.inside ? b : a;
        // Fraction from the inside column to the outside one, kept off the
        // columns so no triangle degenerates.
        float t = std::clamp(in.minimum / (in.minimum - out.minimum), 0.05f, 0.95f);
        float z = std::clamp((1 - t) * 0.5f * (in.lo + in.hi) + t * out.at_minimum, in.lo, in.hi);
        if (lines) {
            // The input's silhouette: the outside column's line misses the
            // input near the inside column's run, so bisect toward it.
            const int ii = a.inside ? i : i2, ij = a.inside ? j : j2;
            const int oi = a.inside ? i2 : i, oj = a.inside ? j2 : j;
            if (!crosses_within(lines->crossings(oi, oj), in.lo, in.hi, nullptr)) {
                double inside_at = 0, outside_at = 1, middle = 0;
                bool found = false;
                for (int step = 0; step < 6; ++step) {
                    const double s = 0.5 * (inside_at + outside_at);
                    double m = 0;
                    if (crosses_within(lines->crossings(ii + s * (oi - ii), ij + s * (oj - ij)), in.lo, in.hi, &m))
                        inside_at = s, middle = m, found = true;
                    else
                        outside_at = s;
                }
                if (found) {
                    t = std::clamp(float(inside_at), 0.05f, 0.95f);
                    z = float(middle);
                }
            }
        }
        const double s = a.inside ? t : 1.0 - t;
        id = add_vertex(i + s * (i2 - i), j + s * (j2 - j), z);
        return id;
    };

    bool any_inside = false;
    for (int i = 0; i + 1 < nx; ++i) {
        if (progress.cancelled()) break;
        for (int j = 0; j + 1 < ny; ++j) {
            // Corners counter-clockwise seen from +d; edge k runs from corner k to k + 1.
            const int ci[4] = {i, i + 1, i + 1, i}, cj[4] = {j, j, j + 1, j + 1};
            bool in[4];
            int inside_count = 0;
            for (int k = 0; k < 4; ++k) inside_count += in[k] = column_at(ci[k], cj[k]).inside;
            if (inside_count == 0) continue;
            any_inside = true;
            const auto edge_vertex = [&](int k) {
                const int a = k, b = (k + 1) % 4;
                const int i0 = std::min(ci[a], ci[b]), j0 = std::min(cj[a], cj[b]);
                return contour_vertex(i0, j0, ci[a] != ci[b] ? 0 : 1);
            };
            // A polygon corner: a column (lifted to its top and bottom) or a contour vertex.
            struct Corner {
                int i, j;
                uint32_t contour;
            };
            const auto emit = [&](const std::vector<Corner>& polygon, size_t apex) {
                const auto ids = [&](const Corner& c) {
                    if (c.contour != none) return std::array<uint32_t, 2>{c.contour, c.contour};
                    return column_vertices(c.i, c.j);
                };
                const size_t n = polygon.size();
                const auto a = ids(polygon[apex]);
                for (size_t s = 1; s + 1 < n; ++s) {
                    const auto b = ids(polygon[(apex + s) % n]), c = ids(polygon[(apex + s + 1) % n]);
                    mesh.triangles.push_back({a[0], b[0], c[0]});
                    mesh.triangles.push_back({a[1], c[1], b[1]});
                }
            };
            const bool saddle = inside_count == 2 && in[0] == in[2];
            if (saddle) {
                for (int k = 0; k < 4; ++k)
                    if (in[k])
                        emit({{ci[k], cj[k], none}, {0, 0, edge_vertex(k)}, {0, 0, edge_vertex((k + 3) % 4)}}, 0);
                continue;
            }
            // Any inside corner sees the whole polygon; with three inside
            // corners the one opposite the outside corner gives the fullest fan.
            int apex_corner = 0;
            while (!in[apex_corner]) ++apex_corner;
            for (int k = 0; k < 4; ++k)
                if (!in[k] && inside_count == 3) apex_corner = (k + 2) % 4;
            std::vector<Corner> polygon;
            size_t apex = 0;
            for (int k = 0; k < 4; ++k) {
                if (in[k]) {
                    if (k == apex_corner) apex = polygon.size();
                    polygon.push_back({ci[k], cj[k], none});
                }
                if (in[k] != in[(k + 1) % 4]) polygon.push_back({0, 0, edge_vertex(k)});
            }
            emit(polygon, apex);
        }
    }
    progress.check();
    if (!any_inside) return Mesh{};
    // Islands of a few thin columns are sign noise: crumbs under an eighth of
    // a voxel³ and flat shells, which no writer accepts, go.
    drop_small_or_flat_shells(mesh, std::pow(0.5 * swept.voxelSize()[0], 3));
    return mesh;
}

}  // namespace fabvdb::volume
