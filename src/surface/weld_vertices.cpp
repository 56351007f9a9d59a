//! Welding of exactly coincident vertices: sorts the vertex indices by
//! position, so equal positions form runs, and maps each run to its lowest index.
#include "surface/weld_vertices.h"

#include <algorithm>
#include <numeric>

namespace fabvdb::surface {

std::vector<uint32_t> coincident_vertex_map(const Mesh& mesh) {
    const size_t count = mesh.vertices.size();
    std::vector<uint32_t> order(count);
    std::iota(order.begin(), order.end(), 0u);
    // std::array's operator< compares lexicographically with double's <, under
    // which -0.0 and 0.0 are equivalent: equal positions end up adjacent.
    std::stable_sort(order.begin(), order.end(),
                     [&](uint32_t a, uint32_t b) { return mesh.vertices[a] < mesh.vertices[b]; });
    std::vector<uint32_t> map(count);
    for (size_t run = 0; run < count;) {
        size_t end = run + 1;
        while (end < count && !(mesh.vertices[order[run]] < mesh.vertices[order[end]])) ++end;
        // stable_sort keeps equal positions in index order: the run starts with its lowest index.
        for (size_t k = run; k < end; ++k) map[order[k]] = order[run];
        run = end;
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
