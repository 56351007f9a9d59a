//! Parting coincident vertices (see part_coincident_vertices.h).
#include "volume/part_coincident_vertices.h"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

namespace fabvdb::volume {

size_t part_coincident_vertices(Mesh& mesh) {
    std::vector<uint32_t> order(mesh.vertices.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        return mesh.vertices[a] < mesh.vertices[b] || (mesh.vertices[a] == mesh.vertices[b] && a < b);
    });
    std::vector<char> coincident(mesh.vertices.size(), 0);
    bool any = false;
    for (size_t i = 1; i < order.size(); ++i)
        if (mesh.vertices[order[i]] == mesh.vertices[order[i - 1]]) {
            coincident[order[i]] = coincident[order[i - 1]] = 1;
            any = true;
        }
    if (!any) return 0;
    std::vector<Vec3> ring_sum(mesh.vertices.size(), Vec3{0, 0, 0});
    std::vector<uint32_t> ring_count(mesh.vertices.size(), 0);
    for (const Triangle& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) {
            if (!coincident[t[k]]) continue;
            for (int j = 1; j < 3; ++j)
                for (int a = 0; a < 3; ++a) ring_sum[t[k]][a] += mesh.vertices[t[(k + j) % 3]][a];
            ring_count[t[k]] += 2;
        }
    constexpr double parting = 0.01;
    size_t moved = 0;
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
        if (!coincident[v] || ring_count[v] == 0) continue;
        ++moved;
        for (int a = 0; a < 3; ++a) {
            const double centre = ring_sum[v][a] / ring_count[v];
            mesh.vertices[v][a] += parting * (centre - mesh.vertices[v][a]);
        }
    }
    return moved;
}

}  // namespace fabvdb::volume
