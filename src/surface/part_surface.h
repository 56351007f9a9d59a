//! The closed surface of one part of the decomposition: the outer triangles of
//! its prisms (from S_low), their inner images (T_in, reversed to face out of
//! the material) and the triangulated side quads along the part's boundary
//! edges (T_side). Each surface triangle carries its kind, source, unit normal,
//! unit-cube area and edge-adjacent surface triangles. A solid part that is a
//! whole piece of S_low (no boundary edge) is its outer triangles alone: its
//! inner faces would lie inside it, on the medial surface.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "surface/shell.h"

namespace fabvdb::surface {

struct PartSurface {
    enum Kind : uint8_t { outer, inner, side };
    std::vector<Kind> kind;
    //! outer/inner: the S_low triangle; side: 3·t + k for the edge (v[k], v[k+1]) of t.
    std::vector<uint32_t> source;
    //! Corner ids: v < V is outer vertex v, V + v is inner vertex f_V(v).
    std::vector<std::array<uint32_t, 3>> corners;
    std::vector<Vec3> normal;
    std::vector<double> area;
    //! Edge-adjacent surface triangles, in compressed rows: those of triangle i
    //! are adjacency[adjacency_start[i] .. adjacency_start[i + 1]).
    std::vector<uint32_t> adjacency_start, adjacency;
    size_t size() const { return kind.size(); }

    struct Neighbours {
        const uint32_t* first;
        const uint32_t* last;
        const uint32_t* begin() const { return first; }
        const uint32_t* end() const { return last; }
        size_t size() const { return size_t(last - first); }
    };
    Neighbours adjacent(size_t i) const {
        return {adjacency.data() + adjacency_start[i], adjacency.data() + adjacency_start[i + 1]};
    }
};

//! The surface of the part made of the outer triangles t with part_of_triangle[t] == part.
PartSurface part_surface(const Shell& shell, const std::vector<int>& part_of_triangle, int part);

//! Measures again the normal and area of the surface triangles of `s` (a
//! part_surface of `shell`) with a corner on an outer vertex v with
//! moved[v] != 0 (its inner vertex moves with it), as part_surface would
//! after the move; returns their indices. Linear in the surface's size.
std::vector<uint32_t> update_part_surface(const Shell& shell, const std::vector<char>& moved, PartSurface& s);

//! Position of a corner id of a PartSurface.
inline const Vec3& corner_position(const Shell& shell, uint32_t id) {
    const size_t v = shell.outer.vertices.size();
    return id < v ? shell.outer.vertices[id] : shell.inner[id - v];
}

}  // namespace fabvdb::surface
