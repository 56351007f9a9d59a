//! Rounding a closed mesh to floats without crossings (see float_rounding.h).
#include "surface/float_rounding.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "core/error.h"
#include "core/float_coordinates.h"
#include "surface/degenerate_triangles.h"
#include "volume/closed_manifold.h"
#include "volume/crossing_pairs.h"

namespace fabvdb::surface {

namespace {

using Point = CGAL::Epick::Point_3;

Point point(const Vec3& p) { return {p[0], p[1], p[2]}; }

//! A float step at the largest coordinate of p.
double float_step(const Vec3& p) {
    const float largest = float(std::max({std::abs(p[0]), std::abs(p[1]), std::abs(p[2])}));
    return double(std::nextafter(largest, HUGE_VALF)) - double(largest);
}

struct Offences {
    std::vector<uint32_t> degenerate;                      //!< triangles
    std::vector<std::pair<uint32_t, uint32_t>> crossings;  //!< pairs of triangles
    bool empty() const { return degenerate.empty() && crossings.empty(); }
    std::vector<uint32_t> triangles() const {
        std::vector<uint32_t> all = degenerate;
        for (const auto& [a, b] : crossings) all.insert(all.end(), {a, b});
        std::sort(all.begin(), all.end());
        all.erase(std::unique(all.begin(), all.end()), all.end());
        return all;
    }
};

struct Box {
    Vec3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    void add(const Vec3& p) {
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], p[k]);
            hi[k] = std::max(hi[k], p[k]);
        }
    }
    bool overlaps(const Box& other) const {
        for (int k = 0; k < 3; ++k)
            if (hi[k] < other.lo[k] || other.hi[k] < lo[k]) return false;
        return true;
    }
};

class Rounding {
public:
    Rounding(const Mesh& mesh, int search_ulps)
        : exact_(mesh.vertices), mesh_(mesh), search_ulps_(search_ulps), star_(mesh.vertices.size()),
          alive_(mesh.triangles.size(), 1) {
        for (Vec3& p : mesh_.vertices) p = nearest_float(p);
        for (size_t t = 0; t < mesh_.triangles.size(); ++t)
            for (uint32_t v : mesh_.triangles[t]) star_[v].push_back(uint32_t(t));
    }

    //! Living triangles that are degenerate, and pairs that cross; with
    //! `candidates` (per triangle), only those with one of them are tested.
    Offences offences(const std::vector<char>& candidates) const {
        Mesh living;
        living.vertices = mesh_.vertices;
        std::vector<uint32_t> id;
        std::vector<char> living_candidates;
        Offences found;
        for (size_t t = 0; t < mesh_.triangles.size(); ++t) {
            if (!alive_[t]) continue;
            const bool candidate = candidates.empty() || candidates[t];
            if (candidate && is_degenerate_triangle(mesh_, mesh_.triangles[t])) found.degenerate.push_back(uint32_t(t));
            living.triangles.push_back(mesh_.triangles[t]);
            id.push_back(uint32_t(t));
            if (!candidates.empty()) living_candidates.push_back(candidates[t]);
        }
        for (const auto& [a, b] : volume::crossing_pairs(living, living_candidates))
            found.crossings.emplace_back(id[a], id[b]);
        std::sort(found.crossings.begin(), found.crossings.end());
        return found;
    }

