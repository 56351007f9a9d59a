//! Per-axis projected overlaps: project the outer triangles on the plane
//! normal to the axis, bin their 2-D boxes in a uniform grid, test each box
//! pair once (in the cell holding the lower corner of the boxes' overlap) and
//! clip the two triangles to measure the shared area. An update of a few
//! moved triangles tests bounding spheres instead of projecting every
//! triangle, and shifts the pair lists in place.
#include "surface/moldability_terms.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>

#include <tbb/parallel_for.h>

#include "core/vec3_ops.h"

namespace fabvdb::surface {

namespace {

struct Point2 {
    double x, y;
};
//! A clipped polygon kept on the stack (clipping runs in the innermost loop).
//! Each clip at most doubles the corners (one kept corner and one crossing
//! per edge), so a triangle clipped three times has at most 24 — in exact
//! arithmetic at most 6.
struct Polygon2 {
    std::array<Point2, 24> corner;
    int size = 0;
    void push(const Point2& p) { corner[size++] = p; }
};

double signed_area(const Polygon2& p) {
    double twice = 0;
    for (int i = 0; i < p.size; ++i) {
        const Point2& a = p.corner[i];
        const Point2& b = p.corner[(i + 1) % p.size];
        twice += a.x * b.y - a.y * b.x;
    }
    return 0.5 * twice;
}

//! Area of the intersection of two counter-clockwise triangles (clipping).
double intersection_area(const std::array<Point2, 3>& a, const std::array<Point2, 3>& b) {
    Polygon2 polygon;
    for (const Point2& p : a) polygon.push(p);
    Polygon2 clipped;
    for (int k = 0; k < 3 && polygon.size > 0; ++k) {
        const Point2 p = b[k];
        const Point2 q = b[(k + 1) % 3];
        const auto side = [&](const Point2& r) { return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x); };
        clipped.size = 0;
        for (int i = 0; i < polygon.size; ++i) {
            const Point2& s = polygon.corner[i];
            const Point2& e = polygon.corner[(i + 1) % polygon.size];
            const double ss = side(s);
            const double se = side(e);
            if (ss >= 0) clipped.push(s);
            if ((ss >= 0) != (se >= 0)) {
                const double t = ss / (ss - se);
                clipped.push({s.x + t * (e.x - s.x), s.y + t * (e.y - s.y)});
            }
        }
        polygon = clipped;
    }
    return polygon.size < 3 ? 0.0 : std::abs(signed_area(polygon));
}

//! A triangle projected on the plane normal to `axis` (basis u, v),
//! counter-clockwise in (u, v) when it faces the axis (`facing` ≥ 0).
std::array<Point2, 3> project_triangle(const std::array<Vec3, 3>& corners, const Vec3& u, const Vec3& v,
                                       double facing) {
    std::array<Point2, 3> p;
    for (int k = 0; k < 3; ++k) p[k] = {dot(corners[k], u), dot(corners[k], v)};
    if (facing < 0) std::swap(p[1], p[2]);
    return p;
}

//! The plane basis (u, v) of the projections along `axis`.
std::pair<Vec3, Vec3> projection_basis(const Vec3& axis) {
    const Vec3 helper = std::abs(axis[0]) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 u = normalized(cross(axis, helper));
    return {u, cross(axis, u)};
}

struct Box2 {
    double lo[2], hi[2];
};

//! Triangles whose vertices moved since `previous` (the overlaps along the axis).
struct Change {
    const std::vector<uint32_t>& triangles;
    const std::vector<char>& flag;  //!< per triangle: in `triangles`
    const MoldabilityTerms::Overlaps& previous;
};

//! The outer triangles projected on the plane normal to an axis: each one's
//! 2-D triangle (counter-clockwise when it faces the axis), its box, whether
//! it is usable (not edge-on), and the mean box side.
struct Projection {
    std::vector<std::array<Point2, 3>> triangles;
    std::vector<Box2> boxes;
    std::vector<char> usable;
    double mean_size = 0;
};

Projection project_shell(const Shell& shell, const Vec3& axis) {
    const size_t n = shell.triangle_count();
    const auto [u, v] = projection_basis(axis);
    Projection projection;
    projection.triangles.resize(n);
    projection.boxes.resize(n);
    projection.usable.resize(n);
    double mean_size = 0;
    for (size_t t = 0; t < n; ++t) {
        const Triangle& f = shell.outer.triangles[t];
        const double facing = dot(shell.normal[t], axis);
        projection.usable[t] = std::abs(facing) > 1e-9;
        auto& tri = projection.triangles[t];
        tri = project_triangle({shell.outer.vertices[f[0]], shell.outer.vertices[f[1]], shell.outer.vertices[f[2]]}, u,
                               v, facing);
        Box2& box = projection.boxes[t];
        box.lo[0] = std::min({tri[0].x, tri[1].x, tri[2].x});
        box.hi[0] = std::max({tri[0].x, tri[1].x, tri[2].x});
        box.lo[1] = std::min({tri[0].y, tri[1].y, tri[2].y});
        box.hi[1] = std::max({tri[0].y, tri[1].y, tri[2].y});
        mean_size += (box.hi[0] - box.lo[0]) + (box.hi[1] - box.lo[1]);
    }
    projection.mean_size = std::max(mean_size / (2.0 * n), 1e-12);
    return projection;
}

//! The usable boxes binned in a grid of cells twice the mean box size: cell
//! (i, j) lists the boxes that meet it, items[start[c]] to items[start[c+1]].
struct BoxGrid {
    double lo[2] = {1e300, 1e300};
    double cell = 0;
    int nx = 1, ny = 1;
    std::vector<uint32_t> start, items;

