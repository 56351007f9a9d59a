//! Crossing pairs of triangles of a mesh (see crossing_pairs.h): the pairs
//! of overlapping boxes (triangle_box_pairs.h) tested exactly
//! (triangles_cross.h), except those at an embedded fan (embedded_fans.h),
//! which meet only along what they share.
#include "volume/crossing_pairs.h"

#include <algorithm>

#include <tbb/enumerable_thread_specific.h>

#include "volume/embedded_fans.h"
#include "volume/triangle_box_pairs.h"
#include "volume/triangles_cross.h"

namespace fabvdb::volume {

namespace {

// The crossing pairs of the whole mesh with a candidate in them (all pairs
// when `candidates` is empty), unsorted.
std::vector<std::pair<uint32_t, uint32_t>> pairs_among(const Mesh& mesh, const std::vector<char>& candidates) {
    if (mesh.triangles.size() < 2) return {};
    const std::vector<char> embedded = embedded_fans(mesh, candidates);
    tbb::enumerable_thread_specific<std::vector<std::pair<uint32_t, uint32_t>>> found;
    for_each_overlapping_box_pair(mesh, [&](uint32_t i, uint32_t j) {
        if (!candidates.empty() && !candidates[i] && !candidates[j]) return;
        if (!triangles_cross(mesh, embedded, mesh.triangles[i], mesh.triangles[j])) return;
        found.local().emplace_back(std::min(i, j), std::max(i, j));
    });
    std::vector<std::pair<uint32_t, uint32_t>> pairs;
    for (const auto& local : found) pairs.insert(pairs.end(), local.begin(), local.end());
    return pairs;
}

}  // namespace

// With candidates, only the triangles near them are searched: the part of
// the mesh they make up has the same crossing pairs with a candidate (a
// vertex whose fan is cut off there counts as not embedded, so its pairs are
// tested exactly).
std::vector<std::pair<uint32_t, uint32_t>> crossing_pairs(const Mesh& mesh, const std::vector<char>& candidates) {
    std::vector<std::pair<uint32_t, uint32_t>> pairs;
    if (candidates.empty()) {
        pairs = pairs_among(mesh, candidates);
    } else {
        const std::vector<uint32_t> near = triangles_near_marked(mesh, candidates);
        Mesh part{mesh.vertices, {}};
        std::vector<char> part_candidates(near.size());
        part.triangles.reserve(near.size());
        for (size_t i = 0; i < near.size(); ++i) {
            part.triangles.push_back(mesh.triangles[near[i]]);
            part_candidates[i] = candidates[near[i]];
        }
        pairs = pairs_among(part, part_candidates);
        for (auto& [i, j] : pairs) i = near[i], j = near[j];
    }
    std::sort(pairs.begin(), pairs.end());
    return pairs;
}

}  // namespace fabvdb::volume
