//! Graph cut with MinCut (Boykov–Kolmogorov), then the component-graph
//! fix-up with Dijkstra searches from the two fixed roots.
#include "surface/parting_line.h"

#include <algorithm>
#include <functional>
#include <memory>
#include <tuple>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "core/vec3_ops.h"
#include "surface/min_cut.h"

namespace fabvdb::surface {

namespace {

//! The flow network of one part surface: a node per surface triangle, an
//! edge per pair of adjacent triangles (the surface's adjacency rows are the
//! arcs). Its structure and the binary capacities do not depend on the
//! direction, so one network serves every candidate: only the terminal
//! capacities are set per direction.
class CutNetwork {
public:
    explicit CutNetwork(const PartSurface& s) : s_(s), cut_(s.adjacency_start, s.adjacency, sisters(s)) {
        for (uint32_t i = 0; i < s.size(); ++i)
            for (uint32_t a = s.adjacency_start[i]; a < s.adjacency_start[i + 1]; ++a)
                if (s.adjacency[a] > i) cut_.set_edge_capacity(a, capacity(i, s.adjacency[a]));
        terminal_.resize(s.size());
    }

    //! After the normals of these surface triangles changed: their edges' capacities.
    void update(const std::vector<uint32_t>& triangles) {
        for (uint32_t i : triangles)
            for (uint32_t a = s_.adjacency_start[i]; a < s_.adjacency_start[i + 1]; ++a)
                cut_.set_edge_capacity(a, capacity(i, s_.adjacency[a]));
    }

    //! Per surface triangle: in M⁺ for direction d.
    std::vector<char> labels(const Vec3& d) {
        for (size_t i = 0; i < s_.size(); ++i)
            // 1 + n·d (for M⁻) and 1 − n·d (for M⁺) less their common part
            // 1 − |n·d|: the same minimum cut, with far less flow to push.
            terminal_[i] = s_.kind[i] == PartSurface::inner ? 0.0 : 2.0 * dot(s_.normal[i], d);
        std::vector<char> upper;
        cut_.solve(terminal_, upper);
        return upper;
    }

private:
    //! The binary cost max(0, n_i·n_j), the same from either side.
    double capacity(uint32_t i, uint32_t j) const {
        return std::max(0.0, dot(s_.normal[std::min(i, j)], s_.normal[std::max(i, j)]));
    }

    //! The reverse of each arc: the k-th entry j in i's row pairs with the
    //! entry i in j's row of the same rank among equal entries.
    static std::vector<uint32_t> sisters(const PartSurface& s) {
        std::vector<uint32_t> sister(s.adjacency.size());
        for (uint32_t i = 0; i < s.size(); ++i) {
            const uint32_t first = s.adjacency_start[i], last = s.adjacency_start[i + 1];
            for (uint32_t a = first; a < last; ++a) {
                const uint32_t j = s.adjacency[a];
                if (j < i) continue;  // paired from j's side
                size_t rank = size_t(std::count(s.adjacency.begin() + first, s.adjacency.begin() + a, j));
                uint32_t back = s.adjacency_start[j];
                for (;; ++back)
                    if (s.adjacency[back] == i && rank-- == 0) break;
                sister[a] = back;
                sister[back] = a;
            }
        }
        return sister;
    }