    int cell_of(double value, int k) const {
        return std::clamp(int((value - lo[k]) / cell), 0, (k == 0 ? nx : ny) - 1);
    }
    size_t index(int i, int j) const { return size_t(j) * nx + i; }
};

BoxGrid bin_boxes(const Projection& projection) {
    const std::vector<Box2>& boxes = projection.boxes;
    BoxGrid grid;
    double hi[2] = {-1e300, -1e300};
    for (const Box2& b : boxes)
        for (int k = 0; k < 2; ++k) {
            grid.lo[k] = std::min(grid.lo[k], b.lo[k]);
            hi[k] = std::max(hi[k], b.hi[k]);
        }
    grid.cell = 2.0 * projection.mean_size;
    grid.nx = std::max(1, int((hi[0] - grid.lo[0]) / grid.cell) + 1);
    grid.ny = std::max(1, int((hi[1] - grid.lo[1]) / grid.cell) + 1);
    const auto for_cells = [&](size_t t, auto&& visit) {
        for (int j = grid.cell_of(boxes[t].lo[1], 1); j <= grid.cell_of(boxes[t].hi[1], 1); ++j)
            for (int i = grid.cell_of(boxes[t].lo[0], 0); i <= grid.cell_of(boxes[t].hi[0], 0); ++i)
                visit(grid.index(i, j));
    };
    grid.start.assign(size_t(grid.nx) * grid.ny + 1, 0);
    for (size_t t = 0; t < boxes.size(); ++t)
        if (projection.usable[t]) for_cells(t, [&](size_t c) { ++grid.start[c + 1]; });
    for (size_t c = 1; c < grid.start.size(); ++c) grid.start[c] += grid.start[c - 1];
    grid.items.resize(grid.start.back());
    std::vector<uint32_t> fill(grid.start.begin(), grid.start.end() - 1);
    for (size_t t = 0; t < boxes.size(); ++t)
        if (projection.usable[t]) for_cells(t, [&](size_t c) { grid.items[fill[c]++] = uint32_t(t); });
    return grid;
}

struct Pair {
    uint32_t a, b;
    float area;
};

//! The pairs of triangles that face alike along `axis` and whose
//! projections share more than `tiny` (area in the shell's units, scaled to
//! mm²), each once. A pair is measured in the one grid cell that holds the
//! lower corner of the overlap of its boxes. With a `change`, only the pairs
//! of a changed triangle.
std::vector<Pair> overlapping_pairs(const Shell& shell, const Vec3& axis, const Projection& projection, double tiny,
                                    const Change* change) {
    const std::vector<Box2>& boxes = projection.boxes;
    const double area_scale = shell.unit_scale * shell.unit_scale;
    std::vector<Pair> found;
    const auto boxes_meet = [&](uint32_t a, uint32_t b) {
        return std::max(boxes[a].lo[0], boxes[b].lo[0]) <= std::min(boxes[a].hi[0], boxes[b].hi[0]) &&
               std::max(boxes[a].lo[1], boxes[b].lo[1]) <= std::min(boxes[a].hi[1], boxes[b].hi[1]);
    };
    // Boxes known to meet: the shared projected area, if the two face alike.
    const auto measure = [&](uint32_t a, uint32_t b) {
        if (dot(shell.normal[a], axis) * dot(shell.normal[b], axis) < 0) return;
        // Edge neighbours facing alike project to opposite sides of their
        // shared edge (they run it in opposite senses): no common area.
        const auto& around = shell.neighbor[a];
        if (around[0] == int(b) || around[1] == int(b) || around[2] == int(b)) return;
        const double shared = intersection_area(projection.triangles[a], projection.triangles[b]);
        if (shared <= tiny) return;
        found.push_back({a, b, float(shared * area_scale)});
    };
    const BoxGrid grid = bin_boxes(projection);
    const auto measure_in_cell = [&](uint32_t a, uint32_t b, int i, int j) {
        if (boxes_meet(a, b) && grid.cell_of(std::max(boxes[a].lo[0], boxes[b].lo[0]), 0) == i &&
            grid.cell_of(std::max(boxes[a].lo[1], boxes[b].lo[1]), 1) == j)
            measure(a, b);
    };
    if (!change) {
        for (int j = 0; j < grid.ny; ++j)
            for (int i = 0; i < grid.nx; ++i) {
                const size_t c = grid.index(i, j);
                for (uint32_t x = grid.start[c]; x < grid.start[c + 1]; ++x)
                    for (uint32_t y = x + 1; y < grid.start[c + 1]; ++y)
                        measure_in_cell(grid.items[x], grid.items[y], i, j);
            }
        return found;
    }
    for (uint32_t a : change->triangles) {
        if (!projection.usable[a]) continue;
        for (int j = grid.cell_of(boxes[a].lo[1], 1); j <= grid.cell_of(boxes[a].hi[1], 1); ++j)
            for (int i = grid.cell_of(boxes[a].lo[0], 0); i <= grid.cell_of(boxes[a].hi[0], 0); ++i) {
                const size_t c = grid.index(i, j);
                for (uint32_t x = grid.start[c]; x < grid.start[c + 1]; ++x) {
                    const uint32_t b = grid.items[x];
                    if (b != a && !(change->flag[b] && b < a)) measure_in_cell(a, b, i, j);
                }
            }
    }
    return found;
}

//! The pair lists of `n` triangles (CSR): with a `change`, the previous
//! pairs of two unchanged triangles first, then the `found` ones, each
//! under both its triangles.
MoldabilityTerms::Overlaps pair_lists(size_t n, const std::vector<Pair>& found, double tiny, const Change* change) {
    const auto kept = [&](uint32_t t, uint32_t k) {
        return change && !change->flag[t] && !change->flag[change->previous.partner[k]];
    };
    MoldabilityTerms::Overlaps result;
    result.negligible = tiny;
    result.offset.assign(n + 1, 0);
    if (change)
        for (uint32_t t = 0; t < n; ++t)
            for (uint32_t k = change->previous.offset[t]; k < change->previous.offset[t + 1]; ++k)
                result.offset[t + 1] += kept(t, k);
    for (const Pair& p : found) {
        ++result.offset[p.a + 1];
        ++result.offset[p.b + 1];
    }
    for (size_t t = 0; t < n; ++t) result.offset[t + 1] += result.offset[t];
    result.partner.resize(result.offset.back());
    result.area.resize(result.offset.back());
    std::vector<uint32_t> next(result.offset.begin(), result.offset.end() - 1);
    const auto add = [&](uint32_t t, uint32_t partner, float area) {
        result.partner[next[t]] = partner;
        result.area[next[t]++] = area;
    };
    if (change)
        for (uint32_t t = 0; t < n; ++t)
            for (uint32_t k = change->previous.offset[t]; k < change->previous.offset[t + 1]; ++k)
                if (kept(t, k)) add(t, change->previous.partner[k], change->previous.area[k]);
    for (const Pair& p : found) {
        add(p.a, p.b, p.area);
        add(p.b, p.a, p.area);
    }
    return result;
}

//! The overlaps along `axis`. With a `change`, only the pairs of a changed
//! triangle are measured again (through the grid); the previous pairs of
//! unchanged triangles are kept.
MoldabilityTerms::Overlaps overlaps_along_axis(const Shell& shell, const Vec3& axis, const Change* change) {
    const Projection projection = project_shell(shell, axis);
    const double tiny = 1e-9 * projection.mean_size * projection.mean_size;
    const std::vector<Pair> found = overlapping_pairs(shell, axis, projection, tiny, change);
    return pair_lists(shell.triangle_count(), found, tiny, change);
}

//! The triangles near a few changed ones along an axis, found by bounding
//! spheres: per triangle its centroid relative to the centre of the changed
//! triangles' bounding sphere, the squared length of that, and the squared
//! distance from that sphere's axis line beyond which its bounding sphere
//! cannot meet the changed ones' (with a margin for rounding); the same for
//! clusters of triangles (cells of a 3-D grid), tested first.
struct Cylinder {
    struct Spheres {
        std::vector<Vec3> offset;
        std::vector<double> length2, limit2;
        void add(const Vec3& o, double reach) {
            offset.push_back(o);
            length2.push_back(dot(o, o));
            limit2.push_back(reach * reach);
        }
        bool out_of_reach(size_t i, const Vec3& axis) const {
            const double along = dot(offset[i], axis);
            return length2[i] - along * along > limit2[i];
        }
    };
    Spheres triangles, clusters;
    std::vector<uint32_t> cluster_start, members;  //!< members of cluster c: [cluster_start[c], cluster_start[c + 1])

