//! smooth_boundaries: snake extraction from the part labels, numerical
//! gradient of the local smoothness terms, one-vertex finite differences of
//! E with the labels held, sequential projected moves with fold checks, then
//! incremental overlap terms (the touched parts' axes each iteration, the
//! other axes once at the end) and parting lines of the touched parts (their
//! surfaces and flow networks kept over the iterations, only the moved
//! triangles measured again), with step halving when an iteration does not
//! lower E.
#include "surface/boundary_smoothing.h"

#include <algorithm>
#include <memory>
#include <set>
#include <tuple>

#include <openvdb/math/Proximity.h>
#include <tbb/parallel_for.h>

#include "core/vec3_ops.h"

namespace fabvdb::surface {

namespace {

using Corners = std::array<Vec3, 3>;

//! Cosine of the angle at x between the directions to a and b.
double corner_cosine(const Vec3& x, const Vec3& a, const Vec3& b) {
    const Vec3 p = a - x, q = b - x;
    const double l = norm(p) * norm(q);
    return l > 0 ? dot(p, q) / l : 1.0;
}

class Smoother {
public:
    Smoother(Shell& shell, MoldabilityTerms& terms, Decomposition& decomposition, const DecompositionOptions& options,
             const std::vector<char>* selected)
        : shell_(shell),
          terms_(terms),
          d_(decomposition),
          options_(options),
          vertex_count_(shell.outer.vertices.size()),
          reference_(shell.outer),
          reference_inner_(shell.inner),
          reference_normal_(shell.normal),
          around_(vertex_count_),
          boundary_(vertex_count_),
          networks_(decomposition.parts.size()) {
        for (size_t t = 0; t < shell.triangle_count(); ++t)
            for (uint32_t v : shell.outer.triangles[t]) around_[v].push_back(uint32_t(t));
        for (size_t t = 0; t < shell.triangle_count(); ++t) {
            const Triangle& f = shell.outer.triangles[t];
            for (int k = 0; k < 3; ++k) {
                const size_t n = size_t(shell.neighbor[t][k]);
                if (n < t || d_.part_of_triangle[n] == d_.part_of_triangle[t]) continue;
                boundary_[f[k]].push_back(f[(k + 1) % 3]);
                boundary_[f[(k + 1) % 3]].push_back(f[k]);
            }
        }
        for (uint32_t v = 0; v < vertex_count_; ++v)
            if (boundary_[v].size() == 2) {
                ++regular_count_;
                if (!selected || (*selected)[v]) movable_.push_back(v);
            }
        // Candidate triangles for projecting a vertex: its two-ring.
        near_.resize(vertex_count_);
        for (uint32_t v : movable_) {
            std::set<uint32_t> ring;
            for (uint32_t t : around_[v])
                for (uint32_t w : shell.outer.triangles[t]) ring.insert(around_[w].begin(), around_[w].end());
            near_[v].assign(ring.begin(), ring.end());
        }
    }

