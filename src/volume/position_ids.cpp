//! Position ids by a parallel sort of the vertex indices (see position_ids.h).
#include "volume/position_ids.h"

#include <numeric>

#include <tbb/parallel_sort.h>

namespace fabvdb::volume {

PositionIds position_ids(const Mesh& mesh) {
    std::vector<uint32_t> order(mesh.vertices.size());
    std::iota(order.begin(), order.end(), 0u);
    // std::array's operator< is lexicographic with double's <: equal
    // positions (also -0.0 and 0.0) end up adjacent.
    tbb::parallel_sort(order.begin(), order.end(),
                       [&](uint32_t a, uint32_t b) { return mesh.vertices[a] < mesh.vertices[b]; });
    PositionIds ids;
    ids.id.resize(mesh.vertices.size());
    for (size_t i = 0; i < order.size(); ++i) {
        if (i > 0 && mesh.vertices[order[i - 1]] < mesh.vertices[order[i]]) ++ids.count;
        ids.id[order[i]] = ids.count;
    }
    if (!order.empty()) ++ids.count;
    return ids;
}

Mesh weld_positions(const Mesh& mesh) {
    const PositionIds ids = position_ids(mesh);
    Mesh welded;
    welded.vertices.resize(ids.count);
    for (size_t v = 0; v < mesh.vertices.size(); ++v) welded.vertices[ids.id[v]] = mesh.vertices[v];
    welded.triangles.reserve(mesh.triangles.size());
    for (const Triangle& t : mesh.triangles) welded.triangles.push_back({ids.id[t[0]], ids.id[t[1]], ids.id[t[2]]});
    return welded;
}

}  // namespace fabvdb::volume
