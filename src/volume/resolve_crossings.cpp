//! Resolving crossing triangles (see resolve_crossings.h): the mesh cut
//! along its crossings (cut_along_crossings.h) falls into patches
//! (cut_patches.h); across a patch the winding number w goes from w_front to
//! w_front + 1 (front_winding_numbers.h), so the patch bounds {w ≥ 1} exactly
//! when w_front = 0. The kept patches are joined at their cuts and parted
//! where they touch at a vertex (part_pinches.h).
#include "volume/resolve_crossings.h"

#include <algorithm>
#include <cstdlib>
#include <numeric>
#include <utility>

#include "core/turned_inside_out.h"
#include "volume/clean_solid.h"
#include "volume/cut_along_crossings.h"
#include "volume/cut_patches.h"
#include "volume/front_winding_numbers.h"
#include "volume/mesh_shells.h"
#include "volume/part_pinches.h"

namespace fabvdb::volume {

size_t max_crossing_pairs(size_t triangle_count) { return std::max<size_t>(1024, triangle_count / 10); }

std::optional<Mesh> resolve_crossings(const Mesh& mesh, const std::vector<std::pair<uint32_t, uint32_t>>& crossings,
                                      Progress& progress) {
    progress.stage("resolve crossings");
    if (crossings.empty() || crossings.size() > max_crossing_pairs(mesh.triangles.size())) return std::nullopt;
    // A surface stored inside out (a negative volume) bounds {w <= -1}: its
    // triangles turned round bound {w >= 1}, the same solid facing outward.
    // The crossing pairs name the same triangles either way.
    if (signed_volume(mesh) < 0.0) return resolve_crossings(turned_inside_out(mesh), crossings, progress);
    const std::optional<CutSurface> surface = cut_along_crossings(mesh, crossings);
    if (!surface) return std::nullopt;
    progress.update(0.2);
    const std::optional<Patches> parts = cut_patches(*surface);
    if (!parts) return std::nullopt;
    const std::vector<uint32_t>& patch = parts->of_triangle;
    progress.update(0.3);
    const std::optional<std::vector<int>> front = front_winding_numbers(surface->mesh, patch, parts->count, progress);
    if (!front) return std::nullopt;
    // One ray per patch: the cuts between them must tell the same story.
    for (const auto& [p, q] : parts->across_cuts)
        if (std::abs((*front)[p] - (*front)[q]) != 1) return std::nullopt;
    progress.update(0.8);

    // The kept pieces' cut points, merged with their copies on the other side
    // of the cut (the same rounded point), and with an input vertex there.
    const Mesh& cut = surface->mesh;
    std::vector<uint32_t> kept, at_cut;
    size_t first_kept_piece = 0;
    for (size_t t = 0; t < cut.triangles.size(); ++t) {
        if ((*front)[patch[t]] != 0) continue;
        if (t < surface->first_piece) {
            ++first_kept_piece;
        } else {
            for (uint32_t v : cut.triangles[t]) at_cut.push_back(v);
        }
        kept.push_back(uint32_t(t));
    }
    std::sort(at_cut.begin(), at_cut.end(), [&](uint32_t a, uint32_t b) {
        return cut.vertices[a] < cut.vertices[b] || (cut.vertices[a] == cut.vertices[b] && a < b);
    });
    std::vector<uint32_t> same(cut.vertices.size());
    std::iota(same.begin(), same.end(), 0u);
    for (size_t i = 1; i < at_cut.size(); ++i)
        if (cut.vertices[at_cut[i]] == cut.vertices[at_cut[i - 1]]) same[at_cut[i]] = same[at_cut[i - 1]];
    Mesh merged{cut.vertices, {}};
    for (uint32_t t : kept) {
        const Triangle& original = cut.triangles[t];
        merged.triangles.push_back({same[original[0]], same[original[1]], same[original[2]]});
    }
    const std::optional<std::vector<uint32_t>> moved = part_pinches(merged);
    if (!moved) return std::nullopt;
    // Only the pieces and the triangles at parted pinches may cross after
    // rounding: the others are the input's, which crossed nothing but the
    // crossing triangles.
    std::vector<char> changed(merged.vertices.size(), 0);
    for (uint32_t v : *moved) changed[v] = 1;
    std::vector<char> candidates(merged.triangles.size(), 0);
    for (size_t t = 0; t < merged.triangles.size(); ++t)
        candidates[t] = t >= first_kept_piece || changed[merged.triangles[t][0]] ||
                        changed[merged.triangles[t][1]] || changed[merged.triangles[t][2]];
    std::vector<uint32_t> all(merged.triangles.size());
    std::iota(all.begin(), all.end(), 0u);
    Mesh resolved = sub_mesh(merged, all);
    if (!check_solid(resolved, progress, candidates).clean) return std::nullopt;
    return resolved;
}

}  // namespace fabvdb::volume