    nlohmann::json run(Progress& progress) {
        nlohmann::json record;
        std::vector<double> smoothness{smoothness_energy()}, moldability{d_.total_energy()};
        std::set<uint32_t> moved_vertices, moved_triangles;
        std::set<int> touched_parts;
        // Axes whose overlaps already follow every accepted move.
        std::vector<char> current(terms_.axes.size(), 1);
        double rho = 0.3;  // step bound, as a fraction of the vertex's shortest edge
        int accepted = 0;
        for (int attempt = 0; attempt < options_.smoothing_iterations && !movable_.empty() && rho > 0.02;
             ++attempt) {
            progress.update(double(attempt) / options_.smoothing_iterations);
            const double energy_before = moldability.back() + options_.smoothness_weight * smoothness.back();
            label_snapshot();
            const std::vector<Move> moves = descent_moves(rho);
            Undo undo;
            apply(moves, undo);
            if (undo.vertices.empty()) break;
            const std::vector<int> parts = recompute(undo);
            const double e_p = d_.total_energy();
            const double e_s = smoothness_energy();
            const bool stays_under = !(moldability.front() < options_.gamma) || e_p < options_.gamma;
            if (e_p + options_.smoothness_weight * e_s < energy_before - 1e-12 && stays_under) {
                smoothness.push_back(e_s);
                moldability.push_back(e_p);
                for (const auto& [v, position] : undo.vertices) moved_vertices.insert(v);
                moved_triangles.insert(undo.triangles.begin(), undo.triangles.end());
                touched_parts.insert(parts.begin(), parts.end());
                for (size_t a = 0; a < current.size(); ++a)
                    if (std::find(undo.axes.begin(), undo.axes.end(), int(a)) == undo.axes.end()) current[a] = 0;
                ++accepted;
            } else {
                revert(undo);
                rho *= 0.5;
            }
        }
        std::vector<int> stale;
        for (size_t a = 0; a < current.size(); ++a)
            if (!current[a]) stale.push_back(int(a));
        update_moldability_terms(shell_, {moved_triangles.begin(), moved_triangles.end()}, stale, terms_);
        record["iterations"] = accepted;
        record["smoothness"] = smoothness;
        record["moldability_energy"] = moldability;
        record["vertices_moved"] = moved_vertices.size();
        record["parts_touched"] = touched_parts;
        return record;
    }

private:
    struct Move {
        uint32_t vertex;
        Vec3 direction;  // unit, tangent
        double step;     // signed length along direction (mm)
    };
    struct Undo {
        std::vector<std::pair<uint32_t, std::pair<Vec3, Vec3>>> vertices;  // outer, inner before the move
        std::vector<uint32_t> triangles;
        std::vector<int> axes;  // the touched parts' axes, whose overlaps were measured again
        std::vector<int> parts;
        std::vector<std::pair<std::vector<char>, MoldabilityEnergy>> labels;  // of `parts` before
    };

    //! Mean corner cosine over the snake vertices with two snake edges.
    double smoothness_energy() const {
        if (regular_count_ == 0) return 0;
        double sum = 0;
        for (uint32_t v = 0; v < vertex_count_; ++v)
            if (boundary_[v].size() == 2) sum += cosine_at(v, v, position(v));
        return sum / double(regular_count_);
    }

    const Vec3& position(uint32_t v) const { return shell_.outer.vertices[v]; }

    //! Corner cosine at snake vertex w with vertex v placed at x.
    double cosine_at(uint32_t w, uint32_t v, const Vec3& x) const {
        const auto at = [&](uint32_t u) { return u == v ? x : position(u); };
        return corner_cosine(at(w), at(boundary_[w][0]), at(boundary_[w][1]));
    }

    //! The smoothness terms that depend on v, with v placed at x.
    double local_smoothness(uint32_t v, const Vec3& x) const {
        double sum = cosine_at(v, v, x);
        for (uint32_t w : boundary_[v])
            if (boundary_[w].size() == 2) sum += cosine_at(w, v, x);
        return sum;
    }

    double shortest_edge(uint32_t v) const {
        double shortest = 1e300;
        for (uint32_t t : around_[v])
            for (uint32_t w : shell_.outer.triangles[t])
                if (w != v) shortest = std::min(shortest, norm(position(w) - position(v)));
        return shortest;
    }

    //! The labels the finite differences hold fixed: M⁺ of each outer triangle
    //! and of the two side triangles of each boundary edge (3·t + k).
    void label_snapshot() {
        outer_upper_.assign(shell_.triangle_count(), 0);
        side_upper_.assign(3 * shell_.triangle_count(), {0, 0});
        const uint32_t v_count = uint32_t(vertex_count_);
        for (const PartMolding& part : d_.parts)
            for (size_t i = 0; i < part.surface.size(); ++i) {
                const uint32_t source = part.surface.source[i];
                if (part.surface.kind[i] == PartSurface::outer) outer_upper_[source] = part.upper[i];
                if (part.surface.kind[i] != PartSurface::side) continue;
                const bool first = part.surface.corners[i][2] >= v_count;  // {a, a', b'} then {a, b', b}
                side_upper_[source][first ? 0 : 1] = part.upper[i];
            }
    }

