//! Graph cut with Boost.Graph's boykov_kolmogorov_max_flow, then the
//! component-graph fix-up with Dijkstra searches from the two fixed roots.
#include "surface/parting_line.h"

#include <algorithm>
#include <mutex>
#include <queue>

// Boost.Graph's edge iterators trip GCC's -Wmaybe-uninitialized (false positive).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/boykov_kolmogorov_max_flow.hpp>
#pragma GCC diagnostic pop
#include <tbb/parallel_for.h>

#include "surface/vec3_ops.h"

namespace fabvdb::surface {

namespace {

using Traits = boost::adjacency_list_traits<boost::vecS, boost::vecS, boost::directedS>;
struct EdgeData {
    double capacity = 0;
    double residual = 0;
    Traits::edge_descriptor reverse;
};
struct VertexData {
    boost::default_color_type color{};
    long distance = 0;
    Traits::edge_descriptor predecessor;
};
using FlowGraph = boost::adjacency_list<boost::vecS, boost::vecS, boost::directedS, VertexData, EdgeData>;

void add_edge_pair(FlowGraph& g, size_t a, size_t b, double forward, double backward) {
    const auto e = boost::add_edge(a, b, g).first;
    const auto r = boost::add_edge(b, a, g).first;
    g[e].capacity = forward;
    g[r].capacity = backward;
    g[e].reverse = r;
    g[r].reverse = e;
}

std::vector<char> graph_cut(const PartSurface& s, const Vec3& d) {
    const size_t n = s.size();
    FlowGraph g(n + 2);
    const size_t source = n, sink = n + 1;
    for (size_t i = 0; i < n; ++i) {
        const double facing = dot(s.normal[i], d);
        const bool inner = s.kind[i] == PartSurface::inner;
        add_edge_pair(g, source, i, inner ? 0.0 : 1.0 + facing, 0.0);
        add_edge_pair(g, i, sink, inner ? 0.0 : 1.0 - facing, 0.0);
        for (uint32_t j : s.adjacent[i])
            if (j > i) {
                const double w = std::max(0.0, dot(s.normal[i], s.normal[j]));
                add_edge_pair(g, i, j, w, w);
            }
    }
    boost::boykov_kolmogorov_max_flow(g, boost::get(&EdgeData::capacity, g), boost::get(&EdgeData::residual, g),
                                      boost::get(&EdgeData::reverse, g), boost::get(&VertexData::predecessor, g),
                                      boost::get(&VertexData::color, g), boost::get(&VertexData::distance, g),
                                      boost::get(boost::vertex_index, g), source, sink);
    std::vector<char> upper(n);
    for (size_t i = 0; i < n; ++i) upper[i] = g[i].color != boost::white_color;
    return upper;
}

//! Makes the M⁺ and M⁻ labels each one connected component (§3.4.4).
void connect_patches(const Shell& shell, const MoldabilityTerms& terms, const PartSurface& s, const Vec3& d,
                     int direction, std::vector<char>& upper) {
    const size_t n = s.size();
    std::vector<int> surface_of_outer(shell.triangle_count(), -1);
    for (size_t i = 0; i < n; ++i)
        if (s.kind[i] == PartSurface::outer) surface_of_outer[s.source[i]] = int(i);
    const auto& overlaps = terms.overlaps_along(direction);
    std::vector<char> overlapping(n, 0);
    for (size_t i = 0; i < n; ++i) {
        if (s.kind[i] != PartSurface::outer) continue;
        const uint32_t t = s.source[i];
        for (uint32_t k = overlaps.offset[t]; k < overlaps.offset[t + 1]; ++k) {
            const int j = surface_of_outer[overlaps.partner[k]];
            if (j >= 0 && upper[j] == upper[i]) {
                overlapping[i] = 1;
                break;
            }
        }
    }
    // Connected components of the four classes (patch × overlap).
    std::vector<int> component(n, -1);
    std::vector<char> label;
    std::vector<double> projected;
    for (size_t start = 0; start < n; ++start) {
        if (component[start] >= 0) continue;
        const int c = int(label.size());
        label.push_back(upper[start]);
        projected.push_back(0);
        std::vector<uint32_t> stack{uint32_t(start)};
        component[start] = c;
        while (!stack.empty()) {
            const uint32_t i = stack.back();
            stack.pop_back();
            projected[c] += s.area[i] * std::abs(dot(s.normal[i], d));
            for (uint32_t j : s.adjacent[i])
                if (component[j] < 0 && upper[j] == upper[start] && overlapping[j] == overlapping[start]) {
                    component[j] = c;
                    stack.push_back(j);
                }
        }
    }
    const size_t count = label.size();
    std::vector<std::vector<int>> links(count);
    for (size_t i = 0; i < n; ++i)
        for (uint32_t j : s.adjacent[i])
            if (component[i] != component[j]) links[component[i]].push_back(component[j]);
    for (auto& l : links) {
        std::sort(l.begin(), l.end());
        l.erase(std::unique(l.begin(), l.end()), l.end());
    }
    std::vector<char> fixed(count, 0);
    int root[2] = {-1, -1};  // [0]: M⁻, [1]: M⁺
    for (size_t c = 0; c < count; ++c) {
        int& r = root[label[c] ? 1 : 0];
        if (r < 0 || projected[c] > projected[r]) r = int(c);
    }
    for (int r : root)
        if (r >= 0) fixed[r] = 1;
    std::vector<int> order(count);
    for (size_t c = 0; c < count; ++c) order[c] = int(c);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return projected[a] > projected[b]; });

