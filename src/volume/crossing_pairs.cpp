//! Crossing pairs of triangles of a mesh (see crossing_pairs.h).
//!
//! Each triangle goes to the grid of its size class: level L has cells of
//! base × 2^L, and a triangle whose bounding box is at most that wide sits in
//! the (at most 8) cells its box overlaps. Pairs in one level meet in a shared
//! cell; a triangle meets the larger ones by looking up the cells its box
//! overlaps in each coarser level. A pair of overlapping boxes is tested only
//! in the cell holding the lowest corner of their common box, so once.
//!
//! Neighbours are the most of the pairs met. Around a vertex whose triangles,
//! seen along their summed normal, turn the same way (certain by the filter)
//! and wind once around it, each triangle projects one to one into its own
//! angular sector: two of them meet only in the projection of what they
//! share, so only along it. Pairs that share such a vertex, or an edge at one,
//! are not tested.
#include "volume/crossing_pairs.h"

#include <algorithm>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include "volume/vertex_corners.h"

namespace fabvdb::volume {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;

struct Box {
    double lo[3], hi[3];
};

constexpr int max_levels = 40;

// A triangle's place in a level: its cell key above its index, in one
// integer, so that sorting the integers groups each cell's triangles.
class Grids {
public:
    explicit Grids(const std::vector<Box>& boxes) {
        while ((uint64_t(1) << triangle_bits_) < boxes.size()) ++triangle_bits_;
        axis_bits_ = std::min(21, (64 - triangle_bits_) / 3);
        const int64_t cells_per_axis = int64_t(1) << axis_bits_;
        std::vector<double> extents(boxes.size(), 0.0);
        double top[3];
        for (int k = 0; k < 3; ++k) {
            origin_[k] = HUGE_VAL;
            top[k] = -HUGE_VAL;
        }
        for (size_t t = 0; t < boxes.size(); ++t)
            for (int k = 0; k < 3; ++k) {
                extents[t] = std::max(extents[t], boxes[t].hi[k] - boxes[t].lo[k]);
                origin_[k] = std::min(origin_[k], boxes[t].lo[k]);
                top[k] = std::max(top[k], boxes[t].hi[k]);
            }
        double span = 0.0;
        for (int k = 0; k < 3; ++k) span = std::max(span, top[k] - origin_[k]);
        std::vector<double> sorted = extents;
        std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
        double base = 2.0 * sorted[sorted.size() / 2];
        // Cells must be few enough per axis for the key, and never empty.
        base = std::max({base, 2.0 * span / double(cells_per_axis), 1e-300});
        for (int level = 0; level < max_levels; ++level) {
            cell_size_[level] = std::ldexp(base, level);
            inverse_cell_size_[level] = 1.0 / cell_size_[level];
        }

        level_.resize(boxes.size());
        int top_level = 0;
        for (size_t t = 0; t < boxes.size(); ++t) {
            int level = 0;
            while (level + 1 < max_levels && cell_size_[level] < extents[t]) ++level;
            level_[t] = uint8_t(level);
            top_level = std::max(top_level, level);
        }
        // Each triangle's cells go to its own slots of its level, in parallel.
        low_cell_.resize(boxes.size());
        std::vector<size_t> slot(boxes.size(), 0);
        tbb::parallel_for(tbb::blocked_range<size_t>(0, boxes.size()), [&](const tbb::blocked_range<size_t>& range) {
            for (size_t t = range.begin(); t != range.end(); ++t) {
                low_cell_[t] = cell_of(boxes[t].lo, level_[t]);
                for_each_cell(boxes[t], level_[t], [&](uint64_t) { ++slot[t]; });
            }
        });
        entries_.resize(size_t(top_level) + 1);
        std::vector<size_t> level_size(entries_.size(), 0);
        for (size_t t = 0; t < boxes.size(); ++t) {
            const size_t cells = slot[t];
            slot[t] = level_size[level_[t]];
            level_size[level_[t]] += cells;
        }
        for (size_t level = 0; level < entries_.size(); ++level) entries_[level].resize(level_size[level]);
        tbb::parallel_for(tbb::blocked_range<size_t>(0, boxes.size()), [&](const tbb::blocked_range<size_t>& range) {
            for (size_t t = range.begin(); t != range.end(); ++t) {
                uint64_t* entry = &entries_[level_[t]][slot[t]];
                for_each_cell(boxes[t], level_[t], [&](uint64_t cell) { *entry++ = entry_of(cell, uint32_t(t)); });
            }
        });
        for (auto& level : entries_) tbb::parallel_sort(level.begin(), level.end());
    }