    //! Moves each corner of a crossing pair, not shared with the other
    //! triangle, to the float position nearest its exact one (within the
    //! search steps) on the side of the other triangle's plane where its
    //! exact position is: rounding directed away from the surface it grazes.
    //! Returns the vertices moved.
    std::vector<uint32_t> separate(const std::vector<std::pair<uint32_t, uint32_t>>& crossings) {
        std::vector<std::pair<uint32_t, uint32_t>> sides;  // (vertex, triangle whose plane it must keep to)
        for (const auto& [a, b] : crossings)
            for (const auto& [own, other] : {std::pair{a, b}, std::pair{b, a}})
                for (uint32_t v : mesh_.triangles[own]) {
                    const Triangle& plane = mesh_.triangles[other];
                    if (v != plane[0] && v != plane[1] && v != plane[2]) sides.emplace_back(v, other);
                }
        std::sort(sides.begin(), sides.end());
        sides.erase(std::unique(sides.begin(), sides.end()), sides.end());
        std::vector<uint32_t> moved;
        for (size_t first = 0; first < sides.size();) {
            const uint32_t v = sides[first].first;
            size_t last = first;
            std::vector<std::pair<uint32_t, CGAL::Orientation>> planes;
            for (; last < sides.size() && sides[last].first == v; ++last) {
                const Triangle& plane = mesh_.triangles[sides[last].second];
                const CGAL::Orientation side = CGAL::orientation(point(exact_[plane[0]]), point(exact_[plane[1]]),
                                                                 point(exact_[plane[2]]), point(exact_[v]));
                if (side != CGAL::COPLANAR) planes.emplace_back(sides[last].second, side);
            }
            first = last;
            if (planes.empty()) continue;
            for (const Vec3& p : candidate_positions(v)) {
                const bool kept = std::all_of(planes.begin(), planes.end(), [&](const auto& plane) {
                    const Triangle& t = mesh_.triangles[plane.first];
                    return CGAL::orientation(point(mesh_.vertices[t[0]]), point(mesh_.vertices[t[1]]),
                                             point(mesh_.vertices[t[2]]), point(p)) == plane.second;
                });
                if (!kept) continue;
                if (p != mesh_.vertices[v]) {
                    mesh_.vertices[v] = p;
                    moved.push_back(v);
                }
                break;
            }
        }
        return moved;
    }

    //! Moves `v` to the float position nearest its exact one, within the
    //! search steps, at which its triangles are valid; false (v unmoved) when
    //! there is none.
    bool place(uint32_t v) {
        std::vector<Vec3> positions = candidate_positions(v);
        Box reach;
        for (const Vec3& p : positions) reach.add(p);
        for (uint32_t t : star_[v])
            for (uint32_t corner : mesh_.triangles[t]) reach.add(mesh_.vertices[corner]);
        const std::vector<uint32_t> others = triangles_near(reach, v);
        const Vec3 before = mesh_.vertices[v];
        for (const Vec3& p : positions) {
            mesh_.vertices[v] = p;
            if (star_is_valid(v, others)) return true;
        }
        mesh_.vertices[v] = before;
        return false;
    }

    //! Collapses the shortest edge of `t` (by exact lengths) under
    //! `max_length` whose collapse keeps the mesh a 2-manifold, into the
    //! endpoint whose triangles are then valid (the first endpoint when
    //! neither is). Returns the vertex kept, or none when no edge of t can go.
    std::optional<uint32_t> collapse_shortest_edge(uint32_t t, double max_length) {
        std::array<std::pair<double, int>, 3> edges;
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = mesh_.triangles[t][k], b = mesh_.triangles[t][(k + 1) % 3];
            edges[k] = {squared_distance(exact_[a], exact_[b]), k};
        }
        std::sort(edges.begin(), edges.end());
        for (const auto& [length, k] : edges) {
            const uint32_t a = mesh_.triangles[t][k], b = mesh_.triangles[t][(k + 1) % 3];
            if (length > max_length * max_length) break;
            if (!link_condition(a, b)) continue;
            for (const auto& [kept, removed] : {std::pair{a, b}, std::pair{b, a}}) {
                const Undo undo = collapse(kept, removed);
                Box reach;
                for (uint32_t s : star_[kept])
                    for (uint32_t corner : mesh_.triangles[s]) reach.add(mesh_.vertices[corner]);
                if (star_is_valid(kept, triangles_near(reach, kept))) return kept;
                restore(undo);
            }
            collapse(a, b);
            return a;
        }
        return std::nullopt;
    }

    const std::vector<uint32_t>& star(uint32_t v) const { return star_[v]; }
    const Vec3& exact(uint32_t v) const { return exact_[v]; }
    bool alive(uint32_t t) const { return alive_[t]; }
    size_t triangle_count() const { return mesh_.triangles.size(); }
    const Triangle& triangle(uint32_t t) const { return mesh_.triangles[t]; }

    //! The living triangles and the vertices they use, in their order.
    Mesh result() const {
        std::vector<uint32_t> index(mesh_.vertices.size(), UINT32_MAX);
        for (size_t t = 0; t < mesh_.triangles.size(); ++t)
            if (alive_[t])
                for (uint32_t corner : mesh_.triangles[t]) index[corner] = 0;
        Mesh out;
        for (size_t v = 0; v < mesh_.vertices.size(); ++v)
            if (index[v] == 0) {
                index[v] = uint32_t(out.vertices.size());
                out.vertices.push_back(mesh_.vertices[v]);
            }
        for (size_t t = 0; t < mesh_.triangles.size(); ++t)
            if (alive_[t]) {
                const Triangle& triangle = mesh_.triangles[t];
                out.triangles.push_back({index[triangle[0]], index[triangle[1]], index[triangle[2]]});
            }
        return out;
    }