    const PartSurface& s_;
    MinCut cut_;
    std::vector<double> terminal_;
};

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
    // Each triangle's projected area, in one pass in memory order (the
    // component walk below reads it in walk order).
    std::vector<double> projected_area(n);
    for (size_t i = 0; i < n; ++i) projected_area[i] = s.area[i] * std::abs(dot(s.normal[i], d));
    // Connected components of the four classes (patch × overlap).
    std::vector<int> component(n, -1);
    std::vector<char> label;
    std::vector<double> projected, outer_projected;
    std::vector<uint32_t> stack;
    for (size_t start = 0; start < n; ++start) {
        if (component[start] >= 0) continue;
        const int c = int(label.size());
        label.push_back(upper[start]);
        projected.push_back(0);
        outer_projected.push_back(0);
        stack.assign(1, uint32_t(start));
        component[start] = c;
        while (!stack.empty()) {
            const uint32_t i = stack.back();
            stack.pop_back();
            projected[c] += projected_area[i];
            if (s.kind[i] == PartSurface::outer) outer_projected[c] += projected_area[i];
            for (uint32_t j : s.adjacent(i))
                if (component[j] < 0 && upper[j] == upper[start] && overlapping[j] == overlapping[start]) {
                    component[j] = c;
                    stack.push_back(j);
                }
        }
    }
    const size_t count = label.size();
    std::vector<std::vector<int>> links(count);
    for (size_t i = 0; i < n; ++i)
        for (uint32_t j : s.adjacent(i))
            if (component[i] != component[j]) links[component[i]].push_back(component[j]);
    for (auto& l : links) {
        std::sort(l.begin(), l.end());
        l.erase(std::unique(l.begin(), l.end()), l.end());
    }
    std::vector<char> fixed(count, 0);
    // Each side grows from its largest patch of the outer surface (the inner
    // surface is not connected to it where the part has no sides: a whole
    // closed shell).
    int root[2] = {-1, -1};  // [0]: M⁻, [1]: M⁺
    for (size_t c = 0; c < count; ++c) {
        int& r = root[label[c] ? 1 : 0];
        if (r < 0 || std::make_pair(outer_projected[c], projected[c]) > std::make_pair(outer_projected[r], projected[r]))
            r = int(c);
    }
    for (int r : root)
        if (r >= 0) fixed[r] = 1;
    std::vector<int> order(count);
    for (size_t c = 0; c < count; ++c) order[c] = int(c);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return projected[a] > projected[b]; });

    // Cheapest path from root[side] to `target`: entering a node of the other
    // label costs its projected area; fixed nodes of the other label block.
    // The search stops when the target is settled (its path is then final).
    // (The queue is a binary heap on one reused vector, as std::priority_queue keeps it.)
    using Entry = std::pair<double, int>;
    std::vector<Entry> queue;
    const auto search = [&](int side, int target, std::vector<double>& distance, std::vector<int>& previous) {
        distance.assign(count, 1e300);
        previous.assign(count, -1);
        if (root[side] < 0) return;
        const std::greater<Entry> later;
        queue.assign(1, Entry(0.0, root[side]));
        distance[root[side]] = 0;
        while (!queue.empty()) {
            std::pop_heap(queue.begin(), queue.end(), later);
            const auto [dist, c] = queue.back();
            queue.pop_back();
            if (dist > distance[c]) continue;
            if (c == target) return;
            for (int next : links[c]) {
                const bool same = (label[next] != 0) == (side == 1);
                if (fixed[next] && !same) continue;
                const double w = dist + (same ? 0.0 : projected[next]);
                if (w < distance[next]) {
                    distance[next] = w;
                    previous[next] = c;
                    queue.emplace_back(w, next);
                    std::push_heap(queue.begin(), queue.end(), later);
                }
            }
        }
    };
    std::vector<double> distance[2];
    std::vector<int> previous[2];
    for (int c : order) {
        if (fixed[c]) continue;
        // From the root of c's own label first: at no cost, that side wins
        // (ties go to M⁺, and reaching c from the other side costs at least
        // its projected area), and the other search is not needed.
        const int own = label[c] ? 1 : 0;
        search(own, c, distance[own], previous[own]);
        int side = own;
        if (!(distance[own][c] == 0 && (own == 1 || projected[c] > 0))) {
            search(1 - own, c, distance[1 - own], previous[1 - own]);
            side = distance[1][c] <= distance[0][c] ? 1 : 0;
        }
        for (int x = c; x >= 0 && !fixed[x]; x = previous[side][x]) {
            label[x] = char(side);
            fixed[x] = 1;
        }
    }
    for (size_t i = 0; i < n; ++i) upper[i] = label[component[i]];
}

//! Labels (graph cut + fix-up) and energy of `surface` for one direction.
std::pair<std::vector<char>, MoldabilityEnergy> label_part(const Shell& shell, const MoldabilityTerms& terms,
                                                           const PartSurface& surface, CutNetwork& network,
                                                           int direction, const MoldabilityWeights& weights) {
    const Vec3& d = terms.directions.directions[direction];
    std::vector<char> upper = network.labels(d);
    connect_patches(shell, terms, surface, d, direction, upper);
    const MoldabilityEnergy energy = moldability_energy(terms, surface, upper, direction, weights, nullptr);
    return {std::move(upper), energy};
}

PartMolding molding_of(const Shell& shell, const MoldabilityTerms& terms, PartSurface surface, int direction,
                       const MoldabilityWeights& weights) {
    PartMolding molding;
    CutNetwork network(surface);
    std::tie(molding.upper, molding.energy) = label_part(shell, terms, surface, network, direction, weights);
    molding.direction = direction;
    molding.surface = std::move(surface);
    return molding;
}

}  // namespace

class PartNetwork::Network : public CutNetwork {
public:
    using CutNetwork::CutNetwork;
};

PartNetwork::PartNetwork(const PartSurface& surface) : network_(std::make_unique<Network>(surface)) {}

PartNetwork::~PartNetwork() = default;

void PartNetwork::update(const std::vector<uint32_t>& triangles) { network_->update(triangles); }

void PartNetwork::relabel(const Shell& shell, const MoldabilityTerms& terms, const MoldabilityWeights& weights,
                          PartMolding& molding) {
    std::tie(molding.upper, molding.energy) =
        label_part(shell, terms, molding.surface, *network_, molding.direction, weights);
}