    //! Where v lands when pushed to x: the closest point of the reference
    //! surface near v, and the inner vertex interpolated there.
    std::pair<Vec3, Vec3> project(uint32_t v, const Vec3& x) const {
        double best = 1e300;
        std::pair<Vec3, Vec3> landing;
        const openvdb::Vec3d p(x[0], x[1], x[2]);
        for (uint32_t t : near_[v]) {
            const Triangle& f = reference_.triangles[t];
            const auto corner = [&](int k) {
                const Vec3& c = reference_.vertices[f[k]];
                return openvdb::Vec3d(c[0], c[1], c[2]);
            };
            openvdb::Vec3d uvw;
            const openvdb::Vec3d q = openvdb::math::closestPointOnTriangleToPoint(corner(0), corner(1), corner(2), p, uvw);
            const double distance = (q - p).lengthSqr();
            if (distance < best) {
                best = distance;
                landing.first = {q[0], q[1], q[2]};
                landing.second = uvw[0] * reference_inner_[f[0]] + uvw[1] * reference_inner_[f[1]] +
                                 uvw[2] * reference_inner_[f[2]];
            }
        }
        return landing;
    }

    //! Whether the triangles around v stay unfolded with v at x.
    bool keeps_shape(uint32_t v, const Vec3& x) const {
        for (uint32_t t : around_[v]) {
            const Corners c = outer_corners(t, v, x);
            const Vec3 n = cross(c[1] - c[0], c[2] - c[0]);
            const Triangle& f = reference_.triangles[t];
            const double reference_twice = norm(cross(reference_.vertices[f[1]] - reference_.vertices[f[0]],
                                                      reference_.vertices[f[2]] - reference_.vertices[f[0]]));
            if (dot(n, reference_normal_[t]) < 0.5 * norm(n) || norm(n) < 0.2 * reference_twice) return false;
        }
        return true;
    }

    Corners outer_corners(uint32_t t, uint32_t v, const Vec3& x) const {
        const Triangle& f = shell_.outer.triangles[t];
        Corners c;
        for (int k = 0; k < 3; ++k) c[k] = f[k] == v ? x : position(f[k]);
        return c;
    }

    //! w_H·E_H + w_L·E_L of the terms that depend on v (its triangles, their
    //! overlaps within their part, the side quads of its snake edges), with
    //! v at x and its inner vertex at inner, labels held.
    double local_moldability(uint32_t v, const Vec3& x, const Vec3& inner) const {
        const double s2 = shell_.unit_scale * shell_.unit_scale;
        const auto& triangles = shell_.outer.triangles;
        const auto in_ring = [&](uint32_t q) { return std::find(around_[v].begin(), around_[v].end(), q) != around_[v].end(); };
        const auto overhang = [&](const Corners& c, bool upper, const Vec3& d) {
            const Vec3 n = cross(c[1] - c[0], c[2] - c[0]);
            return overhang_term(normalized(n), 0.5 * norm(n) * s2, upper ? d : -1.0 * d, terms_.draft);
        };
        double energy = 0;
        for (uint32_t t : around_[v]) {
            const int part = d_.part_of_triangle[t];
            const int direction = d_.parts[part].direction;
            const Vec3& d = terms_.directions.directions[direction];
            const Corners c = outer_corners(t, v, x);
            energy += options_.weights.overhang * overhang(c, outer_upper_[t], d);
            const auto& o = terms_.overlaps_along(direction);
            for (uint32_t k = o.offset[t]; k < o.offset[t + 1]; ++k) {
                const uint32_t q = o.partner[k];
                if (d_.part_of_triangle[q] != part || outer_upper_[q] != outer_upper_[t]) continue;
                const double share = in_ring(q) ? 0.5 : 1.0;
                energy += options_.weights.overlap * share * s2 * projected_overlap(c, outer_corners(q, v, x), d);
            }
            // Side quads along this triangle's snake edges at v.
            const Triangle& f = triangles[t];
            for (int k = 0; k < 3; ++k) {
                const uint32_t a = f[k], b = f[(k + 1) % 3];
                if ((a != v && b != v) || d_.part_of_triangle[shell_.neighbor[t][k]] == part) continue;
                const auto outer_at = [&](uint32_t u) { return u == v ? x : position(u); };
                const auto inner_at = [&](uint32_t u) { return u == v ? inner : shell_.inner[u]; };
                const auto& labels = side_upper_[3 * t + k];
                energy += options_.weights.overhang * overhang({outer_at(a), inner_at(a), inner_at(b)}, labels[0], d);
                energy += options_.weights.overhang * overhang({outer_at(a), inner_at(b), outer_at(b)}, labels[1], d);
            }
        }
        return energy;
    }