    // Cheapest path from root[side] to every node: entering a node of the other
    // label costs its projected area; fixed nodes of the other label block.
    const auto search = [&](int side, std::vector<double>& distance, std::vector<int>& previous) {
        distance.assign(count, 1e300);
        previous.assign(count, -1);
        if (root[side] < 0) return;
        using Entry = std::pair<double, int>;
        std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
        distance[root[side]] = 0;
        queue.emplace(0.0, root[side]);
        while (!queue.empty()) {
            const auto [dist, c] = queue.top();
            queue.pop();
            if (dist > distance[c]) continue;
            for (int next : links[c]) {
                const bool same = (label[next] != 0) == (side == 1);
                if (fixed[next] && !same) continue;
                const double w = dist + (same ? 0.0 : projected[next]);
                if (w < distance[next]) {
                    distance[next] = w;
                    previous[next] = c;
                    queue.emplace(w, next);
                }
            }
        }
    };
    std::vector<double> distance[2];
    std::vector<int> previous[2];
    for (int c : order) {
        if (fixed[c]) continue;
        search(0, distance[0], previous[0]);
        search(1, distance[1], previous[1]);
        const int side = distance[1][c] <= distance[0][c] ? 1 : 0;
        for (int x = c; x >= 0 && !fixed[x]; x = previous[side][x]) {
            label[x] = char(side);
            fixed[x] = 1;
        }
    }
    for (size_t i = 0; i < n; ++i) upper[i] = label[component[i]];
}

PartMolding molding_of(const Shell& shell, const MoldabilityTerms& terms, PartSurface surface, int direction,
                       const MoldabilityWeights& weights) {
    PartMolding molding;
    molding.direction = direction;
    molding.surface = std::move(surface);
    const Vec3& d = terms.directions.directions[direction];
    molding.upper = graph_cut(molding.surface, d);
    connect_patches(shell, terms, molding.surface, d, direction, molding.upper);
    molding.energy = moldability_energy(terms, molding.surface, molding.upper, direction, weights, nullptr);
    return molding;
}

}  // namespace

PartMolding parting_line(const Shell& shell, const MoldabilityTerms& terms, const std::vector<int>& part_of_triangle,
                         int part, int direction, const MoldabilityWeights& weights) {
    return molding_of(shell, terms, part_surface(shell, part_of_triangle, part), direction, weights);
}

PartMolding best_parting_line(const Shell& shell, const MoldabilityTerms& terms,
                              const std::vector<int>& part_of_triangle, int part, const MoldabilityWeights& weights,
                              Progress& progress) {
    const PartSurface surface = part_surface(shell, part_of_triangle, part);
    const size_t count = terms.directions.directions.size();
    std::vector<double> energy(count, 1e300);
    tbb::parallel_for(size_t(0), count, [&](size_t d) {
        if (progress.cancelled()) return;
        energy[d] = molding_of(shell, terms, surface, int(d), weights).energy.total;
    });
    progress.check();
    const int best = int(std::min_element(energy.begin(), energy.end()) - energy.begin());
    return molding_of(shell, terms, surface, best, weights);
}

}  // namespace fabvdb::surface
