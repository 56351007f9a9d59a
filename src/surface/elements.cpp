//! make_elements: union-find over the no-cut sets (thin segments and strokes)
//! restricted to the domain, then element adjacency from triangle adjacency.
#include "surface/elements.h"

#include <algorithm>

#include "core/disjoint_sets.h"

namespace fabvdb::surface {

Elements make_elements(const Shell& shell, const std::vector<std::vector<uint32_t>>& no_cut_sets,
                       const std::vector<char>& domain) {
    const size_t n = shell.triangle_count();
    DisjointSets sets(n);
    const auto unite = [&](uint32_t a, uint32_t b) {
        if (domain[a] && domain[b]) sets.unite(a, b);
    };
    // Each set is joined through its first member in the domain.
    std::vector<int> first_of_segment;
    for (size_t t = 0; t < n; ++t) {
        const int s = shell.thin_segment[t];
        if (s < 0 || !domain[t]) continue;
        if (size_t(s) >= first_of_segment.size()) first_of_segment.resize(size_t(s) + 1, -1);
        if (first_of_segment[s] < 0)
            first_of_segment[s] = int(t);
        else
            unite(uint32_t(first_of_segment[s]), uint32_t(t));
    }
    for (const auto& set : no_cut_sets) {
        const auto first = std::find_if(set.begin(), set.end(), [&](uint32_t t) { return domain[t] != 0; });
        for (auto t = first; t != set.end(); ++t) unite(*first, *t);
    }

    Elements elements;
    elements.element_of_triangle.assign(n, -1);
    std::vector<int> element_of_root(n, -1);
    for (size_t t = 0; t < n; ++t) {
        if (!domain[t]) continue;
        const uint32_t root = sets.find(uint32_t(t));
        if (element_of_root[root] < 0) {
            element_of_root[root] = int(elements.triangles.size());
            elements.triangles.emplace_back();
        }
        const int e = element_of_root[root];
        elements.element_of_triangle[t] = e;
        elements.triangles[e].push_back(uint32_t(t));
    }
    elements.adjacent.resize(elements.triangles.size());
    for (size_t e = 0; e < elements.triangles.size(); ++e) {
        auto& adjacent = elements.adjacent[e];
        for (uint32_t t : elements.triangles[e])
            for (int k = 0; k < 3; ++k) {
                const int other = elements.element_of_triangle[shell.neighbor[t][k]];
                if (other >= 0 && other != int(e)) adjacent.push_back(other);
            }
        std::sort(adjacent.begin(), adjacent.end());
        adjacent.erase(std::unique(adjacent.begin(), adjacent.end()), adjacent.end());
    }
    return elements;
}

}  // namespace fabvdb::surface