private:
    struct Undo {
        uint32_t kept = 0, removed = 0;
        std::vector<uint32_t> kept_star, removed_star;
        std::vector<std::pair<uint32_t, Triangle>> triangles;
        std::vector<uint32_t> killed;
        Vec3 kept_position{0, 0, 0};
    };

    //! The float positions within the search steps of v's nearest float
    //! position, nearest to its exact position first.
    std::vector<Vec3> candidate_positions(uint32_t v) const {
        std::array<std::vector<double>, 3> axis;
        for (int k = 0; k < 3; ++k) {
            const float nearest = float(exact_[v][k]);
            axis[k].push_back(nearest);
            float down = nearest, up = nearest;
            for (int s = 0; s < search_ulps_; ++s) {
                down = std::nextafter(down, -HUGE_VALF);
                up = std::nextafter(up, HUGE_VALF);
                axis[k].push_back(down);
                axis[k].push_back(up);
            }
        }
        std::vector<Vec3> positions;
        for (double x : axis[0])
            for (double y : axis[1])
                for (double z : axis[2]) positions.push_back({x, y, z});
        std::stable_sort(positions.begin(), positions.end(), [&](const Vec3& p, const Vec3& q) {
            return squared_distance(p, exact_[v]) < squared_distance(q, exact_[v]);
        });
        return positions;
    }

    //! Living triangles without v whose boxes meet `reach`.
    std::vector<uint32_t> triangles_near(const Box& reach, uint32_t v) const {
        std::vector<uint32_t> near;
        for (size_t t = 0; t < mesh_.triangles.size(); ++t) {
            if (!alive_[t]) continue;
            const Triangle& triangle = mesh_.triangles[t];
            if (triangle[0] == v || triangle[1] == v || triangle[2] == v) continue;
            Box box;
            for (uint32_t corner : triangle) box.add(mesh_.vertices[corner]);
            if (box.overlaps(reach)) near.push_back(uint32_t(t));
        }
        return near;
    }

    //! No triangle of v degenerate, and none crossing another of its own or
    //! one of `others`.
    bool star_is_valid(uint32_t v, const std::vector<uint32_t>& others) const {
        Mesh local;
        std::vector<char> of_star;
        std::unordered_map<uint32_t, uint32_t> index;
        const auto local_index = [&](uint32_t corner) {
            const auto [at, added] = index.emplace(corner, uint32_t(local.vertices.size()));
            if (added) local.vertices.push_back(mesh_.vertices[corner]);
            return at->second;
        };
        const auto add = [&](uint32_t t, bool in_star) {
            const Triangle& triangle = mesh_.triangles[t];
            local.triangles.push_back({local_index(triangle[0]), local_index(triangle[1]), local_index(triangle[2])});
            of_star.push_back(in_star);
        };
        for (uint32_t t : star_[v]) {
            if (is_degenerate_triangle(mesh_, mesh_.triangles[t])) return false;
            add(t, true);
        }
        for (uint32_t t : others) add(t, false);
        return volume::crossing_pairs(local, of_star).empty();
    }

    //! Whether collapsing edge ab keeps a closed 2-manifold: the vertices
    //! next to both a and b are exactly the corners opposite the edge.
    bool link_condition(uint32_t a, uint32_t b) const {
        std::vector<uint32_t> around_a, around_b, opposite;
        for (uint32_t t : star_[a]) {
            const Triangle& triangle = mesh_.triangles[t];
            const bool has_b = triangle[0] == b || triangle[1] == b || triangle[2] == b;
            for (uint32_t corner : triangle) {
                if (corner == a) continue;
                around_a.push_back(corner);
                if (has_b && corner != b) opposite.push_back(corner);
            }
        }
        for (uint32_t t : star_[b])
            for (uint32_t corner : mesh_.triangles[t])
                if (corner != b) around_b.push_back(corner);
        for (auto* list : {&around_a, &around_b, &opposite}) {
            std::sort(list->begin(), list->end());
            list->erase(std::unique(list->begin(), list->end()), list->end());
        }
        std::vector<uint32_t> common;
        std::set_intersection(around_a.begin(), around_a.end(), around_b.begin(), around_b.end(),
                              std::back_inserter(common));
        return opposite.size() == 2 && common == opposite;
    }

    //! Edge (kept, removed) collapsed into `kept`, which stays at its exact
    //! position rounded to the nearest float; what to restore if refused.
    Undo collapse(uint32_t kept, uint32_t removed) {
        Undo undo{kept, removed, star_[kept], star_[removed], {}, {}, mesh_.vertices[kept]};
        std::vector<uint32_t> merged;
        for (uint32_t t : star_[kept]) {
            const Triangle& triangle = mesh_.triangles[t];
            if (triangle[0] == removed || triangle[1] == removed || triangle[2] == removed) {
                alive_[t] = 0;
                undo.killed.push_back(t);
            } else {
                merged.push_back(t);
            }
        }
        for (uint32_t t : star_[removed]) {
            if (!alive_[t]) continue;
            undo.triangles.emplace_back(t, mesh_.triangles[t]);
            for (uint32_t& corner : mesh_.triangles[t])
                if (corner == removed) corner = kept;
            merged.push_back(t);
        }
        for (uint32_t t : undo.killed)
            for (uint32_t corner : mesh_.triangles[t])
                if (corner != kept && corner != removed)
                    star_[corner].erase(std::remove(star_[corner].begin(), star_[corner].end(), t),
                                        star_[corner].end());
        star_[kept] = std::move(merged);
        star_[removed].clear();
        mesh_.vertices[kept] = nearest_float(exact_[kept]);
        return undo;
    }

    void restore(const Undo& undo) {
        for (uint32_t t : undo.killed) {
            alive_[t] = 1;
            for (uint32_t corner : mesh_.triangles[t])
                if (corner != undo.kept && corner != undo.removed) star_[corner].push_back(t);
        }
        for (const auto& [t, triangle] : undo.triangles) mesh_.triangles[t] = triangle;
        star_[undo.kept] = undo.kept_star;
        star_[undo.removed] = undo.removed_star;
        mesh_.vertices[undo.kept] = undo.kept_position;
    }

    std::vector<Vec3> exact_;
    Mesh mesh_;
    int search_ulps_;
    std::vector<std::vector<uint32_t>> star_;
    std::vector<char> alive_;
};

}  // namespace

