//! Welding of exactly coincident vertices: each position id
//! (volume/position_ids.h) maps to its lowest vertex index.
#include "surface/weld_vertices.h"

#include <limits>

#include "volume/position_ids.h"

namespace fabvdb::surface {

std::vector<uint32_t> coincident_vertex_map(const Mesh& mesh) {
    const volume::PositionIds ids = volume::position_ids(mesh);
    constexpr uint32_t none = std::numeric_limits<uint32_t>::max();
    std::vector<uint32_t> first_at(ids.count, none);
    std::vector<uint32_t> map(mesh.vertices.size());
    for (uint32_t v = 0; v < mesh.vertices.size(); ++v) {
        if (first_at[ids.id[v]] == none) first_at[ids.id[v]] = v;
        map[v] = first_at[ids.id[v]];
    }
    return map;
}

Mesh weld_coincident_vertices(const Mesh& mesh) {
    const std::vector<uint32_t> first = coincident_vertex_map(mesh);
    std::vector<uint32_t> renumbered(mesh.vertices.size());
    Mesh welded;
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
        if (first[v] == v) {
            renumbered[v] = uint32_t(welded.vertices.size());
            welded.vertices.push_back(mesh.vertices[v]);
        } else {
            renumbered[v] = renumbered[first[v]];
        }
    }
    welded.triangles.reserve(mesh.triangles.size());
    for (const Triangle& t : mesh.triangles)
        welded.triangles.push_back({renumbered[t[0]], renumbered[t[1]], renumbered[t[2]]});
    return welded;
}

}  // namespace fabvdb::surface