    //! E restricted to v's terms, with v at x (inner at inner).
    double local_energy(uint32_t v, const Vec3& x, const Vec3& inner) const {
        return local_moldability(v, x, inner) +
               options_.smoothness_weight * local_smoothness(v, x) / double(regular_count_);
    }

    //! Per movable vertex: the smoothing direction and the gradient-descent
    //! step along it from a one-sided finite difference of E.
    std::vector<Move> descent_moves(double rho) const {
        std::vector<Move> moves(movable_.size());
        std::vector<double> slope(movable_.size(), 0.0), reach(movable_.size(), 0.0);
        tbb::parallel_for(size_t(0), movable_.size(), [&](size_t i) {
            const uint32_t v = movable_[i];
            const Vec3 x = position(v);
            const double edge = shortest_edge(v);
            reach[i] = rho * edge;
            moves[i] = {v, {0, 0, 0}, 0.0};
            const double eta = 1e-4 * edge;
            Vec3 gradient{0, 0, 0};
            for (int k = 0; k < 3; ++k) {
                Vec3 plus = x, minus = x;
                plus[k] += eta;
                minus[k] -= eta;
                gradient[k] = (local_smoothness(v, plus) - local_smoothness(v, minus)) / (2 * eta);
            }
            Vec3 normal{0, 0, 0};
            for (uint32_t t : around_[v]) normal = normal + shell_.area[t] * shell_.normal[t];
            normal = normalized(normal);
            const Vec3 tangent = gradient - dot(gradient, normal) * normal;
            if (norm(tangent) < 1e-12) return;
            const Vec3 u = -1.0 / norm(tangent) * tangent;
            const double h = 0.1 * edge;
            const auto [y, y_inner] = project(v, x + h * u);
            const double along = dot(y - x, u);
            if (along <= 0) return;
            moves[i].direction = u;
            slope[i] = (local_energy(v, y, y_inner) - local_energy(v, x, shell_.inner[v])) / along;
        });
        // One learning rate for all: the median slope moves a median vertex by its bound.
        std::vector<double> magnitudes, reaches;
        for (size_t i = 0; i < slope.size(); ++i)
            if (slope[i] != 0) {
                magnitudes.push_back(std::abs(slope[i]));
                reaches.push_back(reach[i]);
            }
        if (magnitudes.empty()) return {};
        const auto median = [](std::vector<double> values) {
            std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
            return values[values.size() / 2];
        };
        const double rate = median(reaches) / median(magnitudes);
        for (size_t i = 0; i < moves.size(); ++i)
            moves[i].step = std::clamp(-rate * slope[i], -reach[i], reach[i]);
        return moves;
    }

    void set_vertex(uint32_t v, const Vec3& outer, const Vec3& inner) {
        shell_.outer.vertices[v] = outer;
        shell_.inner[v] = inner;
        const double s2 = shell_.unit_scale * shell_.unit_scale;
        for (uint32_t t : around_[v]) {
            const Triangle& f = shell_.outer.triangles[t];
            const Vec3 c = cross(position(f[1]) - position(f[0]), position(f[2]) - position(f[0]));
            shell_.normal[t] = normalized(c);
            shell_.area[t] = 0.5 * norm(c) * s2;
        }
    }

