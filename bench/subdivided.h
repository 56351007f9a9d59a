// subdivided(mesh): every triangle split into four at its edge midpoints
// (midpoints shared between neighbours, so a closed manifold stays one). The
// surface does not move; the triangle count is multiplied by four. The
// benchmarks make their million-triangle scans this way from corpus or shared
// models. Costs one map entry per edge.
#pragma once

#include <algorithm>
#include <cstdint>
#include <map>
#include <utility>

#include "core/mesh.h"

namespace fabvdb::bench {

inline Mesh subdivided(const Mesh& mesh) {
    Mesh out;
    out.vertices = mesh.vertices;
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoint;
    const auto middle = [&](uint32_t a, uint32_t b) {
        const auto key = std::minmax(a, b);
        auto [it, inserted] = midpoint.try_emplace({key.first, key.second}, uint32_t(out.vertices.size()));
        if (inserted) {
            const auto &p = mesh.vertices[a], &q = mesh.vertices[b];
            out.vertices.push_back({0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1]), 0.5 * (p[2] + q[2])});
        }
        return it->second;
    };
    for (const auto& t : mesh.triangles) {
        const uint32_t ab = middle(t[0], t[1]), bc = middle(t[1], t[2]), ca = middle(t[2], t[0]);
        out.triangles.push_back({t[0], ab, ca});
        out.triangles.push_back({ab, t[1], bc});
        out.triangles.push_back({ca, bc, t[2]});
        out.triangles.push_back({ab, bc, ca});
    }
    return out;
}

}  // namespace fabvdb::bench
