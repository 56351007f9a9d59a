//! Embedded vertex fans (see embedded_fans.h).
//!
//! Around a vertex whose triangles, seen along their summed normal, turn the
//! same way (certain by the filter) and wind once around it, each triangle
//! projects one to one into its own angular sector: two of them meet only in
//! the projection of what they share, so only along it.
#include "volume/embedded_fans.h"

#include <algorithm>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/vec3_ops.h"
#include "volume/certain_sign.h"
#include "volume/vertex_corners.h"

namespace fabvdb::volume {

namespace {

// Whether the triangles around vertex `centre` (at its `corners`, `count` of
// them; vertex_corners.h) wind once around it, seen along their summed
// normal, each turning the same way: the link edges a -> b of the triangles (centre, a, b) chain into one
// cycle, every turn is certainly positive, and the angular sectors (a, b] of
// the projected triangles cover the direction of the first link vertex once
// (the one ending there, certainly no other).
bool fan_is_embedded(const Mesh& mesh, uint32_t centre, const uint32_t* corners, size_t count) {
    constexpr size_t max_fan = 64;
    if (count < 3 || count > max_fan) return false;
    uint32_t from[max_fan], to[max_fan];
    for (size_t k = 0; k < count; ++k) {
        const Triangle& t = mesh.triangles[corners[k] / 3];
        const uint32_t corner = corners[k] % 3;
        from[k] = t[(corner + 1) % 3];
        to[k] = t[(corner + 2) % 3];
        if (from[k] == centre || to[k] == centre || from[k] == to[k]) return false;
        for (size_t j = 0; j < k; ++j)
            if (from[j] == from[k]) return false;
    }
    size_t steps = 1;
    for (uint32_t at = to[0]; at != from[0]; ++steps) {
        const size_t next = size_t(std::find(from, from + count, at) - from);
        if (next == count || steps == count) return false;
        at = to[next];
    }
    if (steps != count) return false;

    const Vec3& c = mesh.vertices[centre];
    Vec3 normal = {0.0, 0.0, 0.0};
    for (size_t k = 0; k < count; ++k) normal = normal + cross(mesh.vertices[from[k]] - c, mesh.vertices[to[k]] - c);
    const double normal_squared = dot(normal, normal);
    if (!(normal_squared > 0.0)) return false;
    const Vec3 reference = mesh.vertices[from[0]] - c;
    const double reference_squared = dot(reference, reference);
    for (size_t k = 0; k < count; ++k) {
        const Vec3 a = mesh.vertices[from[k]] - c, b = mesh.vertices[to[k]] - c;
        const double a_squared = dot(a, a), b_squared = dot(b, b);
        if (certain_sign(dot(normal, cross(a, b)), normal_squared * a_squared * b_squared) <= 0) return false;
        if (k == 0 || to[k] == from[0]) continue;
        // The sector (a, b], narrower than a half turn, holds the reference
        // direction when it lies after a and not after b.
        if (certain_sign(dot(normal, cross(a, reference)), normal_squared * a_squared * reference_squared) >= 0 &&
            certain_sign(dot(normal, cross(reference, b)), normal_squared * reference_squared * b_squared) >= 0)
            return false;
    }
    return true;
}

}  // namespace

std::vector<char> embedded_fans(const Mesh& mesh, const std::vector<char>& candidates) {
    const size_t vertex_count = mesh.vertices.size();
    const VertexCorners corners(mesh);
    std::vector<char> wanted(vertex_count, candidates.empty());
    for (size_t t = 0; t < candidates.size(); ++t)
        if (candidates[t])
            for (uint32_t v : mesh.triangles[t]) wanted[v] = 1;
    std::vector<char> embedded(vertex_count, 0);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, vertex_count), [&](const tbb::blocked_range<size_t>& range) {
        for (size_t v = range.begin(); v != range.end(); ++v)
            embedded[v] = wanted[v] && fan_is_embedded(mesh, uint32_t(v), corners.corner.data() + corners.first[v],
                                                       corners.first[v + 1] - corners.first[v]);
    });
    return embedded;
}

}  // namespace fabvdb::volume
