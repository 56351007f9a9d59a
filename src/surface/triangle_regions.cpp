//! triangle_regions: union-find over the vertices of the chosen triangles.
#include "surface/triangle_regions.h"

#include <algorithm>

#include "core/disjoint_sets.h"
#include "core/error.h"

namespace fabvdb::surface {

std::vector<TriangleRegion> triangle_regions(const Mesh& mesh, const std::vector<uint8_t>& chosen) {
    if (chosen.size() != mesh.triangles.size())
        throw Error(FABVDB_ERR_INVALID_ARGUMENT, "triangle_regions: one flag per triangle is needed");
    DisjointSets sets(mesh.vertices.size());
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        if (!chosen[t]) continue;
        const Triangle& tri = mesh.triangles[t];
        sets.unite(tri[0], tri[1]);
        sets.unite(tri[0], tri[2]);
    }
    std::vector<int64_t> region_of_root(mesh.vertices.size(), -1);
    std::vector<TriangleRegion> regions;
    std::vector<double> weighted;
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        if (!chosen[t]) continue;
        const Triangle& tri = mesh.triangles[t];
        const uint32_t r = sets.find(tri[0]);
        if (region_of_root[r] < 0) {
            region_of_root[r] = int64_t(regions.size());
            regions.emplace_back();
            regions.back().box.min = regions.back().box.max = mesh.vertices[tri[0]];
        }
        TriangleRegion& region = regions[size_t(region_of_root[r])];
        region.triangles.push_back(uint32_t(t));
        const double area = triangle_area(mesh, tri);
        region.area += area;
        for (int k = 0; k < 3; ++k) {
            const Vec3& p = mesh.vertices[tri[k]];
            region.vertices.push_back(tri[k]);
            region.box.add(p);
            for (int c = 0; c < 3; ++c) region.centroid[c] += area * p[c] / 3.0;
        }
    }
    for (TriangleRegion& region : regions) {
        std::sort(region.vertices.begin(), region.vertices.end());
        region.vertices.erase(std::unique(region.vertices.begin(), region.vertices.end()), region.vertices.end());
        if (region.area > 0.0) {
            for (double& c : region.centroid) c /= region.area;
        } else {
            for (int c = 0; c < 3; ++c) region.centroid[c] = 0.5 * (region.box.min[c] + region.box.max[c]);
        }
    }
    std::stable_sort(regions.begin(), regions.end(),
                     [](const TriangleRegion& a, const TriangleRegion& b) { return a.area > b.area; });
    return regions;
}

}  // namespace fabvdb::surface
