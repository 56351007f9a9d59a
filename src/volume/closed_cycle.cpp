//! Whether a mesh is a closed cycle (see closed_cycle.h).
#include "volume/closed_cycle.h"

#include <algorithm>
#include <numeric>

namespace fabvdb::volume {

bool is_closed_cycle(const Mesh& mesh) {
    // One id per distinct position.
    std::vector<uint32_t> by_position(mesh.vertices.size());
    std::iota(by_position.begin(), by_position.end(), 0u);
    std::sort(by_position.begin(), by_position.end(),
              [&](uint32_t a, uint32_t b) { return mesh.vertices[a] < mesh.vertices[b]; });
    std::vector<uint32_t> position_id(mesh.vertices.size());
    for (size_t i = 0, id = 0; i < by_position.size(); ++i) {
        if (i > 0 && mesh.vertices[by_position[i]] != mesh.vertices[by_position[i - 1]]) ++id;
        position_id[by_position[i]] = uint32_t(id);
    }
    // Each directed edge as (undirected key, +1 or -1); every key must sum to 0.
    std::vector<std::pair<uint64_t, int>> edges;
    edges.reserve(3 * mesh.triangles.size());
    for (const Triangle& t : mesh.triangles)
        for (int corner = 0; corner < 3; ++corner) {
            const uint32_t from = position_id[t[corner]], to = position_id[t[(corner + 1) % 3]];
            if (from == to) continue;
            edges.emplace_back(uint64_t(std::min(from, to)) << 32 | std::max(from, to), from < to ? 1 : -1);
        }
    std::sort(edges.begin(), edges.end());
    for (size_t i = 0; i < edges.size();) {
        int sum = 0;
        size_t j = i;
        for (; j < edges.size() && edges[j].first == edges[i].first; ++j) sum += edges[j].second;
        if (sum != 0) return false;
        i = j;
    }
    return true;
}

}  // namespace fabvdb::volume