namespace {

//! One direction per axis (d and −d give the same mold with its halves
//! swapped: mirrored unary costs, the same E_P), the `count` axes first whose
//! estimate is lowest: E_P of the labelling M⁺ = {n·d ≥ 0} before the cut
//! (each visible triangle's lesser overhang, plus every overlap of the part
//! along the axis, since facing pairs then share a label).
std::vector<int> ranked_candidates(const Shell& shell, const MoldabilityTerms& terms, const PartSurface& surface,
                                   size_t count) {
    // The visible (outer and side) triangles and the outer ones' S_low
    // triangles, in surface order (so each sum adds in the same order).
    std::vector<uint32_t> visible, outer;
    std::vector<double> in_part(shell.triangle_count(), 0.0);  // 1 or 0, a factor (no branch to mispredict)
    for (size_t i = 0; i < surface.size(); ++i) {
        if (surface.kind[i] == PartSurface::inner) continue;
        visible.push_back(uint32_t(i));
        if (surface.kind[i] == PartSurface::outer) {
            outer.push_back(surface.source[i]);
            in_part[surface.source[i]] = 1.0;
        }
    }
    // One direction per axis, each estimated independently (in parallel).
    std::vector<int> axis_directions;
    for (size_t d = 0; d < terms.directions.directions.size(); ++d)
        if (terms.axes[terms.axis_of_direction[d]] == terms.directions.directions[d]) axis_directions.push_back(int(d));
    std::vector<std::pair<double, int>> estimate(axis_directions.size());
    tbb::parallel_for(size_t(0), axis_directions.size(), [&](size_t a) {
        const int d = axis_directions[a];
        const int axis = terms.axis_of_direction[d];
        const Vec3& dir = terms.directions.directions[d];
        double e = 0;
        // The lesser overhang is zero unless the triangle is within the draft
        // angle of parallel to the axis (|n·d| < sin φ).
        const double within_draft = std::sin(terms.draft);
        for (uint32_t i : visible)
            if (std::abs(dot(surface.normal[i], dir)) < within_draft)
                e += std::min(overhang_term(surface.normal[i], surface.area[i], dir, terms.draft),
                              overhang_term(surface.normal[i], surface.area[i], -1.0 * dir, terms.draft));
        // Adding 0 for a partner outside the part leaves the sum as it is.
        const uint32_t* offset = terms.overlaps[axis].offset.data();
        const uint32_t* partner = terms.overlaps[axis].partner.data();
        const float* area = terms.overlaps[axis].area.data();
        for (uint32_t t : outer)
            for (uint32_t k = offset[t]; k < offset[t + 1]; ++k) e += in_part[partner[k]] * (0.5 * area[k]);
        estimate[a] = {e, d};
    });
    count = std::min(count, estimate.size());
    std::partial_sort(estimate.begin(), estimate.begin() + count, estimate.end());
    std::vector<int> ranked;
    for (size_t i = 0; i < count; ++i) ranked.push_back(estimate[i].second);
    return ranked;
}

}  // namespace

PartMolding parting_line(const Shell& shell, const MoldabilityTerms& terms, const std::vector<int>& part_of_triangle,
                         int part, int direction, const MoldabilityWeights& weights) {
    return molding_of(shell, terms, part_surface(shell, part_of_triangle, part), direction, weights);
}

PartMolding best_parting_line(const Shell& shell, const MoldabilityTerms& terms,
                              const std::vector<int>& part_of_triangle, int part, const MoldabilityWeights& weights,
                              const std::vector<int>& hints, Progress& progress, size_t candidates_checked) {
    PartSurface surface = part_surface(shell, part_of_triangle, part);
    std::vector<int> candidates = ranked_candidates(shell, terms, surface, candidates_checked);
    for (int hint : hints) {
        const Vec3& axis = terms.axes[terms.axis_of_direction[hint]];
        const int d = terms.directions.directions[hint] == axis ? hint : terms.directions.opposite[hint];
        if (std::find(candidates.begin(), candidates.end(), d) == candidates.end()) candidates.push_back(d);
    }
    // Each candidate's labelling is kept, so the best one is not computed twice.
    std::vector<std::pair<std::vector<char>, MoldabilityEnergy>> labelled(candidates.size());
    tbb::enumerable_thread_specific<std::unique_ptr<CutNetwork>> networks;
    tbb::parallel_for(size_t(0), candidates.size(), [&](size_t c) {
        labelled[c].second.total = 1e300;
        if (progress.cancelled()) return;
        auto& network = networks.local();
        if (!network) network = std::make_unique<CutNetwork>(surface);
        labelled[c] = label_part(shell, terms, surface, *network, candidates[c], weights);
    });
    progress.check();
    size_t best = 0;
    for (size_t c = 1; c < candidates.size(); ++c)
        if (labelled[c].second.total < labelled[best].second.total) best = c;
    PartMolding molding;
    molding.direction = candidates[best];
    molding.upper = std::move(labelled[best].first);
    molding.energy = labelled[best].second;
    molding.surface = std::move(surface);
    return molding;
}

}  // namespace fabvdb::surface
