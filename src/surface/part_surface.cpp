//! part_surface: prism tops, bottoms and boundary sides of one part, with
//! adjacency from matching opposite half-edges (all matches are linked, so a
//! boundary that pinches at a vertex still gives a connected surface graph).
#include "surface/part_surface.h"

#include <unordered_map>

#include "surface/vec3_ops.h"

namespace fabvdb::surface {

PartSurface part_surface(const Shell& shell, const std::vector<int>& part_of_triangle, int part) {
    PartSurface s;
    const uint32_t v_count = uint32_t(shell.outer.vertices.size());
    const double area_scale = shell.unit_scale * shell.unit_scale;
    const auto add = [&](PartSurface::Kind kind, uint32_t source, std::array<uint32_t, 3> c) {
        const Vec3 n = cross(corner_position(shell, c[1]) - corner_position(shell, c[0]),
                             corner_position(shell, c[2]) - corner_position(shell, c[0]));
        s.kind.push_back(kind);
        s.source.push_back(source);
        s.corners.push_back(c);
        s.normal.push_back(kind == PartSurface::outer ? shell.normal[source] : normalized(n));
        s.area.push_back(0.5 * norm(n) * area_scale);
    };
    // A solid part without boundary is a whole piece of S_low: its prisms'
    // inner faces meet on the medial surface, inside the part.
    bool bounded = false;
    for (size_t t = 0; t < shell.triangle_count() && !bounded; ++t)
        if (part_of_triangle[t] == part)
            for (int k = 0; k < 3; ++k) bounded = bounded || part_of_triangle[shell.neighbor[t][k]] != part;
    const bool with_inner = !shell.solid || bounded;
    for (size_t t = 0; t < shell.triangle_count(); ++t) {
        if (part_of_triangle[t] != part) continue;
        const Triangle& f = shell.outer.triangles[t];
        add(PartSurface::outer, uint32_t(t), {f[0], f[1], f[2]});
        if (with_inner) add(PartSurface::inner, uint32_t(t), {v_count + f[0], v_count + f[2], v_count + f[1]});
        for (int k = 0; k < 3; ++k) {
            if (part_of_triangle[shell.neighbor[t][k]] == part) continue;
            const uint32_t a = f[k], b = f[(k + 1) % 3];
            add(PartSurface::side, uint32_t(3 * t + k), {a, v_count + a, v_count + b});
            add(PartSurface::side, uint32_t(3 * t + k), {a, v_count + b, b});
        }
    }
    std::unordered_multimap<uint64_t, uint32_t> half_edges;
    half_edges.reserve(3 * s.size());
    const auto key = [](uint32_t a, uint32_t b) { return (uint64_t(a) << 32) | b; };
    for (uint32_t i = 0; i < s.size(); ++i)
        for (int k = 0; k < 3; ++k) half_edges.emplace(key(s.corners[i][k], s.corners[i][(k + 1) % 3]), i);
    s.adjacent.resize(s.size());
    for (uint32_t i = 0; i < s.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            const auto range = half_edges.equal_range(key(s.corners[i][(k + 1) % 3], s.corners[i][k]));
            for (auto it = range.first; it != range.second; ++it)
                if (it->second != i) s.adjacent[i].push_back(it->second);
        }
    return s;
}

}  // namespace fabvdb::surface
