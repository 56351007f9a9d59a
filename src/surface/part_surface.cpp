//! part_surface: prism tops, bottoms and boundary sides of one part. The
//! adjacency comes from S_low's edge neighbours for the tops and bottoms and
//! from the side quads' own layout; the vertical side edges are matched by
//! vertex, every match linked, so a boundary that pinches at a vertex still
//! gives a connected surface graph. Linear in the part's size (plus a sort of
//! its boundary corners). update_part_surface measures again, with the same
//! arithmetic, the triangles on moved vertices.
#include "surface/part_surface.h"

#include <algorithm>
#include <tuple>

#include "core/vec3_ops.h"

namespace fabvdb::surface {

namespace {

//! The unit normal and unit-cube area of a surface triangle.
std::pair<Vec3, double> measure(const Shell& shell, PartSurface::Kind kind, uint32_t source,
                                const std::array<uint32_t, 3>& c) {
    const Vec3 n = cross(corner_position(shell, c[1]) - corner_position(shell, c[0]),
                         corner_position(shell, c[2]) - corner_position(shell, c[0]));
    return {kind == PartSurface::outer ? shell.normal[source] : normalized(n),
            0.5 * norm(n) * (shell.unit_scale * shell.unit_scale)};
}

}  // namespace

std::vector<uint32_t> update_part_surface(const Shell& shell, const std::vector<char>& moved, PartSurface& s) {
    const size_t v_count = shell.outer.vertices.size();
    std::vector<uint32_t> changed;
    for (uint32_t i = 0; i < s.size(); ++i) {
        const auto& c = s.corners[i];
        const auto on_moved = [&](uint32_t id) { return moved[id < v_count ? id : id - v_count] != 0; };
        if (!on_moved(c[0]) && !on_moved(c[1]) && !on_moved(c[2])) continue;
        std::tie(s.normal[i], s.area[i]) = measure(shell, s.kind[i], s.source[i], c);
        changed.push_back(i);
    }
    return changed;
}

PartSurface part_surface(const Shell& shell, const std::vector<int>& part_of_triangle, int part) {
    PartSurface s;
    const uint32_t v_count = uint32_t(shell.outer.vertices.size());
    const auto add = [&](PartSurface::Kind kind, uint32_t source, std::array<uint32_t, 3> c) {
        const auto [normal, area] = measure(shell, kind, source, c);
        s.kind.push_back(kind);
        s.source.push_back(source);
        s.corners.push_back(c);
        s.normal.push_back(normal);
        s.area.push_back(area);
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
    // Where each prism's faces are: top, bottom, and the first of the two
    // side triangles of each boundary edge 3t + k ({a, a', b'}, then {a, b', b}).
    constexpr uint32_t none = uint32_t(-1);
    std::vector<uint32_t> top(shell.triangle_count(), none), bottom(shell.triangle_count(), none);
    std::vector<uint32_t> side_first(3 * shell.triangle_count(), none);
    std::vector<std::pair<uint32_t, uint32_t>> starting, ending;  // (vertex, side triangle) of vertical edges
    for (uint32_t i = 0; i < s.size(); ++i) {
        if (s.kind[i] == PartSurface::outer) top[s.source[i]] = i;
        if (s.kind[i] == PartSurface::inner) bottom[s.source[i]] = i;
        if (s.kind[i] == PartSurface::side && side_first[s.source[i]] == none) {
            side_first[s.source[i]] = i;
            starting.emplace_back(s.corners[i][0], i);        // {a, a', b'}: the edge a → a'
            ending.emplace_back(s.corners[i + 1][2], i + 1);  // {a, b', b}: the edge b' → b
        }
    }
    std::sort(starting.begin(), starting.end());
    std::sort(ending.begin(), ending.end());
    const auto link_vertical = [](const std::vector<std::pair<uint32_t, uint32_t>>& list, uint32_t vertex,
                                  std::vector<uint32_t>& adjacent) {
        auto it = std::lower_bound(list.begin(), list.end(), std::make_pair(vertex, uint32_t(0)));
        for (; it != list.end() && it->first == vertex; ++it) adjacent.push_back(it->second);
    };
    s.adjacency_start.assign(1, 0);
    s.adjacency.reserve(3 * s.size() + 2 * starting.size());
    std::vector<uint32_t>& adjacent = s.adjacency;
    for (uint32_t i = 0; i < s.size(); ++i) {
        if (s.kind[i] == PartSurface::side) {
            const uint32_t t = s.source[i] / 3;
            if (side_first[s.source[i]] == i) {
                // {a, a', b'}: a → a' meets the quads ending at a, a' → b' the bottom, b' → a its twin.
                link_vertical(ending, s.corners[i][0], adjacent);
                adjacent.push_back(bottom[t]);
                adjacent.push_back(i + 1);
            } else {
                // {a, b', b}: a → b' its twin, b' → b the quads starting at b, b → a the top.
                adjacent.push_back(i - 1);
                link_vertical(starting, s.corners[i][2], adjacent);
                adjacent.push_back(top[t]);
            }
            s.adjacency_start.push_back(uint32_t(adjacent.size()));
            continue;
        }
        const uint32_t t = s.source[i];
        const bool outer = s.kind[i] == PartSurface::outer;
        // The top's corner edges are S_low's edges 0, 1, 2; the bottom's
        // (reversed) are S_low's edges 2, 1, 0.
        for (int j = 0; j < 3; ++j) {
            const int k = outer ? j : 2 - j;
            const int u = shell.neighbor[t][k];
            if (part_of_triangle[u] == part)
                adjacent.push_back(outer ? top[u] : bottom[u]);
            else
                adjacent.push_back(side_first[3 * t + k] + (outer ? 1 : 0));
        }
        s.adjacency_start.push_back(uint32_t(adjacent.size()));
    }
    return s;
}

}  // namespace fabvdb::surface