    int levels() const { return int(entries_.size()); }
    int level(size_t t) const { return level_[t]; }
    //! The cell of its own level that holds the lowest corner of t's box.
    uint64_t low_cell(size_t t) const { return low_cell_[t]; }
    //! The level's entries, sorted: by cell, then by triangle.
    const std::vector<uint64_t>& entries(int level) const { return entries_[level]; }
    uint64_t entry_of(uint64_t cell, uint32_t triangle) const { return cell << triangle_bits_ | triangle; }
    uint64_t cell(uint64_t entry) const { return entry >> triangle_bits_; }
    uint32_t triangle(uint64_t entry) const { return uint32_t(entry & ((uint64_t(1) << triangle_bits_) - 1)); }

    uint64_t cell_of(const double* p, int level) const {
        const int64_t last = (int64_t(1) << axis_bits_) - 1;
        uint64_t key = 0;
        for (int k = 0; k < 3; ++k)
            key = key << axis_bits_ |
                  uint64_t(std::clamp(int64_t(std::floor((p[k] - origin_[k]) * inverse_cell_size_[level])), int64_t(0), last));
        return key;
    }

    //! The cell holding the lowest corner of the common box of two boxes
    //! whose lowest corners lie in cells `a` and `b` of one level.
    uint64_t common_low_cell(uint64_t a, uint64_t b) const {
        const uint64_t mask = (uint64_t(1) << axis_bits_) - 1;
        uint64_t key = 0;
        for (int shift = 2 * axis_bits_; shift >= 0; shift -= axis_bits_)
            key |= std::max((a >> shift) & mask, (b >> shift) & mask) << shift;
        return key;
    }