    //! The triangles whose spheres reach the changed ones' along `axis`, in increasing order.
    std::vector<uint32_t> near(const Vec3& axis) const {
        std::vector<uint32_t> found;
        for (size_t c = 0; c + 1 < cluster_start.size(); ++c) {
            if (clusters.out_of_reach(c, axis)) continue;
            for (uint32_t k = cluster_start[c]; k < cluster_start[c + 1]; ++k)
                if (!triangles.out_of_reach(members[k], axis)) found.push_back(members[k]);
        }
        std::sort(found.begin(), found.end());
        return found;
    }
};

Cylinder cylinder_test(const Shell& shell, const std::vector<uint32_t>& changed) {
    const size_t n = shell.triangle_count();
    const auto corner = [&](size_t t, int k) -> const Vec3& { return shell.outer.vertices[shell.outer.triangles[t][k]]; };
    Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
    for (uint32_t t : changed)
        for (int k = 0; k < 3; ++k)
            for (int i = 0; i < 3; ++i) {
                lo[i] = std::min(lo[i], corner(t, k)[i]);
                hi[i] = std::max(hi[i], corner(t, k)[i]);
            }
    const Vec3 centre = 0.5 * (lo + hi);
    double radius = 0;
    for (uint32_t t : changed)
        for (int k = 0; k < 3; ++k) radius = std::max(radius, norm(corner(t, k) - centre));
    const auto reach = [&](const Vec3& offset, double r) {
        return radius + r + 1e-7 * (norm(offset) + radius + r);
    };
    std::vector<Vec3> middle(n);
    std::vector<double> own(n, 0.0);
    Vec3 all_lo{1e300, 1e300, 1e300}, all_hi{-1e300, -1e300, -1e300};
    Cylinder c;
    for (size_t t = 0; t < n; ++t) {
        middle[t] = (1.0 / 3.0) * (corner(t, 0) + corner(t, 1) + corner(t, 2));
        for (int k = 0; k < 3; ++k) own[t] = std::max(own[t], norm(corner(t, k) - middle[t]));
        c.triangles.add(middle[t] - centre, reach(middle[t] - centre, own[t]));
        for (int i = 0; i < 3; ++i) {
            all_lo[i] = std::min(all_lo[i], middle[t][i]);
            all_hi[i] = std::max(all_hi[i], middle[t][i]);
        }
    }
    // Clusters: cells of a grid of about n/4 cells over the centroids.
    const int k = std::max(1, int(std::cbrt(double(n) / 4.0)));
    const auto cell_of = [&](const Vec3& p) {
        size_t index = 0;
        for (int i = 0; i < 3; ++i) {
            const double extent = all_hi[i] - all_lo[i];
            const int j = extent > 0 ? std::clamp(int((p[i] - all_lo[i]) / extent * k), 0, k - 1) : 0;
            index = index * size_t(k) + size_t(j);
        }
        return index;
    };
    std::vector<uint32_t> start(size_t(k) * k * k + 1, 0);
    std::vector<size_t> cell(n);
    for (size_t t = 0; t < n; ++t) ++start[(cell[t] = cell_of(middle[t])) + 1];
    for (size_t i = 1; i < start.size(); ++i) start[i] += start[i - 1];
    std::vector<uint32_t> members(n), fill(start.begin(), start.end() - 1);
    for (size_t t = 0; t < n; ++t) members[fill[cell[t]]++] = uint32_t(t);
    c.cluster_start.push_back(0);
    for (size_t i = 0; i + 1 < start.size(); ++i) {
        if (start[i] == start[i + 1]) continue;
        Vec3 sum{0, 0, 0};
        for (uint32_t m = start[i]; m < start[i + 1]; ++m) sum = sum + middle[members[m]];
        const Vec3 mean = (1.0 / double(start[i + 1] - start[i])) * sum;
        double r = 0;
        for (uint32_t m = start[i]; m < start[i + 1]; ++m) {
            r = std::max(r, norm(middle[members[m]] - mean) + own[members[m]]);
            c.members.push_back(members[m]);
        }
        c.clusters.add(mean - centre, reach(mean - centre, r));
        c.cluster_start.push_back(uint32_t(c.members.size()));
    }
    return c;
}

//! The pairs along `axis` of a few changed triangles: each against the
//! triangles whose bounding spheres project onto their bounding sphere's
//! disc (the others' projections cannot meet theirs).
struct FoundPair {
    uint32_t a, b;
    float area;
};

std::vector<FoundPair> pairs_of_few(const Shell& shell, const Vec3& axis, const std::vector<uint32_t>& changed,
                                    const std::vector<char>& flag, const Cylinder& cylinder, double negligible) {
    const auto [u, v] = projection_basis(axis);
    struct Projected {
        std::array<Point2, 3> triangle;
        Box2 box;
        bool usable;
    };
    const auto project = [&](uint32_t t) {
        const Triangle& f = shell.outer.triangles[t];
        const double facing = dot(shell.normal[t], axis);
        Projected p;
        p.usable = std::abs(facing) > 1e-9;
        p.triangle = project_triangle(
            {shell.outer.vertices[f[0]], shell.outer.vertices[f[1]], shell.outer.vertices[f[2]]}, u, v, facing);
        const auto& q = p.triangle;
        p.box = {{std::min({q[0].x, q[1].x, q[2].x}), std::min({q[0].y, q[1].y, q[2].y})},
                 {std::max({q[0].x, q[1].x, q[2].x}), std::max({q[0].y, q[1].y, q[2].y})}};
        return p;
    };
    std::vector<Projected> moved(changed.size());
    Box2 hull{{1e300, 1e300}, {-1e300, -1e300}};
    for (size_t i = 0; i < changed.size(); ++i) {
        moved[i] = project(changed[i]);
        for (int k = 0; k < 2; ++k) {
            hull.lo[k] = std::min(hull.lo[k], moved[i].box.lo[k]);
            hull.hi[k] = std::max(hull.hi[k], moved[i].box.hi[k]);
        }
    }
    const auto meet = [](const Box2& a, const Box2& b) {
        return std::max(a.lo[0], b.lo[0]) <= std::min(a.hi[0], b.hi[0]) &&
               std::max(a.lo[1], b.lo[1]) <= std::min(a.hi[1], b.hi[1]);
    };
    const double area_scale = shell.unit_scale * shell.unit_scale;
    std::vector<FoundPair> found;
    for (uint32_t b : cylinder.near(axis)) {
        const Projected pb = project(b);
        if (!pb.usable || !meet(pb.box, hull)) continue;
        for (size_t i = 0; i < changed.size(); ++i) {
            const uint32_t a = changed[i];
            if (!moved[i].usable || a == b || (flag[b] && b < a) || !meet(moved[i].box, pb.box)) continue;
            if (dot(shell.normal[a], axis) * dot(shell.normal[b], axis) < 0) continue;
            const auto& around = shell.neighbor[a];
            if (around[0] == int(b) || around[1] == int(b) || around[2] == int(b)) continue;
            const double shared = intersection_area(moved[i].triangle, pb.triangle);
            if (shared > negligible) found.push_back({a, b, float(shared * area_scale)});
        }
    }
    return found;
}

//! Replaces, in place, the rows of `o` that change: a changed triangle's
//! pairs are all `found` ones, another triangle keeps its pairs with
//! unchanged partners (in their order) and adds its `found` ones (in the
//! order found). The rows in between shift as blocks.
void replace_pairs(MoldabilityTerms::Overlaps& o, const std::vector<uint32_t>& changed, const std::vector<char>& flag,
                   const std::vector<FoundPair>& found) {
    std::vector<uint32_t> rows;
    for (uint32_t t : changed) {
        rows.push_back(t);
        rows.insert(rows.end(), o.partner.begin() + o.offset[t], o.partner.begin() + o.offset[t + 1]);
    }
    for (const FoundPair& p : found) {
        rows.push_back(p.a);
        rows.push_back(p.b);
    }
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    const size_t count = rows.size();
    const auto row_index = [&](uint32_t t) { return size_t(std::lower_bound(rows.begin(), rows.end(), t) - rows.begin()); };
    // The new rows, gathered before anything moves.
    std::vector<uint32_t> start(count + 1, 0);
    for (size_t i = 0; i < count; ++i) {
        const uint32_t t = rows[i];
        if (!flag[t])
            for (uint32_t k = o.offset[t]; k < o.offset[t + 1]; ++k) start[i + 1] += !flag[o.partner[k]];
    }
    for (const FoundPair& p : found) {
        ++start[row_index(p.a) + 1];
        ++start[row_index(p.b) + 1];
    }
    for (size_t i = 0; i < count; ++i) start[i + 1] += start[i];
    std::vector<uint32_t> partner(start.back());
    std::vector<float> area(start.back());
    std::vector<uint32_t> next(start.begin(), start.end() - 1);
    const auto add = [&](size_t i, uint32_t q, float a) {
        partner[next[i]] = q;
        area[next[i]++] = a;
    };
    for (size_t i = 0; i < count; ++i) {
        const uint32_t t = rows[i];
        if (!flag[t])
            for (uint32_t k = o.offset[t]; k < o.offset[t + 1]; ++k)
                if (!flag[o.partner[k]]) add(i, o.partner[k], o.area[k]);
    }
    for (const FoundPair& p : found) {
        add(row_index(p.a), p.b, p.area);
        add(row_index(p.b), p.a, p.area);
    }
    // Block i (the rows after rows[i], up to the next changing row) shifts by shift[i].
    const size_t n = o.offset.size() - 1;
    std::vector<int64_t> shift(count);
    int64_t total = 0;
    for (size_t i = 0; i < count; ++i) {
        total += int64_t(start[i + 1] - start[i]) - int64_t(o.offset[rows[i] + 1] - o.offset[rows[i]]);
        shift[i] = total;
    }
    const size_t old_size = o.partner.size(), new_size = size_t(int64_t(old_size) + total);
    if (new_size > old_size) {
        o.partner.resize(new_size);
        o.area.resize(new_size);
    }
    const auto move_block = [&](size_t i) {
        const uint32_t first = o.offset[rows[i] + 1];
        const uint32_t last = i + 1 < count ? o.offset[rows[i + 1]] : uint32_t(old_size);
        if (last == first) return;
        std::memmove(o.partner.data() + first + shift[i], o.partner.data() + first, (last - first) * sizeof(uint32_t));
        std::memmove(o.area.data() + first + shift[i], o.area.data() + first, (last - first) * sizeof(float));
    };
    // A block moving left lands past the blocks before it that move right
    // (and on those that moved left already), and conversely.
    for (size_t i = 0; i < count; ++i)
        if (shift[i] < 0) move_block(i);
    for (size_t i = count; i-- > 0;)
        if (shift[i] > 0) move_block(i);
    for (size_t i = 0; i < count; ++i) {
        const size_t at = size_t(int64_t(o.offset[rows[i]]) + (i > 0 ? shift[i - 1] : 0));
        std::copy(partner.begin() + start[i], partner.begin() + start[i + 1], o.partner.begin() + at);
        std::copy(area.begin() + start[i], area.begin() + start[i + 1], o.area.begin() + at);
    }
    for (size_t i = 0; i < count; ++i) {
        const size_t last = i + 1 < count ? rows[i + 1] : n;
        for (size_t t = rows[i] + 1; t <= last; ++t) o.offset[t] = uint32_t(int64_t(o.offset[t]) + shift[i]);
    }
    if (new_size < old_size) {
        o.partner.resize(new_size);
        o.area.resize(new_size);
    }
}

}  // namespace

