//! Corners grouped by vertex (see vertex_corners.h).
#include "volume/vertex_corners.h"

namespace fabvdb::volume {

VertexCorners::VertexCorners(const Mesh& mesh) : first(mesh.vertices.size() + 1, 0) {
    for (const Triangle& t : mesh.triangles)
        for (uint32_t v : t) ++first[v + 1];
    for (size_t v = 0; v < mesh.vertices.size(); ++v) first[v + 1] += first[v];
    corner.resize(first.back());
    std::vector<uint32_t> filled(first.begin(), first.end() - 1);
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) corner[filled[mesh.triangles[t][k]]++] = uint32_t(3 * t + k);
}

VertexCorners::Across VertexCorners::across(const Mesh& mesh, uint32_t t, int k) const {
    const uint32_t from = mesh.triangles[t][k], to = mesh.triangles[t][(k + 1) % 3];
    Across result;
    for (uint32_t c = first[to]; c != first[to + 1]; ++c) {
        const uint32_t other = corner[c] / 3, at = corner[c] % 3;
        if (mesh.triangles[other][(at + 1) % 3] != from) continue;
        if (result.count++ == 0) result.first = other;
    }
    return result;
}

}  // namespace fabvdb::volume
