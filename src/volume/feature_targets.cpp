//! Targets on the input's sharp edges and corners (see feature_targets.h).
#include "volume/feature_targets.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include <tbb/parallel_sort.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "volume/edge_table.h"

namespace fabvdb::volume {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Vector = Kernel::Vector_3;

// Normals of the triangles beside a sharp edge turn by more than ~37 degrees
// (cos below this); two sharp edges at a vertex turning as much make a corner.
constexpr double sharp_cos = 0.8;
// A surface vertex is drawn by a feature only if its normal is within 60
// degrees of one of the feature's triangles (not the far side of a thin wall).
constexpr double min_facing = 0.5;
// An edge draws it only if the normal of the input triangle closest to it is
// also within 60 degrees of one of the edge's two (cos): a vertex on another
// shell that a sharp edge passes under stays there. (Corners do not ask this: the
// triangle closest to a vertex near a corner may be any around it.)
constexpr double min_alignment = 0.5;

Point point(const Vec3& v) { return Point(v[0], v[1], v[2]); }

Vector unit(const Vector& v) {
    const double length = std::sqrt(v.squared_length());
    return length > 0.0 ? v / length : Vector(0, 0, 0);
}

Vector unit_normal(const Mesh& mesh, const Triangle& t) {
    const Vec3 n = triangle_normal(mesh, t);
    return unit(Vector(n[0], n[1], n[2]));
}

struct SharpEdge {
    uint32_t a, b;
    Vector normal_a, normal_b;  // of the two triangles beside it
};

// Edges used by exactly two triangles in opposite directions (consistently
// oriented) whose normals turn by more than the sharp angle.
std::vector<SharpEdge> sharp_edges(const Mesh& input) {
    const EdgeTable table = build_edge_table(input);
    std::vector<SharpEdge> edges;
    for (size_t e = 0; e < table.edge_count(); ++e) {
        if (table.use_count(e) != 2) continue;
        const EdgeUse &first = table.uses[table.begin[e]], &second = table.uses[table.begin[e] + 1];
        if (first.forward == second.forward) continue;
        const Vector n0 = unit_normal(input, input.triangles[first.triangle]);
        const Vector n1 = unit_normal(input, input.triangles[second.triangle]);
        if (n0 != CGAL::NULL_VECTOR && n1 != CGAL::NULL_VECTOR && n0 * n1 < sharp_cos)
            edges.push_back({first.lo, first.hi, n0, n1});
    }
    return edges;
}

// The surface's vertices bucketed in cubic cells of side `reach`, to find
// the nearest one within reach of a point.
class VertexGrid {
public:
    VertexGrid(const Mesh& surface, double reach) : surface_(surface), reach_(reach) {
        entries_.reserve(surface.vertices.size());
        for (uint32_t v = 0; v < surface.vertices.size(); ++v) entries_.push_back({cell_key(surface.vertices[v], 0, 0, 0), v});
        tbb::parallel_sort(entries_.begin(), entries_.end());
    }

    // The vertex nearest to p within reach for which `accept(v)` holds, or -1.
    template <class Accept>
    int64_t nearest(const Vec3& p, const Accept& accept) const {
        int64_t best = -1;
        double best_squared = reach_ * reach_;
        for (int dx = -1; dx <= 1; ++dx)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dz = -1; dz <= 1; ++dz) {
                    const uint64_t key = cell_key(p, dx, dy, dz);
                    auto it = std::lower_bound(entries_.begin(), entries_.end(), std::pair<uint64_t, uint32_t>(key, 0));
                    for (; it != entries_.end() && it->first == key; ++it) {
                        const double squared = CGAL::squared_distance(point(p), point(surface_.vertices[it->second]));
                        if (squared <= best_squared && accept(it->second)) {
                            best_squared = squared;
                            best = it->second;
                        }
                    }
                }
        return best;
    }

private:
    uint64_t cell_key(const Vec3& p, int dx, int dy, int dz) const {
        const int offsets[3] = {dx, dy, dz};
        uint64_t key = 0;
        for (int k = 0; k < 3; ++k) {
            const int64_t cell = int64_t(std::floor(p[k] / reach_)) + offsets[k] + (int64_t(1) << 20);
            key = (key << 21) | (uint64_t(cell) & ((uint64_t(1) << 21) - 1));
        }
        return key;
    }