    template <class Visit>
    void for_each_cell(const Box& box, int level, const Visit& visit) const {
        const uint64_t lo = cell_of(box.lo, level), hi = cell_of(box.hi, level);
        const int b = axis_bits_;
        const uint64_t mask = (uint64_t(1) << b) - 1;
        for (uint64_t x = lo >> (2 * b); x <= hi >> (2 * b); ++x)
            for (uint64_t y = (lo >> b) & mask; y <= ((hi >> b) & mask); ++y)
                for (uint64_t z = lo & mask; z <= (hi & mask); ++z) visit(x << (2 * b) | y << b | z);
    }

private:
    int triangle_bits_ = 1;
    int axis_bits_ = 21;
    double origin_[3] = {0, 0, 0};
    double cell_size_[max_levels], inverse_cell_size_[max_levels];
    std::vector<uint8_t> level_;
    std::vector<uint64_t> low_cell_;
    std::vector<std::vector<uint64_t>> entries_;
};

bool boxes_overlap(const Box& a, const Box& b) {
    for (int k = 0; k < 3; ++k)
        if (a.hi[k] < b.lo[k] || b.hi[k] < a.lo[k]) return false;
    return true;
}

// Floating-point filters in front of the exact predicates: a sign they
// return is certain (their error bound is far above the rounding error of the
// expressions, ~10 ulp of the bound's product); 0 means "not sure".
using Vec = std::array<double, 3>;
Vec minus(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec cross_product(const Vec& a, const Vec& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
constexpr double filter_bound_squared = 1e-24;

// Whether x > 0 beyond the error bound whose square is `bound_squared`.
int certain_sign(double x, double bound_squared) {
    if (x * x <= filter_bound_squared * bound_squared) return 0;
    return x > 0.0 ? 1 : -1;
}

// The plane through three points, for the side of points.
class TrianglePlane {
public:
    TrianglePlane(const std::vector<Vec3>& v, const Triangle& t) : TrianglePlane(v[t[0]], v[t[1]], v[t[2]]) {}
    TrianglePlane(const Vec3& a, const Vec3& b, const Vec3& c) : origin_(a) {
        const Vec ab = minus(b, origin_), ac = minus(c, origin_);
        normal_ = cross_product(ab, ac);
        scale_squared_ = dot(ab, ab) * dot(ac, ac);
    }
    int certain_side(const Vec3& p) const {
        const Vec d = minus(p, origin_);
        return certain_sign(dot(normal_, d), scale_squared_ * dot(d, d));
    }
    // Whether the points lie certainly strictly on one side.
    template <class... Points>
    bool certainly_one_side(const Vec3& first, const Points&... others) const {
        const int side = certain_side(first);
        return side != 0 && ((certain_side(others) == side) && ...);
    }

private:
    Vec3 origin_;
    Vec normal_;
    double scale_squared_;
};

// Whether a plane through an edge of triangle a and along its normal
// certainly has a's third corner strictly on one side and all of b strictly
// on the other. The plane passes through the edge's ends and a third point
// off them (the edge's start moved along the computed normal), so the edge
// lies on it exactly whatever the rounding of that point. Separates
// coplanar triangles, which the planes of the triangles themselves cannot.
bool edge_plane_separates(const std::vector<Vec3>& v, const Triangle& a, const Triangle& b) {
    const Vec normal = cross_product(minus(v[a[1]], v[a[0]]), minus(v[a[2]], v[a[0]]));
    for (int k = 0; k < 3; ++k) {
        const Vec3& start = v[a[k]];
        const Vec3 above = {start[0] + normal[0], start[1] + normal[1], start[2] + normal[2]};
        const TrianglePlane plane(start, v[a[(k + 1) % 3]], above);
        const int third = plane.certain_side(v[a[(k + 2) % 3]]);
        if (third != 0 && plane.certainly_one_side(v[b[0]], v[b[1]], v[b[2]]) && plane.certain_side(v[b[0]]) == -third)
            return true;
    }
    return false;
}

// Whether segment pq certainly misses the triangle (v, a, b): both its ends
// lie strictly on one side of the triangle's plane or, seen along its normal,
// strictly beyond the line through v and a or the one through v and b.
bool segment_certainly_misses(const Vec3& v, const Vec3& a, const Vec3& b, const Vec3& p, const Vec3& q) {
    const Vec va = minus(a, v), vb = minus(b, v), vp = minus(p, v), vq = minus(q, v);
    const double la = dot(va, va), lb = dot(vb, vb), lp = dot(vp, vp), lq = dot(vq, vq);
    const Vec normal = cross_product(va, vb);
    const int side_p = certain_sign(dot(normal, vp), la * lb * lp);
    if (side_p != 0 && certain_sign(dot(normal, vq), la * lb * lq) == side_p) return true;
    const Vec toward_b = cross_product(normal, va), toward_a = cross_product(vb, normal);
    return (certain_sign(dot(toward_b, vp), la * la * lb * lp) < 0 &&
            certain_sign(dot(toward_b, vq), la * la * lb * lq) < 0) ||
           (certain_sign(dot(toward_a, vp), lb * lb * la * lp) < 0 &&
            certain_sign(dot(toward_a, vq), lb * lb * la * lq) < 0);
}

// Whether the triangles around vertex `centre` (at its `corners`, `count` of
// them; vertex_corners.h) wind once around it, seen along their summed normal, each turning the same
// way: the link edges a -> b of the triangles (centre, a, b) chain into one
// cycle, every turn is certainly positive, and the angular sectors (a, b] of
// the projected triangles cover the direction of the first link vertex once
// (the one ending there, certainly no other).
bool fan_is_embedded(const Mesh& mesh, uint32_t centre, const uint32_t* corners, size_t count) {
    constexpr size_t max_fan = 64;
    if (count < 3 || count > max_fan) return false;
    uint32_t from[max_fan], to[max_fan];
    for (size_t k = 0; k < count; ++k) {
        const Triangle& t = mesh.triangles[corners[k] / 3];
        const uint32_t corner = corners[k] % 3;
        from[k] = t[(corner + 1) % 3];
        to[k] = t[(corner + 2) % 3];
        if (from[k] == centre || to[k] == centre || from[k] == to[k]) return false;
        for (size_t j = 0; j < k; ++j)
            if (from[j] == from[k]) return false;
    }
    size_t steps = 1;
    for (uint32_t at = to[0]; at != from[0]; ++steps) {
        const size_t next = size_t(std::find(from, from + count, at) - from);
        if (next == count || steps == count) return false;
        at = to[next];
    }
    if (steps != count) return false;

    const Vec3& c = mesh.vertices[centre];
    Vec normal = {0.0, 0.0, 0.0};
    for (size_t k = 0; k < count; ++k) {
        const Vec turn = cross_product(minus(mesh.vertices[from[k]], c), minus(mesh.vertices[to[k]], c));
        for (int axis = 0; axis < 3; ++axis) normal[axis] += turn[axis];
    }
    const double normal_squared = dot(normal, normal);
    if (!(normal_squared > 0.0)) return false;
    const Vec reference = minus(mesh.vertices[from[0]], c);
    const double reference_squared = dot(reference, reference);
    for (size_t k = 0; k < count; ++k) {
        const Vec a = minus(mesh.vertices[from[k]], c), b = minus(mesh.vertices[to[k]], c);
        const double a_squared = dot(a, a), b_squared = dot(b, b);
        if (certain_sign(dot(normal, cross_product(a, b)), normal_squared * a_squared * b_squared) <= 0) return false;
        if (k == 0 || to[k] == from[0]) continue;
        // The sector (a, b], narrower than a half turn, holds the reference
        // direction when it lies after a and not after b.
        if (certain_sign(dot(normal, cross_product(a, reference)), normal_squared * a_squared * reference_squared) >= 0 &&
            certain_sign(dot(normal, cross_product(reference, b)), normal_squared * reference_squared * b_squared) >= 0)
            return false;
    }
    return true;
}

// Per vertex, whether fan_is_embedded holds; computed for the vertices of
// the candidate triangles only (all when there are no candidates).
std::vector<char> embedded_fans(const Mesh& mesh, const std::vector<char>& candidates) {
    const size_t vertex_count = mesh.vertices.size();
    const VertexCorners corners(mesh);
    std::vector<char> wanted(vertex_count, candidates.empty());
    for (size_t t = 0; t < candidates.size(); ++t)
        if (candidates[t])
            for (uint32_t v : mesh.triangles[t]) wanted[v] = 1;
    std::vector<char> embedded(vertex_count, 0);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, vertex_count), [&](const tbb::blocked_range<size_t>& range) {
        for (size_t v = range.begin(); v != range.end(); ++v)
            embedded[v] = wanted[v] && fan_is_embedded(mesh, uint32_t(v), &corners.corner[corners.first[v]],
                                                       corners.first[v + 1] - corners.first[v]);
    });
    return embedded;
}

// Whether triangles a and b meet other than along what they share; pairs
// sharing a vertex with an embedded fan, or an edge at one, do not.
bool cross(const Mesh& mesh, const std::vector<char>& embedded, const Triangle& a, const Triangle& b) {
    const auto& v = mesh.vertices;
    const auto point = [&](uint32_t i) { return Point(v[i][0], v[i][1], v[i][2]); };
    int shared = 0, a_shared[3] = {}, b_shared[3] = {};
    bool at_embedded_fan = false;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (a[i] == b[j]) {
                ++shared;
                a_shared[i] = b_shared[j] = 1;
                at_embedded_fan = at_embedded_fan || embedded[a[i]];
            }
    if (shared >= 3) return true;
    if (at_embedded_fan) return false;
    if (shared == 2) {
        int i = 0, j = 0;
        while (a_shared[i]) ++i;
        while (b_shared[j]) ++j;
        const uint32_t u = a[(i + 1) % 3], w = a[(i + 2) % 3], p = a[i], q = b[j];
        // Run along the shared edge in opposite directions with normals that
        // agree: either not coplanar or on opposite sides, so not crossing.
        if (b[(j + 1) % 3] == w) {
            const Vec edge = minus(v[w], v[u]), to_p = minus(v[p], v[u]), to_q = minus(v[q], v[u]);
            const double agreement = dot(cross_product(edge, to_p), cross_product(to_q, edge));
            const double edge_squared = dot(edge, edge);
            if (certain_sign(agreement, edge_squared * edge_squared * dot(to_p, to_p) * dot(to_q, to_q)) > 0)
                return false;
        }
        const Point pu = point(u), pw = point(w), pp = point(p), pq = point(q);
        return CGAL::coplanar(pu, pw, pp, pq) && CGAL::coplanar_orientation(pu, pw, pp, pq) == CGAL::POSITIVE;
    }
    const Kernel::Triangle_3 ta(point(a[0]), point(a[1]), point(a[2])), tb(point(b[0]), point(b[1]), point(b[2]));
    if (shared == 0) {
        if (TrianglePlane(v, a).certainly_one_side(v[b[0]], v[b[1]], v[b[2]]) ||
            TrianglePlane(v, b).certainly_one_side(v[a[0]], v[a[1]], v[a[2]]) || edge_plane_separates(v, a, b) ||
            edge_plane_separates(v, b, a))
            return false;
        return CGAL::do_intersect(ta, tb);
    }
    int i = 0, j = 0;
    while (!a_shared[i]) ++i;
    while (!b_shared[j]) ++j;
    const uint32_t a1 = a[(i + 1) % 3], a2 = a[(i + 2) % 3], b1 = b[(j + 1) % 3], b2 = b[(j + 2) % 3];
    const Vec3& corner = v[a[i]];
    const bool b_edge_misses = segment_certainly_misses(corner, v[a1], v[a2], v[b1], v[b2]);
    const bool a_edge_misses = segment_certainly_misses(corner, v[b1], v[b2], v[a1], v[a2]);
    return (!b_edge_misses && CGAL::do_intersect(ta, Kernel::Segment_3(point(b1), point(b2)))) ||
           (!a_edge_misses && CGAL::do_intersect(tb, Kernel::Segment_3(point(a1), point(a2))));
}

Box box_of(const Mesh& mesh, const Triangle& t) {
    Box box;
    for (int k = 0; k < 3; ++k) {
        const double a = mesh.vertices[t[0]][k], b = mesh.vertices[t[1]][k], c = mesh.vertices[t[2]][k];
        box.lo[k] = std::min({a, b, c});
        box.hi[k] = std::max({a, b, c});
    }
    return box;
}

// The triangles, in index order, whose bounding box meets a candidate's:
// only they can be in a crossing pair with a candidate. The candidates'
// boxes go into cubic cells as wide as the widest of them (so each meets at
// most 8); a triangle looks in the cells its own box meets. Two boxes that
// share a point share that point's cell: the cell index floor((x − origin)
// / side) never decreases with x, rounding included. A triangle meeting
// more than `max_cells` cells is compared with every candidate instead.
std::vector<uint32_t> near_candidates(const Mesh& mesh, const std::vector<char>& candidates) {
    constexpr int64_t max_cells = 64;
    constexpr int cell_bits = 21;
    std::vector<uint32_t> listed;
    for (size_t t = 0; t < candidates.size(); ++t)
        if (candidates[t]) listed.push_back(uint32_t(t));
    if (listed.empty()) return {};
    std::vector<Box> boxes;
    boxes.reserve(listed.size());
    double origin[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, top[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL}, side = 0.0;
    for (uint32_t t : listed) {
        const Box& box = boxes.emplace_back(box_of(mesh, mesh.triangles[t]));
        for (int k = 0; k < 3; ++k) {
            origin[k] = std::min(origin[k], box.lo[k]);
            top[k] = std::max(top[k], box.hi[k]);
            side = std::max(side, box.hi[k] - box.lo[k]);
        }
    }
    for (int k = 0; k < 3; ++k) side = std::max(side, (top[k] - origin[k]) / double(int64_t(1) << (cell_bits - 1)));
    side = std::max(side, 1e-300);
    int64_t last[3];
    const auto cell = [&](double x, int k) { return int64_t(std::floor((x - origin[k]) / side)); };
    for (int k = 0; k < 3; ++k) last[k] = cell(top[k], k);
    const auto key = [](int64_t x, int64_t y, int64_t z) {
        return uint64_t(x) << (2 * cell_bits) | uint64_t(y) << cell_bits | uint64_t(z);
    };
    std::vector<std::pair<uint64_t, uint32_t>> cells;  // (cell, index into listed)
    for (uint32_t c = 0; c < listed.size(); ++c) {
        const Box& box = boxes[c];
        for (int64_t x = cell(box.lo[0], 0); x <= cell(box.hi[0], 0); ++x)
            for (int64_t y = cell(box.lo[1], 1); y <= cell(box.hi[1], 1); ++y)
                for (int64_t z = cell(box.lo[2], 2); z <= cell(box.hi[2], 2); ++z) cells.emplace_back(key(x, y, z), c);
    }
    tbb::parallel_sort(cells.begin(), cells.end());

    std::vector<char> near(mesh.triangles.size(), 0);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, mesh.triangles.size(), 4096),
                      [&](const tbb::blocked_range<size_t>& range) {
        for (size_t t = range.begin(); t != range.end(); ++t) {
            if (candidates[t]) {
                near[t] = 1;
                continue;
            }
            const Box box = box_of(mesh, mesh.triangles[t]);
            int64_t lo[3], hi[3], count = 1;
            for (int k = 0; k < 3; ++k) {
                lo[k] = std::max<int64_t>(cell(box.lo[k], k), 0);
                hi[k] = std::min(cell(box.hi[k], k), last[k]);
                count *= std::max<int64_t>(hi[k] - lo[k] + 1, 0);
            }
            if (count == 0) continue;
            if (count > max_cells) {
                near[t] = std::any_of(boxes.begin(), boxes.end(), [&](const Box& other) { return boxes_overlap(box, other); });
                continue;
            }
            for (int64_t x = lo[0]; x <= hi[0] && !near[t]; ++x)
                for (int64_t y = lo[1]; y <= hi[1] && !near[t]; ++y)
                    for (int64_t z = lo[2]; z <= hi[2] && !near[t]; ++z)
                        for (auto it = std::lower_bound(cells.begin(), cells.end(), std::make_pair(key(x, y, z), 0u));
                             it != cells.end() && it->first == key(x, y, z); ++it)
                            if (boxes_overlap(box, boxes[it->second])) {
                                near[t] = 1;
                                break;
                            }
        }
    });
    std::vector<uint32_t> result;
    for (size_t t = 0; t < near.size(); ++t)
        if (near[t]) result.push_back(uint32_t(t));
    return result;
}

