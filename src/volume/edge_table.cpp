//! The edge table by one parallel sort of the triangles' sides (see edge_table.h).
#include "volume/edge_table.h"

#include <algorithm>
#include <tuple>

#include <tbb/parallel_sort.h>

namespace fabvdb::volume {

EdgeTable build_edge_table(const Mesh& mesh) {
    EdgeTable table;
    table.uses.reserve(mesh.triangles.size() * 3);
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
            if (a != b) table.uses.push_back({std::min(a, b), std::max(a, b), uint32_t(t), a < b});
        }
    tbb::parallel_sort(table.uses.begin(), table.uses.end(), [](const EdgeUse& x, const EdgeUse& y) {
        return std::tie(x.lo, x.hi, x.triangle, x.forward) < std::tie(y.lo, y.hi, y.triangle, y.forward);
    });
    table.begin.reserve(table.uses.size() / 2 + 2);
    for (size_t u = 0; u < table.uses.size(); ++u)
        if (u == 0 || table.uses[u].lo != table.uses[u - 1].lo || table.uses[u].hi != table.uses[u - 1].hi)
            table.begin.push_back(u);
    table.begin.push_back(table.uses.size());
    return table;
}

}  // namespace fabvdb::volume