    //! Moves the vertices one after the other (each checked against its
    //! neighbours' new places), halving a step that would fold a triangle.
    void apply(const std::vector<Move>& moves, Undo& undo) {
        std::set<uint32_t> triangles;
        for (const Move& m : moves) {
            if (m.step == 0) continue;
            const Vec3 x = position(m.vertex);
            for (double step = m.step; std::abs(step) > 1e-3 * std::abs(m.step); step *= 0.5) {
                const auto [y, y_inner] = project(m.vertex, x + step * m.direction);
                if (!keeps_shape(m.vertex, y)) continue;
                undo.vertices.push_back({m.vertex, {x, shell_.inner[m.vertex]}});
                set_vertex(m.vertex, y, y_inner);
                triangles.insert(around_[m.vertex].begin(), around_[m.vertex].end());
                break;
            }
        }
        undo.triangles.assign(triangles.begin(), triangles.end());
    }

    //! The parts' surfaces and networks follow the moved vertices (in
    //! parallel); a part's network is made the first time it is needed.
    void update_parts(const Undo& undo) {
        std::vector<char> moved(vertex_count_, 0);
        for (const auto& [v, position] : undo.vertices) moved[v] = 1;
        tbb::parallel_for(size_t(0), undo.parts.size(), [&](size_t i) {
            const int p = undo.parts[i];
            const std::vector<uint32_t> changed = update_part_surface(shell_, moved, d_.parts[p].surface);
            if (networks_[p])
                networks_[p]->update(changed);
            else
                networks_[p] = std::make_unique<PartNetwork>(d_.parts[p].surface);
        });
    }

    //! Overlap terms of the moved triangles along the axes of their parts (the
    //! others follow at the end) and parting lines of their parts.
    std::vector<int> recompute(Undo& undo) {
        std::set<int> touched, axes;
        for (uint32_t t : undo.triangles) touched.insert(d_.part_of_triangle[t]);
        for (int p : touched) axes.insert(terms_.axis_of_direction[d_.parts[p].direction]);
        undo.axes.assign(axes.begin(), axes.end());
        update_moldability_terms(shell_, undo.triangles, undo.axes, terms_);
        undo.parts.assign(touched.begin(), touched.end());
        for (int p : undo.parts) undo.labels.emplace_back(d_.parts[p].upper, d_.parts[p].energy);
        update_parts(undo);
        tbb::parallel_for(size_t(0), undo.parts.size(), [&](size_t i) {
            networks_[undo.parts[i]]->relabel(shell_, terms_, options_.weights, d_.parts[undo.parts[i]]);
        });
        return undo.parts;
    }

    void revert(Undo& undo) {
        for (auto it = undo.vertices.rbegin(); it != undo.vertices.rend(); ++it)
            set_vertex(it->first, it->second.first, it->second.second);
        update_moldability_terms(shell_, undo.triangles, undo.axes, terms_);
        update_parts(undo);
        for (size_t i = 0; i < undo.parts.size(); ++i)
            std::tie(d_.parts[undo.parts[i]].upper, d_.parts[undo.parts[i]].energy) = std::move(undo.labels[i]);
    }

    Shell& shell_;
    MoldabilityTerms& terms_;
    Decomposition& d_;
    const DecompositionOptions& options_;
    const size_t vertex_count_;
    const Mesh reference_;
    const std::vector<Vec3> reference_inner_;
    const std::vector<Vec3> reference_normal_;
    std::vector<std::vector<uint32_t>> around_;    // triangles around each vertex
    std::vector<std::vector<uint32_t>> boundary_;  // snake neighbours of each vertex
    std::vector<std::vector<uint32_t>> near_;      // projection candidates of movable vertices
    std::vector<uint32_t> movable_;
    std::vector<std::unique_ptr<PartNetwork>> networks_;  // per part, once relabelled
    size_t regular_count_ = 0;
    std::vector<char> outer_upper_;
    std::vector<std::array<char, 2>> side_upper_;
};

}  // namespace

nlohmann::json smooth_boundaries(Shell& shell, MoldabilityTerms& terms, Decomposition& decomposition,
                                 const DecompositionOptions& options, const std::vector<char>* selected,
                                 Progress& progress) {
    Smoother smoother(shell, terms, decomposition, options, selected);
    return smoother.run(progress);
}

}  // namespace fabvdb::surface