// The crossing pairs of the whole mesh with a candidate in them (all pairs
// when `candidates` is empty), unsorted.
std::vector<std::pair<uint32_t, uint32_t>> pairs_among(const Mesh& mesh, const std::vector<char>& candidates) {
    const size_t count = mesh.triangles.size();
    if (count < 2) return {};
    std::vector<Box> boxes(count);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, count), [&](const tbb::blocked_range<size_t>& range) {
        for (size_t t = range.begin(); t != range.end(); ++t) boxes[t] = box_of(mesh, mesh.triangles[t]);
    });
    const Grids grids(boxes);
    const std::vector<char> embedded = embedded_fans(mesh, candidates);

    tbb::enumerable_thread_specific<std::vector<std::pair<uint32_t, uint32_t>>> found;
    // Tests the pair met in `cell` unless another cell owns it; `i_low` and
    // `j_low`: the cells of that level holding their boxes' lowest corners.
    const auto test = [&](uint32_t i, uint32_t j, const Box& i_box, const Box& j_box, uint64_t cell, uint64_t i_low,
                          uint64_t j_low) {
        if (!boxes_overlap(i_box, j_box) || grids.common_low_cell(i_low, j_low) != cell) return;
        if (i == j || (!candidates.empty() && !candidates[i] && !candidates[j])) return;
        if (!cross(mesh, embedded, mesh.triangles[i], mesh.triangles[j])) return;
        found.local().emplace_back(std::min(i, j), std::max(i, j));
    };

    for (int level = 0; level < grids.levels(); ++level) {
        const std::vector<uint64_t>& entries = grids.entries(level);
        std::vector<size_t> runs;
        for (size_t e = 0; e < entries.size(); ++e)
            if (e == 0 || grids.cell(entries[e]) != grids.cell(entries[e - 1])) runs.push_back(e);
        runs.push_back(entries.size());
        tbb::parallel_for(tbb::blocked_range<size_t>(0, runs.size() - 1), [&](const tbb::blocked_range<size_t>& range) {
            // The run's triangles, boxes and lowest cells side by side, read once.
            std::vector<uint32_t> run_triangles;
            std::vector<Box> run_boxes;
            std::vector<uint64_t> run_lows;
            for (size_t r = range.begin(); r != range.end(); ++r) {
                const size_t size = runs[r + 1] - runs[r];
                const uint64_t cell = grids.cell(entries[runs[r]]);
                run_triangles.resize(size);
                run_boxes.resize(size);
                run_lows.resize(size);
                for (size_t e = 0; e < size; ++e) {
                    run_triangles[e] = grids.triangle(entries[runs[r] + e]);
                    run_boxes[e] = boxes[run_triangles[e]];
                    run_lows[e] = grids.low_cell(run_triangles[e]);
                }
                for (size_t e = 0; e < size; ++e)
                    for (size_t f = e + 1; f < size; ++f)
                        test(run_triangles[e], run_triangles[f], run_boxes[e], run_boxes[f], cell, run_lows[e],
                             run_lows[f]);
            }
        });
    }
    if (grids.levels() > 1)
        tbb::parallel_for(tbb::blocked_range<size_t>(0, count), [&](const tbb::blocked_range<size_t>& range) {
            for (size_t t = range.begin(); t != range.end(); ++t)
                for (int level = grids.level(t) + 1; level < grids.levels(); ++level) {
                    const std::vector<uint64_t>& entries = grids.entries(level);
                    const uint64_t t_low = grids.cell_of(boxes[t].lo, level);
                    grids.for_each_cell(boxes[t], level, [&](uint64_t cell) {
                        auto it = std::lower_bound(entries.begin(), entries.end(), grids.entry_of(cell, 0));
                        for (; it != entries.end() && grids.cell(*it) == cell; ++it) {
                            const uint32_t other = grids.triangle(*it);
                            test(uint32_t(t), other, boxes[t], boxes[other], cell, t_low, grids.low_cell(other));
                        }
                    });
                }
        });
    std::vector<std::pair<uint32_t, uint32_t>> pairs;
    for (const auto& local : found) pairs.insert(pairs.end(), local.begin(), local.end());
    return pairs;
}

}  // namespace

// With candidates, only the triangles near them are searched: the part of
// the mesh they make up has the same crossing pairs with a candidate (a
// vertex whose fan is cut off there counts as not embedded, so its pairs are
// tested exactly).
std::vector<std::pair<uint32_t, uint32_t>> crossing_pairs(const Mesh& mesh, const std::vector<char>& candidates) {
    std::vector<std::pair<uint32_t, uint32_t>> pairs;
    if (candidates.empty()) {
        pairs = pairs_among(mesh, candidates);
    } else {
        const std::vector<uint32_t> near = near_candidates(mesh, candidates);
        Mesh part{mesh.vertices, {}};
        std::vector<char> part_candidates(near.size());
        part.triangles.reserve(near.size());
        for (size_t i = 0; i < near.size(); ++i) {
            part.triangles.push_back(mesh.triangles[near[i]]);
            part_candidates[i] = candidates[near[i]];
        }
        pairs = pairs_among(part, part_candidates);
        for (auto& [i, j] : pairs) i = near[i], j = near[j];
    }
    std::sort(pairs.begin(), pairs.end());
    return pairs;
}

}  // namespace fabvdb::volume
