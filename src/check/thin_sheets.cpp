//! thin_sheets: the regions' faces gathered by shared medial cells, then the
//! border loops of each region (edges of one region triangle only, joined
//! through their vertices) counted per sheet (see thin_sheets.h).
#include "check/thin_sheets.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "core/disjoint_sets.h"
#include "core/vec3_ops.h"

namespace fabvdb::check {

namespace {

uint64_t cell_key(int64_t i, int64_t j, int64_t k) {
    constexpr int64_t bias = int64_t(1) << 20;
    return (uint64_t(i + bias) << 42) | (uint64_t(j + bias) << 21) | uint64_t(k + bias);
}

//! The loops of the region's border at least `min_loop` long.
int border_loops(const Mesh& surface, const surface::TriangleRegion& region, double min_loop) {
    std::unordered_map<uint64_t, int> edge_count;
    for (uint32_t t : region.triangles)
        for (int e = 0; e < 3; ++e) {
            const uint32_t a = surface.triangles[t][e], b = surface.triangles[t][(e + 1) % 3];
            ++edge_count[(uint64_t(std::min(a, b)) << 32) | std::max(a, b)];
        }
    std::unordered_map<uint32_t, int> local;
    std::vector<std::pair<int, int>> border;
    std::vector<double> length;
    const auto index = [&](uint32_t v) {
        const auto [at, added] = local.emplace(v, int(local.size()));
        return at->second;
    };
    for (const auto& [key, count] : edge_count) {
        if (count != 1) continue;
        const uint32_t a = uint32_t(key >> 32), b = uint32_t(key & 0xffffffffu);
        border.emplace_back(index(a), index(b));
        length.push_back(std::sqrt(squared_distance(surface.vertices[a], surface.vertices[b])));
    }
    DisjointSets loops(local.size());
    for (const auto& [a, b] : border) loops.unite(uint32_t(a), uint32_t(b));
    std::unordered_map<uint32_t, double> loop_length;
    for (size_t e = 0; e < border.size(); ++e) loop_length[loops.find(uint32_t(border[e].first))] += length[e];
    int count = 0;
    for (const auto& [root, total] : loop_length) count += total >= min_loop ? 1 : 0;
    return count;
}

}  // namespace

std::vector<SheetReading> thin_sheets(const Mesh& surface, const std::vector<surface::TriangleRegion>& regions,
                                      const std::vector<Vec3>& centre, double cell, double min_loop) {
    const auto key_of = [&](const Vec3& p, int di, int dj, int dk) {
        return cell_key(int64_t(std::floor(p[0] / cell)) + di, int64_t(std::floor(p[1] / cell)) + dj,
                        int64_t(std::floor(p[2] / cell)) + dk);
    };
    std::unordered_map<uint64_t, int> owner;  // medial cell → the first region there
    for (size_t r = 0; r < regions.size(); ++r)
        for (uint32_t v : regions[r].vertices) owner.emplace(key_of(centre[v], 0, 0, 0), int(r));
    DisjointSets sheets(regions.size());
    for (size_t r = 0; r < regions.size(); ++r)
        for (uint32_t v : regions[r].vertices)
            for (int d = 0; d < 27; ++d) {
                const auto found = owner.find(key_of(centre[v], d % 3 - 1, d / 3 % 3 - 1, d / 9 - 1));
                if (found != owner.end() && found->second != int(r)) sheets.unite(uint32_t(found->second), uint32_t(r));
            }
    std::vector<int> held(regions.size(), 0);
    std::vector<double> area(regions.size(), 0.0);
    std::vector<Vec3> facing(regions.size(), Vec3{0, 0, 0});  // the area-weighted normals' sum
    std::vector<SheetReading> readings(regions.size());
    for (size_t r = 0; r < regions.size(); ++r) {
        const int sheet = readings[r].sheet = int(sheets.find(uint32_t(r)));
        held[sheet] += border_loops(surface, regions[r], min_loop);
        for (uint32_t t : regions[r].triangles) {
            const Vec3& a = surface.vertices[surface.triangles[t][0]];
            const Vec3 twice = cross(surface.vertices[surface.triangles[t][1]] - a,
                                     surface.vertices[surface.triangles[t][2]] - a);
            facing[sheet] = facing[sheet] + 0.5 * twice;
            area[sheet] += 0.5 * norm(twice);
        }
    }
    for (SheetReading& reading : readings) {
        reading.held_edges = held[reading.sheet];
        reading.two_sided = norm(facing[reading.sheet]) < 0.5 * area[reading.sheet];
        reading.fin = reading.held_edges == 1 && reading.two_sided;
    }
    return readings;
}

}  // namespace fabvdb::check
