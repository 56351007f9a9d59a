//! Independent geometric checks for tests (see ray_cast.h).
#include "support/ray_cast.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <utility>

#include <CGAL/Polygon_mesh_processing/self_intersections.h>

#include "support/cgal_mesh.h"
#include "support/check_vec3.h"

namespace fabvdb::test {

LineCaster::LineCaster(const Mesh& mesh, const Vec3& direction) : mesh_(mesh) {
    w_ = unit(direction);
    const Vec3 helper = std::abs(w_[0]) < 0.6 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    u_ = unit(cross(helper, w_));
    v_ = cross(w_, u_);
    if (mesh.triangles.empty()) return;
    double u1 = -1e300, v1 = -1e300;
    u0_ = v0_ = 1e300;
    for (const Vec3& p : mesh.vertices) {
        u0_ = std::min(u0_, dot(p, u_)), u1 = std::max(u1, dot(p, u_));
        v0_ = std::min(v0_, dot(p, v_)), v1 = std::max(v1, dot(p, v_));
    }
    const int side = std::max(1, int(std::sqrt(double(mesh.triangles.size()) / 2.0)));
    cell_ = std::max(u1 - u0_, v1 - v0_) / side + 1e-12;
    nu_ = int((u1 - u0_) / cell_) + 1;
    nv_ = int((v1 - v0_) / cell_) + 1;
    bins_.assign(size_t(nu_) * size_t(nv_), {});
    for (uint32_t t = 0; t < mesh.triangles.size(); ++t) {
        double a0 = 1e300, a1 = -1e300, b0 = 1e300, b1 = -1e300;
        for (uint32_t i : mesh.triangles[t]) {
            const Vec3& p = mesh.vertices[i];
            a0 = std::min(a0, dot(p, u_)), a1 = std::max(a1, dot(p, u_));
            b0 = std::min(b0, dot(p, v_)), b1 = std::max(b1, dot(p, v_));
        }
        for (int i = int((a0 - u0_) / cell_); i <= std::min(nu_ - 1, int((a1 - u0_) / cell_)); ++i)
            for (int j = int((b0 - v0_) / cell_); j <= std::min(nv_ - 1, int((b1 - v0_) / cell_)); ++j)
                bins_[size_t(i) * size_t(nv_) + size_t(j)].push_back(t);
    }
}

std::vector<double> LineCaster::crossings(const Vec3& point) const {
    // A line through an edge or a vertex would count it once per triangle:
    // such lines are moved aside by a tiny deterministic jitter and re-cast.
    Vec3 at = point;
    for (int attempt = 1;; ++attempt) {
        bool near_edge = false;
        std::vector<double> hits = crossings_once(at, near_edge);
        if (!near_edge || attempt == 8) return hits;
        const double shift = 1e-6 * cell_ * attempt;
        for (int k = 0; k < 3; ++k) at[k] += shift * (0.7548776662 * u_[k] + 0.5698402910 * v_[k]);
    }
}

std::vector<double> LineCaster::crossings_once(const Vec3& point, bool& near_edge) const {
    std::vector<double> hits;
    const double a = dot(point, u_), b = dot(point, v_);
    const int i = int(std::floor((a - u0_) / cell_)), j = int(std::floor((b - v0_) / cell_));
    if (bins_.empty() || i < 0 || j < 0 || i >= nu_ || j >= nv_) return hits;
    for (uint32_t t : bins_[size_t(i) * size_t(nv_) + size_t(j)]) {
        // Möller–Trumbore on the whole line (t of any sign).
        const Vec3& p0 = mesh_.vertices[mesh_.triangles[t][0]];
        const Vec3 e1 = sub(mesh_.vertices[mesh_.triangles[t][1]], p0);
        const Vec3 e2 = sub(mesh_.vertices[mesh_.triangles[t][2]], p0);
        const Vec3 p = cross(w_, e2);
        const double det = dot(e1, p);
        if (std::abs(det) < 1e-300) continue;
        const Vec3 s = sub(point, p0);
        const double bu = dot(s, p) / det;
        if (bu < 0 || bu > 1) continue;
        const Vec3 q = cross(s, e1);
        const double bv = dot(w_, q) / det;
        if (bv < 0 || bu + bv > 1) continue;
        const double margin = 1e-9;
        if (bu < margin || bv < margin || bu + bv > 1 - margin) near_edge = true;
        hits.push_back(dot(e2, q) / det);
    }
    std::sort(hits.begin(), hits.end());
    return hits;
}

bool LineCaster::inside(const Vec3& point) const {
    size_t ahead = 0;
    for (double t : crossings(point)) ahead += t > 0;
    return ahead % 2 == 1;
}

HeightFieldCheck check_double_height_field(const Mesh& mesh, const Vec3& direction, int samples_per_side) {
    LineCaster caster(mesh, direction);
    const Vec3 w = unit(direction);
    const Vec3 helper = std::abs(w[0]) < 0.6 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 u = unit(cross(helper, w)), v = cross(w, u);
    double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300;
    for (const Vec3& p : mesh.vertices) {
        u0 = std::min(u0, dot(p, u)), u1 = std::max(u1, dot(p, u));
        v0 = std::min(v0, dot(p, v)), v1 = std::max(v1, dot(p, v));
    }
    std::mt19937 random(12345);
    std::uniform_real_distribution<double> jitter(0.0, 1.0);
    HeightFieldCheck result;
    for (int i = 0; i < samples_per_side; ++i)
        for (int j = 0; j < samples_per_side; ++j) {
            const double a = u0 + (u1 - u0) * (i + jitter(random)) / samples_per_side;
            const double b = v0 + (v1 - v0) * (j + jitter(random)) / samples_per_side;
            Vec3 point;
            for (int k = 0; k < 3; ++k) point[k] = a * u[k] + b * v[k];
            const size_t count = caster.crossings(point).size();
            if (count == 0) continue;
            ++result.lines;
            result.lines_over_two += count > 2;
            result.odd_lines += count % 2;
            result.max_crossings = std::max(result.max_crossings, count);
        }
    return result;
}

bool closed_two_manifold(const Mesh& mesh) {
    std::map<std::pair<uint32_t, uint32_t>, int> directed;
    for (const auto& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
    for (const auto& [edge, count] : directed) {
        if (count != 1 || edge.first == edge.second) return false;
        auto reverse = directed.find({edge.second, edge.first});
        if (reverse == directed.end() || reverse->second != 1) return false;
    }
    // Around each vertex, follow the fan: next triangle across the outgoing edge.
    std::map<uint32_t, std::map<uint32_t, uint32_t>> fan;  // vertex → (from neighbour → to neighbour)
    for (const auto& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) fan[t[k]][t[(k + 1) % 3]] = t[(k + 2) % 3];
    for (const auto& [vertex, links] : fan) {
        uint32_t start = links.begin()->first, at = start;
        size_t steps = 0;
        do {
            auto next = links.find(at);
            if (next == links.end()) return false;
            at = next->second;
            ++steps;
        } while (at != start && steps <= links.size());
        if (steps != links.size()) return false;
    }
    return true;
}

bool self_intersects(const Mesh& mesh) {
    bool valid = false;
    const cgal::SurfaceMesh surface = cgal::surface_mesh_of(mesh, &valid);
    if (!valid) return true;  // not a valid surface: treated as a failure by the caller's other checks too
    return CGAL::Polygon_mesh_processing::does_self_intersect(surface);
}

Mesh stored_as_float(Mesh mesh) {
    // Through a volatile float: GCC 12.2 at -O2 and above vectorises the
    // round trip of x and y into a pair conversion that it drops as a no-op.
    for (Vec3& p : mesh.vertices)
        for (double& c : p) {
            volatile float rounded = float(c);
            c = rounded;
        }
    return mesh;
}

size_t degenerate_triangle_count(const Mesh& mesh) {
    size_t count = 0;
    for (const auto& t : mesh.triangles) {
        const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
        count += cross(sub(b, a), sub(c, a)) == Vec3{0.0, 0.0, 0.0};
    }
    return count;
}

double sampled_common_volume(const std::vector<const Mesh*>& solids, const Vec3& box_lo, const Vec3& box_hi,
                             int samples_per_side) {
    std::vector<LineCaster> casters;
    casters.reserve(solids.size());
    for (const Mesh* solid : solids) casters.emplace_back(*solid, Vec3{0.0123, 0.0371, 1.0});
    size_t common = 0;
    for (int i = 0; i < samples_per_side; ++i)
        for (int j = 0; j < samples_per_side; ++j)
            for (int k = 0; k < samples_per_side; ++k) {
                Vec3 point;
                const int index[3] = {i, j, k};
                for (int a = 0; a < 3; ++a)
                    point[a] = box_lo[a] + (box_hi[a] - box_lo[a]) * (index[a] + 0.5) / samples_per_side;
                bool all = true;
                for (const LineCaster& caster : casters) all = all && caster.inside(point);
                common += all;
            }
    double cell = 1.0;
    for (int a = 0; a < 3; ++a) cell *= (box_hi[a] - box_lo[a]) / samples_per_side;
    return double(common) * cell;
}

}  // namespace fabvdb::test
