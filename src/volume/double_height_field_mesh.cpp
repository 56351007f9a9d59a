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
    bool lo_on_input = false, hi_on_input = false;  //!< ends moved to the input's crossings
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

//! The input's vertices by grid cell (cell (i, j) spans block offsets
//! [i, i + 1) × [j, j + 1)), each with its block offsets and index z, and
//! whether it lies on the input's silhouette along the column axis (its
//! triangles face both ways along it).
struct CellPoint {
    openvdb::Vec3d at;
    bool silhouette;
};

class CellVertices {
public:
    CellVertices() = default;
    CellVertices(const Mesh& input, double orientation, const openvdb::math::Transform& transform,
                 const openvdb::Coord& origin, int nx, int ny)
        : ny_(ny), start_(size_t(nx) * size_t(ny) + 1, 0) {
        const openvdb::Vec3d a = transform.indexToWorld(openvdb::Vec3d(0, 0, 0));
        const openvdb::Vec3d b = transform.indexToWorld(openvdb::Vec3d(0, 0, 1));
        const Vec3 axis{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        std::vector<uint8_t> faces(input.vertices.size(), 0);  // bit 0: one faces +d, bit 1: one faces −d
        for (const Triangle& t : input.triangles) {
            const Vec3 n = cross(input.vertices[t[1]] - input.vertices[t[0]], input.vertices[t[2]] - input.vertices[t[0]]);
            const double along = orientation * dot(n, axis);
            const uint8_t bit = along > 0 ? 1 : along < 0 ? 2 : 0;
            for (uint32_t v : t) faces[v] |= bit;
        }
        std::vector<std::pair<size_t, CellPoint>> placed;
        for (size_t v = 0; v < input.vertices.size(); ++v) {
            const Vec3& w = input.vertices[v];
            const openvdb::Vec3d p = transform.worldToIndex(openvdb::Vec3d(w[0], w[1], w[2])) - origin.asVec3d();
            const double ci = std::floor(p[0]), cj = std::floor(p[1]);
            if (ci < 0 || cj < 0 || ci >= nx - 1 || cj >= ny - 1) continue;
            placed.push_back({size_t(ci) * size_t(ny) + size_t(cj),
                              {{p[0], p[1], p[2] + origin.z()}, faces[v] == 3}});
        }
        for (const auto& entry : placed) ++start_[entry.first + 1];
        for (size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
        points_.resize(placed.size());
        std::vector<size_t> next(start_.begin(), start_.end() - 1);
        for (const auto& entry : placed) points_[next[entry.first]++] = entry.second;
    }
    //! The vertices in cell (i, j): [first, last).
    std::pair<const CellPoint*, const CellPoint*> of(int i, int j) const {
        if (start_.empty()) return {nullptr, nullptr};
        const size_t c = size_t(i) * size_t(ny_) + size_t(j);
        return {points_.data() + start_[c], points_.data() + start_[c + 1]};
    }

private:
    int ny_ = 0;
    std::vector<size_t> start_;
    std::vector<CellPoint> points_;
};

//! A corner of a cell's polygon: block offsets, its top and bottom index z,
//! and their vertices (the same for a contour vertex).
struct LiftedCorner {
    double i, j, top, bottom;
    uint32_t top_id, bottom_id;
};

struct SteinerPoint {
    double i, j, top, bottom;
};

//! The interpolated top and bottom at (x, y) of the fan from corner `apex`
//! of a convex polygon, when the point lies in it.
std::optional<std::pair<double, double>> fan_heights(const std::vector<LiftedCorner>& polygon, size_t apex, double x,
                                                     double y) {
    const size_t n = polygon.size();
    const LiftedCorner& a = polygon[apex];
    for (size_t s = 1; s + 1 < n; ++s) {
        const LiftedCorner &b = polygon[(apex + s) % n], &c = polygon[(apex + s + 1) % n];
        const double area = (b.i - a.i) * (c.j - a.j) - (c.i - a.i) * (b.j - a.j);
        if (area <= 0) continue;
        const double wb = ((x - a.i) * (c.j - a.j) - (c.i - a.i) * (y - a.j)) / area;
        const double wc = ((b.i - a.i) * (y - a.j) - (x - a.i) * (b.j - a.j)) / area;
        const double wa = 1 - wb - wc;
        if (wa < -1e-9 || wb < -1e-9 || wc < -1e-9) continue;
        return std::make_pair(wa * a.top + wb * b.top + wc * c.top, wa * a.bottom + wb * b.bottom + wc * c.bottom);
    }
    return std::nullopt;
}

//! How far along d (voxels) an input vertex in a cell may lie from the
//! sheet's fan and still be taken as a point of that sheet: a tip along d
//! between columns ends up to about a voxel over the tan of its half-angle
//! past them.
constexpr double bend_reach = 4.0;

//! Where the input bends between a cell's corners (a tip along d, a ridge,
//! a steep slope near the silhouette), the part's sheet over the cell gets
//! one more vertex: of the input's vertices inside the polygon (a twentieth
//! of a voxel from its edges) on a sheet whose corners all lie on the input,
//! the one farthest along d from the fan, when over a twentieth of a voxel
//! and within bend_reach of it, and when a ray there confirms it is the
//! input's crossing nearest to the fan on that sheet (not another layer of
//! the input); the other sheet there is read by the same ray.
std::optional<SteinerPoint> steiner_point(const std::vector<LiftedCorner>& polygon, size_t apex,
                                          std::pair<const CellPoint*, const CellPoint*> candidates,
                                          const InputLines& lines, bool top_on_input, bool bottom_on_input) {
    if (!top_on_input && !bottom_on_input) return std::nullopt;
    const size_t n = polygon.size();
    const double margin = 0.05;
    struct Candidate {
        double x, y, z, top, bottom, error;
        bool on_top;
    };
    std::vector<Candidate> found;
    for (const CellPoint* v = candidates.first; v != candidates.second; ++v) {
        const double x = v->at[0], y = v->at[1], z = v->at[2];
        bool inside = true;
        for (size_t s = 0; s < n && inside; ++s) {
            const LiftedCorner &a = polygon[s], &b = polygon[(s + 1) % n];
            const double length = std::hypot(b.i - a.i, b.j - a.j);
            inside = length > 0 && ((b.i - a.i) * (y - a.j) - (x - a.i) * (b.j - a.j)) / length > margin;
        }
        if (!inside) continue;
        const auto heights = fan_heights(polygon, apex, x, y);
        if (!heights) continue;
        const double to_top = std::abs(z - heights->first), to_bottom = std::abs(z - heights->second);
        const bool on_top = to_top <= to_bottom;
        const double error = on_top ? to_top : to_bottom;
        if ((on_top ? !top_on_input : !bottom_on_input) || error > bend_reach || error <= 0.05) continue;
        found.push_back({x, y, z, heights->first, heights->second, error, on_top});
    }
    std::sort(found.begin(), found.end(), [](const Candidate& a, const Candidate& b) { return a.error > b.error; });
    for (const Candidate& c : found) {
        // The ray through the vertex: the crossing nearest to the fan on its
        // sheet must be the vertex itself.
        const std::vector<Crossing> crossings = lines.crossings(c.x, c.y);
        const auto nearest = [&](double from, int facing) {
            double best = from, distance = bend_reach;
            for (const Crossing& k : crossings)
                if (k.facing == facing && std::abs(k.z - from) <= distance) best = k.z, distance = std::abs(k.z - from);
            return best;
        };
        SteinerPoint point{c.x, c.y, c.top, c.bottom};
        if (c.on_top) {
            if (std::abs(nearest(c.top, 1) - c.z) > 1e-3) continue;
            point.top = c.z;
            if (bottom_on_input) point.bottom = nearest_crossing(crossings, c.bottom, -1);
        } else {
            if (std::abs(nearest(c.bottom, -1) - c.z) > 1e-3) continue;
            point.bottom = c.z;
            if (top_on_input) point.top = nearest_crossing(crossings, c.top, 1);
        }
        if (point.top - point.bottom < 1e-3) continue;
        return point;
    }
    return std::nullopt;
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
            column.lo_on_input = lo != column.lo;
            column.hi_on_input = hi != column.hi;
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
    std::vector<openvdb::Vec3d> at_index;  //!< per vertex: block offsets i, j and index z
    const openvdb::math::Transform& transform = swept.transform();
    const auto add_vertex = [&](double i, double j, double z) {
        const openvdb::Vec3d p =
            transform.indexToWorld(openvdb::Vec3d(i + box.min().x(), j + box.min().y(), z));
        mesh.vertices.push_back({p[0], p[1], p[2]});
        at_index.emplace_back(i, j, z);
        return uint32_t(mesh.vertices.size() - 1);
    };
    const CellVertices cell_vertices =
        lines ? CellVertices(*input->mesh, input->orientation, transform, box.min(), nx, ny) : CellVertices();
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
                if (lines && n >= 3) {
                    std::vector<LiftedCorner> lifted;
                    bool top_on_input = true, bottom_on_input = true;
                    for (const Corner& corner : polygon) {
                        const auto v = ids(corner);
                        lifted.push_back({at_index[v[0]][0], at_index[v[0]][1], at_index[v[0]][2],
                                          at_index[v[1]][2], v[0], v[1]});
                        if (corner.contour != none) continue;
                        top_on_input &= column_at(corner.i, corner.j).hi_on_input;
                        bottom_on_input &= column_at(corner.i, corner.j).lo_on_input;
                    }
                    const std::optional<SteinerPoint> point =
                        steiner_point(lifted, apex, cell_vertices.of(i, j), *lines, top_on_input, bottom_on_input);
                    if (point) {
                        const uint32_t p_top = add_vertex(point->i, point->j, point->top);
                        const uint32_t p_bottom = add_vertex(point->i, point->j, point->bottom);
                        for (size_t s = 0; s < n; ++s) {
                            const LiftedCorner &b = lifted[s], &e = lifted[(s + 1) % n];
                            mesh.triangles.push_back({p_top, b.top_id, e.top_id});
                            mesh.triangles.push_back({p_bottom, e.bottom_id, b.bottom_id});
                        }
                        return;
                    }
                }
                const auto a = ids(polygon[apex]);
                for (size_t s = 1; s + 1 < n; ++s) {
                    const auto b = ids(polygon[(apex + s) % n]), c = ids(polygon[(apex + s + 1) % n]);
                    mesh.triangles.push_back({a[0], b[0], c[0]});
                    mesh.triangles.push_back({a[1], c[1], b[1]});
                }
            };
            // The polygon's contour edge (two contour vertices in a row) cuts
            // off a corner of the input's silhouette that lies in the cell:
            // the silhouette vertex of the input farthest past it (within
            // the cell, at a height within the polygon's run) goes in
            // between them. The polygon stays convex (the vertex is inside
            // the cell, past the edge) and its cell edges stay as they were.
            const auto insert_silhouette_vertex = [&](std::vector<Corner>& polygon, size_t& apex, int ci0, int cj0) {
                const size_t n = polygon.size();
                size_t edge = n;
                for (size_t s = 0; s < n; ++s)
                    if (polygon[s].contour != none && polygon[(s + 1) % n].contour != none) edge = s;
                if (edge == n) return;
                const openvdb::Vec3d &a = at_index[polygon[edge].contour],
                                     &b = at_index[polygon[(edge + 1) % n].contour];
                double low = std::min(a[2], b[2]), high = std::max(a[2], b[2]);
                for (const Corner& corner : polygon)
                    if (corner.contour == none) {
                        low = std::min(low, double(column_at(corner.i, corner.j).lo));
                        high = std::max(high, double(column_at(corner.i, corner.j).hi));
                    }
                const double length = std::hypot(b[0] - a[0], b[1] - a[1]);
                if (!(length > 0)) return;
                const double margin = 0.05;
                const CellPoint* best = nullptr;
                double farthest = margin;
                const auto points = cell_vertices.of(ci0, cj0);
                for (const CellPoint* p = points.first; p != points.second; ++p) {
                    if (!p->silhouette) continue;
                    const double x = p->at[0], y = p->at[1], z = p->at[2];
                    if (x - ci0 < margin || ci0 + 1 - x < margin || y - cj0 < margin || cj0 + 1 - y < margin) continue;
                    if (z < low - snap_reach || z > high + snap_reach) continue;
                    const double past = ((x - a[0]) * (b[1] - a[1]) - (b[0] - a[0]) * (y - a[1])) / length;
                    if (past > farthest) farthest = past, best = p;
                }
                if (!best) return;
                const uint32_t id = add_vertex(best->at[0], best->at[1], best->at[2]);
                polygon.insert(polygon.begin() + std::ptrdiff_t(edge + 1), Corner{0, 0, id});
                if (apex > edge) ++apex;
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
            if (lines) insert_silhouette_vertex(polygon, apex, i, j);
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
