//! Void regions of a cavity surface (see cavity_regions.h).
#include "volume/cavity_regions.h"

#include <cmath>

#include "volume/mesh_shells.h"

namespace fabvdb::volume {

namespace {

//! Whether the ray from `origin` along a fixed generic direction crosses
//! triangle abc (Möller–Trumbore).
bool ray_crosses(const Vec3& origin, const Vec3& a, const Vec3& b, const Vec3& c) {
    static const double direction[3] = {0.8372, 0.3127, 0.4487};
    const double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double p[3] = {direction[1] * e2[2] - direction[2] * e2[1], direction[2] * e2[0] - direction[0] * e2[2],
                         direction[0] * e2[1] - direction[1] * e2[0]};
    const double det = e1[0] * p[0] + e1[1] * p[1] + e1[2] * p[2];
    if (std::abs(det) < 1e-300) return false;
    const double s[3] = {origin[0] - a[0], origin[1] - a[1], origin[2] - a[2]};
    const double u = (s[0] * p[0] + s[1] * p[1] + s[2] * p[2]) / det;
    if (u < 0.0 || u > 1.0) return false;
    const double q[3] = {s[1] * e1[2] - s[2] * e1[1], s[2] * e1[0] - s[0] * e1[2], s[0] * e1[1] - s[1] * e1[0]};
    const double v = (direction[0] * q[0] + direction[1] * q[1] + direction[2] * q[2]) / det;
    if (v < 0.0 || u + v > 1.0) return false;
    return (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) / det > 0.0;
}

}  // namespace

std::vector<CavityRegion> split_cavity_regions(const Mesh& cavity_surface) {
    const Mesh& mesh = cavity_surface;
    const std::vector<MeshShell> shells = split_shells(mesh);
    std::vector<size_t> region_outer;  // the outer shell of each region
    std::vector<int> region_of_shell(shells.size(), -1);
    for (size_t s = 0; s < shells.size(); ++s)
        if (shells[s].volume > 0.0) {
            region_of_shell[s] = int(region_outer.size());
            region_outer.push_back(s);
        }
    // The region whose outer shell is the smallest around shell s (other than
    // its own), by the parity of a ray from one of its vertices; -1: none.
    const auto smallest_around = [&](size_t s) {
        const Vec3& probe = mesh.vertices[mesh.triangles[shells[s].triangles.front()][0]];
        double smallest = INFINITY;
        int around = -1;
        for (size_t r = 0; r < region_outer.size(); ++r) {
            const size_t outer = region_outer[r];
            if (outer == s || shells[outer].volume >= smallest) continue;
            size_t crossings = 0;
            for (uint32_t t : shells[outer].triangles) {
                const Triangle& tri = mesh.triangles[t];
                crossings += ray_crosses(probe, mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]]);
            }
            if (crossings % 2 == 1) {
                smallest = shells[outer].volume;
                around = int(r);
            }
        }
        return around;
    };
    std::vector<CavityRegion> regions(region_outer.size());
    for (size_t r = 0; r < region_outer.size(); ++r) regions[r].in_island = smallest_around(region_outer[r]) >= 0;
    for (size_t s = 0; s < shells.size(); ++s)
        if (region_of_shell[s] < 0) region_of_shell[s] = smallest_around(s);

    for (size_t s = 0; s < shells.size(); ++s) {
        if (region_of_shell[s] < 0) continue;  // an island outside every outer shell bounds no void
        CavityRegion& region = regions[size_t(region_of_shell[s])];
        const bool island = shells[s].volume <= 0.0;
        region.volume += shells[s].volume;
        if (island) region.island_volume -= shells[s].volume;
        append(island ? region.islands : region.surface, sub_mesh(mesh, shells[s].triangles));
    }
    return regions;
}

}  // namespace fabvdb::volume
