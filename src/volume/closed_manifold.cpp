//! Whether a mesh is a closed oriented 2-manifold (see closed_manifold.h).
//!
//! The triangle (v, a, b) puts the link edge a → b into v's link. The mesh is
//! a closed oriented manifold exactly when every vertex's link edges start at
//! distinct vertices and form a single cycle through all of them.
#include "volume/closed_manifold.h"

#include <algorithm>
#include <atomic>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace fabvdb::volume {

bool is_closed_manifold(const Mesh& mesh) {
    const size_t vertex_count = mesh.vertices.size();
    std::vector<uint32_t> first(vertex_count + 1, 0);
    for (const Triangle& t : mesh.triangles) {
        if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) return false;
        for (uint32_t v : t) ++first[v + 1];
    }
    for (size_t v = 0; v < vertex_count; ++v) first[v + 1] += first[v];
    std::vector<std::pair<uint32_t, uint32_t>> link(first[vertex_count]);
    std::vector<uint32_t> filled(first.begin(), first.end() - 1);
    for (const Triangle& t : mesh.triangles)
        for (int corner = 0; corner < 3; ++corner)
            link[filled[t[corner]]++] = {t[(corner + 1) % 3], t[(corner + 2) % 3]};

    std::atomic<bool> manifold{true};
    tbb::parallel_for(tbb::blocked_range<size_t>(0, vertex_count), [&](const tbb::blocked_range<size_t>& range) {
        for (size_t v = range.begin(); v != range.end() && manifold; ++v) {
            const auto begin = link.begin() + first[v], end = link.begin() + first[v + 1];
            if (begin == end) continue;
            for (auto e = begin; e != end; ++e)
                for (auto f = begin; f != e; ++f)
                    if (f->first == e->first) manifold = false;
            // Walk the link from its first edge; it must come back after all of them.
            size_t steps = 1;
            for (uint32_t at = begin->second; at != begin->first; ++steps) {
                auto next = std::find_if(begin, end, [&](const auto& edge) { return edge.first == at; });
                if (next == end || steps > size_t(end - begin)) {
                    manifold = false;
                    break;
                }
                at = next->second;
            }
            if (steps != size_t(end - begin)) manifold = false;
        }
    });
    return manifold;
}

}  // namespace fabvdb::volume