double overhang_term(const Vec3& n, double area, const Vec3& d, double draft) {
    const double c = std::clamp(dot(n, d), -1.0, 1.0);
    const double theta = std::acos(c);
    if (theta <= M_PI / 2 - draft) return 0.0;
    return -std::cos(std::min(theta + draft, M_PI)) * area * std::abs(c);
}

MoldabilityTerms compute_moldability_terms(const Shell& shell, double draft_radians, Progress& progress) {
    MoldabilityTerms terms;
    terms.draft = draft_radians;
    terms.directions = thesis_directions();
    const size_t count = terms.directions.directions.size();
    terms.axis_of_direction.assign(count, -1);
    for (size_t i = 0; i < count; ++i) {
        const int j = terms.directions.opposite[i];
        if (terms.axis_of_direction[i] >= 0) continue;
        terms.axis_of_direction[i] = int(terms.axes.size());
        terms.axis_of_direction[size_t(j)] = int(terms.axes.size());
        terms.axes.push_back(terms.directions.directions[i]);
    }
    terms.overlaps.resize(terms.axes.size());
    progress.stage("moldability terms");
    std::atomic<size_t> done{0};
    tbb::parallel_for(size_t(0), terms.axes.size(), [&](size_t a) {
        if (progress.cancelled()) return;
        terms.overlaps[a] = overlaps_along_axis(shell, terms.axes[a], nullptr);
        progress.update(double(++done) / terms.axes.size());
    });
    progress.check();
    for (const auto& o : terms.overlaps) terms.pair_count += o.partner.size() / 2;
    return terms;
}