Mesh round_to_float(const Mesh& mesh, const std::string& name, const FloatRoundingOptions& options) {
    if (options.search_ulps < 0 || options.search_ulps > 16 || options.max_rounds < 1)
        throw Error(FABVDB_ERR_INVALID_ARGUMENT,
                    "float rounding needs 0 to 16 search steps and at least one round");
    Rounding rounding(mesh, options.search_ulps);
    std::vector<char> candidates;
    std::vector<char> offended_before(mesh.triangles.size(), 0);
    bool untouched = false;  // the first check, of the whole mesh, found nothing to mend
    for (int round = 0; round < options.max_rounds; ++round) {
        const Offences offences = rounding.offences(candidates);
        if (offences.empty()) {
            untouched = round == 0;
            break;
        }
        const std::vector<uint32_t> offending = offences.triangles();
        std::vector<uint32_t> moved = rounding.separate(offences.crossings);
        std::vector<char> offended(rounding.triangle_count(), 0);
        for (uint32_t t : offending) {
            offended[t] = 1;
            if (offended_before[t] && rounding.alive(t)) {
                // A sliver still offending after a round of moves: its
                // shortest edge goes if it is a few hundred float steps long.
                const double step = float_step(rounding.exact(rounding.triangle(t)[0]));
                if (const auto kept = rounding.collapse_shortest_edge(t, 256 * step)) moved.push_back(*kept);
            }
        }
        for (uint32_t t : offences.degenerate)
            if (!offended_before[t])
                for (uint32_t v : rounding.triangle(t))
                    if (rounding.place(v)) moved.push_back(v);
        offended_before = std::move(offended);
        candidates.assign(rounding.triangle_count(), 0);
        for (uint32_t t : offending) candidates[t] = 1;
        for (uint32_t v : moved)
            for (uint32_t t : rounding.star(v)) candidates[t] = 1;
    }
    Mesh rounded = rounding.result();
    if (untouched) return rounded;
    if (!volume::is_closed_manifold(rounded) || !degenerate_triangles(rounded).empty() ||
        !volume::crossing_pairs(rounded).empty())
        throw Error(FABVDB_ERR_INTERNAL, name + " could not be rounded to float coordinates without degenerate "
                                                "or crossing triangles");
    return rounded;
}

}  // namespace fabvdb::surface
