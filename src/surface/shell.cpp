//! make_shell: validates S_low as a closed oriented edge-manifold and derives
//! per-triangle normals, unit-cube areas and edge adjacency.
#include "surface/shell.h"

#include <algorithm>
#include <unordered_map>

#include "core/error.h"
#include "core/vec3_ops.h"

namespace fabvdb::surface {

Shell make_shell(Mesh outer, std::vector<Vec3> inner, std::vector<int> thin_segment, double thickness,
                 const std::string& what) {
    const size_t n = outer.triangles.size();
    if (n == 0) throw Error(FABVDB_ERR_BAD_INPUT, what + ": the low-resolution surface is empty");
    if (inner.size() != outer.vertices.size() || thin_segment.size() != n)
        throw Error(FABVDB_ERR_BAD_INPUT, what + ": inner vertices or thin labels do not match the surface");
    Shell shell;
    const BoundingBox box = bounding_box(outer);
    const double extent =
        std::max({box.max[0] - box.min[0], box.max[1] - box.min[1], box.max[2] - box.min[2]});
    if (!(extent > 0)) throw Error(FABVDB_ERR_BAD_INPUT, what + ": the surface has no extent");
    shell.unit_scale = 1.0 / extent;
    shell.normal.resize(n);
    shell.area.resize(n);
    shell.neighbor.assign(n, {-1, -1, -1});
    std::unordered_map<uint64_t, int> half_edge;  // (from << 32 | to) -> triangle * 3 + k
    half_edge.reserve(3 * n);
    const auto key = [](uint32_t a, uint32_t b) { return (uint64_t(a) << 32) | b; };
    for (size_t t = 0; t < n; ++t) {
        const Triangle& f = outer.triangles[t];
        const Vec3 c = cross(outer.vertices[f[1]] - outer.vertices[f[0]], outer.vertices[f[2]] - outer.vertices[f[0]]);
        shell.normal[t] = normalized(c);
        shell.area[t] = 0.5 * norm(c) * shell.unit_scale * shell.unit_scale;
        for (int k = 0; k < 3; ++k) {
            if (!half_edge.emplace(key(f[k], f[(k + 1) % 3]), int(3 * t + k)).second)
                throw Error(FABVDB_ERR_BAD_INPUT, what + ": the low-resolution surface has a non-manifold or "
                                                         "inconsistently oriented edge");
        }
    }
    for (size_t t = 0; t < n; ++t) {
        const Triangle& f = outer.triangles[t];
        for (int k = 0; k < 3; ++k) {
            const auto twin = half_edge.find(key(f[(k + 1) % 3], f[k]));
            if (twin == half_edge.end())
                throw Error(FABVDB_ERR_BAD_INPUT, what + ": the low-resolution surface is not closed");
            shell.neighbor[t][k] = twin->second / 3;
        }
    }
    shell.outer = std::move(outer);
    shell.inner = std::move(inner);
    shell.thin_segment = std::move(thin_segment);
    shell.thickness = thickness;
    return shell;
}

}  // namespace fabvdb::surface