void update_moldability_terms(const Shell& shell, const std::vector<uint32_t>& changed, const std::vector<int>& axes,
                              MoldabilityTerms& terms) {
    std::vector<char> is_changed(shell.triangle_count(), 0);
    for (uint32_t t : changed) is_changed[t] = 1;
    constexpr size_t few = 64;
    if (changed.size() <= few) {
        if (changed.empty()) return;
        const Cylinder cylinder = cylinder_test(shell, changed);
        tbb::parallel_for(size_t(0), axes.size(), [&](size_t i) {
            MoldabilityTerms::Overlaps& o = terms.overlaps[axes[i]];
            const std::vector<FoundPair> found =
                pairs_of_few(shell, terms.axes[axes[i]], changed, is_changed, cylinder, o.negligible);
            replace_pairs(o, changed, is_changed, found);
        });
    } else {
        tbb::parallel_for(size_t(0), axes.size(), [&](size_t i) {
            const int a = axes[i];
            const Change change{changed, is_changed, terms.overlaps[a]};
            terms.overlaps[a] = overlaps_along_axis(shell, terms.axes[a], &change);
        });
    }
    terms.pair_count = 0;
    for (const auto& o : terms.overlaps) terms.pair_count += o.partner.size() / 2;
}

double projected_overlap(const std::array<Vec3, 3>& a, const std::array<Vec3, 3>& b, const Vec3& axis) {
    const auto [u, v] = projection_basis(axis);
    const auto facing = [&](const std::array<Vec3, 3>& t) { return dot(cross(t[1] - t[0], t[2] - t[0]), axis); };
    return intersection_area(project_triangle(a, u, v, facing(a)), project_triangle(b, u, v, facing(b)));
}

}  // namespace fabvdb::surface
