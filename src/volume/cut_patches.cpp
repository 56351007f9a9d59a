//! The patches of a cut surface (see cut_patches.h).
#include "volume/cut_patches.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/disjoint_sets.h"
#include "volume/vertex_corners.h"

namespace fabvdb::volume {

std::optional<Patches> cut_patches(const CutSurface& surface) {
    const auto& triangles = surface.mesh.triangles;
    const VertexCorners corners(surface.mesh);
    // For every edge k (corner k to k + 1) of every triangle, the one
    // triangle running along it the other way; UINT32_MAX if not one.
    std::vector<uint32_t> opposite(3 * triangles.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, triangles.size()), [&](const tbb::blocked_range<size_t>& range) {
        for (size_t t = range.begin(); t != range.end(); ++t)
            for (int k = 0; k < 3; ++k) {
                const VertexCorners::Across other = corners.across(surface.mesh, uint32_t(t), k);
                opposite[3 * t + k] = other.count == 1 ? other.first : UINT32_MAX;
            }
    });
    DisjointSets patches(triangles.size());
    std::vector<std::pair<uint32_t, uint32_t>> cut_sides;  // triangles
    for (size_t t = 0; t < triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = triangles[t][k], b = triangles[t][(k + 1) % 3], other = opposite[3 * t + k];
            if (other == UINT32_MAX) return std::nullopt;
            // Cut edges run between pieces only: an untouched triangle's
            // edge has a piece on its other side when it lies on a cut.
            const bool untouched = t < surface.first_piece && other < surface.first_piece;
            if (untouched || !surface.along_cut(a, b))
                patches.unite(uint32_t(t), other);
            else if (a < b)
                cut_sides.emplace_back(uint32_t(t), other);
        }
    Patches result;
    result.of_triangle.resize(triangles.size());
    std::vector<uint32_t> number(triangles.size(), UINT32_MAX);
    for (size_t t = 0; t < triangles.size(); ++t) {
        uint32_t& n = number[patches.find(uint32_t(t))];
        if (n == UINT32_MAX) n = uint32_t(result.count++);
        result.of_triangle[t] = n;
    }
    for (const auto& [t, u] : cut_sides) {
        const uint32_t p = result.of_triangle[t], q = result.of_triangle[u];
        if (p == q) return std::nullopt;
        result.across_cuts.emplace_back(p, q);
    }
    return result;
}

}  // namespace fabvdb::volume
