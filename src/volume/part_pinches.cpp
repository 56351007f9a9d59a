//! Parting pinched vertices (see part_pinches.h).
#include "volume/part_pinches.h"

#include <algorithm>
#include <atomic>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "volume/vertex_corners.h"

namespace fabvdb::volume {

std::optional<std::vector<uint32_t>> part_pinches(Mesh& mesh) {
    constexpr double pinch_parting = 0.01;
    const VertexCorners corners(mesh);
    // Per vertex (in parallel, without allocating for the usual single fan),
    // its fans when it has several; whether every vertex's are closed.
    std::atomic<bool> closed{true};
    tbb::enumerable_thread_specific<std::vector<std::pair<uint32_t, std::vector<uint32_t>>>> local_fans;
    tbb::enumerable_thread_specific<std::vector<char>> local_visited;
    tbb::parallel_for(tbb::blocked_range<uint32_t>(0, uint32_t(mesh.vertices.size())),
                      [&](const tbb::blocked_range<uint32_t>& range) {
        std::vector<char>& visited = local_visited.local();
        for (uint32_t v = range.begin(); v != range.end() && closed; ++v) {
            const auto begin = corners.corner.begin() + corners.first[v];
            const auto end = corners.corner.begin() + corners.first[v + 1];
            const auto ring = [&](uint32_t c, uint32_t step) { return mesh.triangles[c / 3][(c % 3 + step) % 3]; };
            const auto next_of = [&](auto at) {
                const uint32_t next = ring(*at, 2);
                return std::find_if(begin, end, [&](const auto& c) { return ring(c, 1) == next; });
            };
            for (auto c = begin; c != end; ++c)
                for (auto d = begin; d != c; ++d)
                    if (ring(*c, 1) == ring(*d, 1)) closed = false;
            visited.assign(size_t(end - begin), 0);
            size_t cycles = 0;
            for (auto start = begin; start != end && closed; ++start) {
                if (visited[size_t(start - begin)]) continue;
                auto at = start;
                do {
                    visited[size_t(at - begin)] = 1;
                    at = next_of(at);
                    if (at == end) break;
                } while (!visited[size_t(at - begin)]);
                if (at != start) closed = false;
                ++cycles;
            }
            if (cycles < 2 || !closed) continue;
            visited.assign(size_t(end - begin), 0);
            for (auto start = begin; start != end; ++start) {
                if (visited[size_t(start - begin)]) continue;
                std::vector<uint32_t> fan;
                for (auto at = start; !visited[size_t(at - begin)]; at = next_of(at)) {
                    visited[size_t(at - begin)] = 1;
                    fan.push_back(*at / 3);
                }
                local_fans.local().emplace_back(v, std::move(fan));
            }
        }
    });
    if (!closed) return std::nullopt;
    std::vector<std::pair<uint32_t, std::vector<uint32_t>>> fans;  // vertex, its fan's triangles, in vertex order
    for (auto& part : local_fans)
        for (auto& fan : part) fans.push_back(std::move(fan));
    std::stable_sort(fans.begin(), fans.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<uint32_t> moved;
    for (const auto& [v, fan] : fans) {
        Vec3 centre{0, 0, 0};
        for (uint32_t t : fan)
            for (uint32_t w : mesh.triangles[t])
                if (w != v)
                    for (int k = 0; k < 3; ++k) centre[k] += mesh.vertices[w][k] / double(2 * fan.size());
        Vec3 copy;
        for (int k = 0; k < 3; ++k)
            copy[k] = mesh.vertices[v][k] + pinch_parting * (centre[k] - mesh.vertices[v][k]);
        const uint32_t index = uint32_t(mesh.vertices.size());
        mesh.vertices.push_back(copy);
        for (uint32_t t : fan)
            for (uint32_t& w : mesh.triangles[t])
                if (w == v) w = index;
        moved.push_back(index);
    }
    return moved;
}

}  // namespace fabvdb::volume
