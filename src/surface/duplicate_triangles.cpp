//! Duplicate triangles: sort (sorted index triple, triangle index) and keep
//! every entry equal in its triple to the one before it.
#include "surface/duplicate_triangles.h"

#include <algorithm>
#include <utility>

namespace fabvdb::surface {

std::vector<uint32_t> duplicate_triangles(const Mesh& mesh) {
    std::vector<std::pair<Triangle, uint32_t>> keyed;
    keyed.reserve(mesh.triangles.size());
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        Triangle key = mesh.triangles[t];
        std::sort(key.begin(), key.end());
        keyed.push_back({key, uint32_t(t)});
    }
    std::sort(keyed.begin(), keyed.end());
    std::vector<uint32_t> found;
    for (size_t k = 1; k < keyed.size(); ++k)
        if (keyed[k].first == keyed[k - 1].first) found.push_back(keyed[k].second);
    std::sort(found.begin(), found.end());
    return found;
}

}  // namespace fabvdb::surface
