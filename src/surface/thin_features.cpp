//! thin_segments: flood fill of the candidate triangles, then the min/mean rule.
#include "surface/thin_features.h"

#include <algorithm>

namespace fabvdb::surface {

std::vector<int> thin_segments(const Mesh& outer, const std::vector<std::array<int, 3>>& neighbor,
                               const std::vector<double>& vertex_depth, double thickness) {
    const size_t n = outer.triangles.size();
    std::vector<double> local(n);
    for (size_t t = 0; t < n; ++t) {
        const Triangle& f = outer.triangles[t];
        local[t] = 2.0 * (vertex_depth[f[0]] + vertex_depth[f[1]] + vertex_depth[f[2]]) / 3.0;
    }
    std::vector<int> segment(n, -1);
    std::vector<char> visited(n, 0);
    int next_id = 0;
    for (size_t start = 0; start < n; ++start) {
        if (visited[start] || local[start] >= 4.0 * thickness) continue;
        std::vector<size_t> members;
        std::vector<size_t> stack{start};
        visited[start] = 1;
        while (!stack.empty()) {
            const size_t t = stack.back();
            stack.pop_back();
            members.push_back(t);
            for (int k = 0; k < 3; ++k) {
                const int other = neighbor[t][k];
                if (other >= 0 && !visited[other] && local[other] < 4.0 * thickness) {
                    visited[other] = 1;
                    stack.push_back(size_t(other));
                }
            }
        }
        double minimum = 1e300, sum = 0;
        for (size_t t : members) {
            minimum = std::min(minimum, local[t]);
            sum += local[t];
        }
        if (minimum < 2.0 * thickness && sum / members.size() < 3.0 * thickness) {
            for (size_t t : members) segment[t] = next_id;
            ++next_id;
        }
    }
    return segment;
}

}  // namespace fabvdb::surface