    const Mesh& surface_;
    double reach_;
    std::vector<std::pair<uint64_t, uint32_t>> entries_;
};

}  // namespace

FeatureTargets feature_targets(const Mesh& surface, const std::vector<Vec3>& surface_normals,
                               const std::vector<Vec3>& nearest_input_normals, const Mesh& input, double reach) {
    FeatureTargets targets;
    targets.has_target.assign(surface.vertices.size(), 0);
    targets.target.resize(surface.vertices.size());
    const std::vector<SharpEdge> edges = sharp_edges(input);
    if (edges.empty()) return targets;
    const VertexGrid grid(surface, reach);
    const auto faces = [&](uint32_t v, const Vector& normal) {
        const Vector n = unit(Vector(surface_normals[v][0], surface_normals[v][1], surface_normals[v][2]));
        return n * normal >= min_facing;
    };
    const auto aligned = [&](uint32_t v, const Vector& normal) {
        const Vec3& nearest = nearest_input_normals[v];
        return faces(v, normal) && Vector(nearest[0], nearest[1], nearest[2]) * normal >= min_alignment;
    };

    // Corners: vertices with three or more sharp edges, or two that turn.
    std::vector<std::vector<uint32_t>> edges_at(input.vertices.size());
    for (uint32_t e = 0; e < edges.size(); ++e) {
        edges_at[edges[e].a].push_back(e);
        edges_at[edges[e].b].push_back(e);
    }
    std::vector<char> corner_drawn(surface.vertices.size(), 0);
    for (uint32_t c = 0; c < input.vertices.size(); ++c) {
        const auto& at = edges_at[c];
        if (at.size() < 2) continue;
        if (at.size() == 2) {
            const auto other = [&](uint32_t e) { return edges[e].a == c ? edges[e].b : edges[e].a; };
            const Point p = point(input.vertices[c]);
            const Vector in = unit(p - point(input.vertices[other(at[0])]));
            const Vector out = unit(point(input.vertices[other(at[1])]) - p);
            if (in * out >= sharp_cos) continue;
        }
        const int64_t v = grid.nearest(input.vertices[c], [&](uint32_t v) {
            return std::any_of(at.begin(), at.end(), [&](uint32_t e) {
                return faces(v, edges[e].normal_a) || faces(v, edges[e].normal_b);
            });
        });
        if (v < 0) continue;
        targets.has_target[v] = 1;
        targets.target[v] = input.vertices[c];
        corner_drawn[v] = 1;
    }

    // Edges: the vertex nearest to each sample goes to its closest point on
    // the edge; a vertex drawn by several edges goes to the nearest one.
    std::vector<double> drawn_distance(surface.vertices.size(), std::numeric_limits<double>::infinity());
    const double spacing = 0.5 * reach;
    for (const SharpEdge& edge : edges) {
        const Point a = point(input.vertices[edge.a]), b = point(input.vertices[edge.b]);
        const Kernel::Segment_3 segment(a, b);
        const int steps = std::max(1, int(std::ceil(std::sqrt(segment.squared_length()) / spacing)));
        for (int i = 0; i <= steps; ++i) {
            const Point s = a + (b - a) * (double(i) / steps);
            const int64_t v = grid.nearest({s.x(), s.y(), s.z()}, [&](uint32_t v) {
                return !corner_drawn[v] && (aligned(v, edge.normal_a) || aligned(v, edge.normal_b));
            });
            if (v < 0) continue;
            const Point p = point(surface.vertices[v]);
            const Vector ab = b - a;
            const double along = std::clamp(((p - a) * ab) / ab.squared_length(), 0.0, 1.0);
            const Point q = a + ab * along;
            const double distance = std::sqrt(CGAL::squared_distance(p, q));
            if (distance > reach || distance >= drawn_distance[v]) continue;
            drawn_distance[v] = distance;
            targets.has_target[v] = 1;
            targets.target[v] = {q.x(), q.y(), q.z()};
        }
    }
    return targets;
}

}  // namespace fabvdb::volume
