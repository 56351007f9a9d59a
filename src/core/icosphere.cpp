//! Icosphere by repeated 1-to-4 splits of the icosahedron, midpoints shared
//! between neighbouring triangles so the result is a closed manifold.
#include "core/icosphere.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace fabvdb {

namespace {

Vec3 normalized(const Vec3& p) {
    const double n = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    return {p[0] / n, p[1] / n, p[2] / n};
}

}  // namespace

Mesh unit_icosphere(int splits) {
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    Mesh mesh;
    mesh.vertices = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                     {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    mesh.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9},  {5, 11, 4},
                      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},   {3, 9, 4},  {3, 4, 2},   {3, 2, 6},  {3, 6, 8},
                      {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (Vec3& p : mesh.vertices) p = normalized(p);
    for (int level = 0; level < splits; ++level) {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoint_of_edge;
        auto midpoint = [&](uint32_t a, uint32_t b) {
            const auto key = std::minmax(a, b);
            const auto found = midpoint_of_edge.find(key);
            if (found != midpoint_of_edge.end()) return found->second;
            const Vec3& p = mesh.vertices[a];
            const Vec3& q = mesh.vertices[b];
            mesh.vertices.push_back(normalized({p[0] + q[0], p[1] + q[1], p[2] + q[2]}));
            return midpoint_of_edge[key] = uint32_t(mesh.vertices.size() - 1);
        };
        std::vector<Triangle> finer;
        finer.reserve(mesh.triangles.size() * 4);
        for (const Triangle& f : mesh.triangles) {
            const uint32_t ab = midpoint(f[0], f[1]);
            const uint32_t bc = midpoint(f[1], f[2]);
            const uint32_t ca = midpoint(f[2], f[0]);
            finer.push_back({f[0], ab, ca});
            finer.push_back({f[1], bc, ab});
            finer.push_back({f[2], ca, bc});
            finer.push_back({ab, bc, ca});
        }
        mesh.triangles = std::move(finer);
    }
    return mesh;
}

SphereDirections thesis_directions() {
    SphereDirections result;
    result.directions = unit_icosphere(2).vertices;
    const size_t n = result.directions.size();
    result.opposite.assign(n, -1);
    for (size_t i = 0; i < n; ++i) {
        const Vec3& d = result.directions[i];
        double best = 1e9;
        for (size_t j = 0; j < n; ++j) {
            const Vec3& e = result.directions[j];
            const double distance = std::abs(d[0] + e[0]) + std::abs(d[1] + e[1]) + std::abs(d[2] + e[2]);
            if (distance < best) {
                best = distance;
                result.opposite[i] = int(j);
            }
        }
    }
    return result;
}

}  // namespace fabvdb
