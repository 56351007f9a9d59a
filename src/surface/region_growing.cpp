//! Region growing with a lazy priority queue: an element's cost is re-evaluated
//! when it is popped (its overlap with the region may have appeared since it
//! was queued) and re-queued if it rose.
#include "surface/region_growing.h"

#include <algorithm>
#include <cmath>
#include <queue>
#include <random>
#include <tuple>

#include <tbb/parallel_for.h>

#include "core/vec3_ops.h"

namespace fabvdb::surface {

namespace {

struct Grower {
    const Shell& shell;
    const MoldabilityTerms& terms;
    const Elements& elements;
    double overlap_weight;
    std::vector<int> region_of_triangle;

    bool overlaps_region(uint32_t t, int region, int direction) const {
        const auto& o = terms.overlaps_along(direction);
        for (uint32_t i = o.offset[t]; i < o.offset[t + 1]; ++i)
            if (region_of_triangle[o.partner[i]] == region) return true;
        return false;
    }
    double triangle_cost(uint32_t t, int region, int direction) const {
        const double facing = dot(shell.normal[t], terms.directions.directions[direction]);
        const double base = shell.thin_segment[t] >= 0 ? -std::abs(facing) : -facing;
        return base + (overlaps_region(t, region, direction) ? overlap_weight : 0.0);
    }
    double element_cost(int element, int region, int direction) const {
        double sum = 0;
        for (uint32_t t : elements.triangles[element]) sum += triangle_cost(t, region, direction);
        return sum;
    }

    //! Assigns every reachable element; returns Σ C(t, r).
    double grow(const std::vector<int>& seeds, const std::vector<int>& directions) {
        region_of_triangle.assign(shell.triangle_count(), -1);
        std::vector<int> region_of_element(elements.triangles.size(), -1);
        using Entry = std::tuple<double, int, int>;  // cost, element, region
        std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
        const auto assign = [&](int e, int r) {
            region_of_element[e] = r;
            for (uint32_t t : elements.triangles[e]) region_of_triangle[t] = r;
            for (int next : elements.adjacent[e])
                if (region_of_element[next] < 0) queue.emplace(element_cost(next, r, directions[r]), next, r);
        };
        for (size_t r = 0; r < seeds.size(); ++r) assign(seeds[r], int(r));
        while (!queue.empty()) {
            const auto [cost, e, r] = queue.top();
            queue.pop();
            if (region_of_element[e] >= 0) continue;
            const double now = element_cost(e, r, directions[r]);
            if (now > cost + 1e-12) {
                queue.emplace(now, e, r);
                continue;
            }
            assign(e, r);
        }
        double total = 0;
        for (size_t t = 0; t < shell.triangle_count(); ++t) {
            const int r = region_of_triangle[t];
            if (r >= 0) total += triangle_cost(uint32_t(t), r, directions[r]);
        }
        return total;
    }

    //! argmin_{d∈D} Σ_{t∈r} C(t, r) for every region.
    std::vector<int> best_directions(int region_count) const {
        const size_t axis_count = terms.axes.size();
        const size_t direction_count = terms.directions.directions.size();
        std::vector<Vec3> normal_sum(region_count, Vec3{0, 0, 0});
        std::vector<std::vector<uint32_t>> thin_triangles(region_count);
        for (size_t t = 0; t < shell.triangle_count(); ++t) {
            const int r = region_of_triangle[t];
            if (r < 0) continue;
            if (shell.thin_segment[t] >= 0)
                thin_triangles[r].push_back(uint32_t(t));
            else
                normal_sum[r] = normal_sum[r] + shell.normal[t];
        }
        // Per axis (in parallel): the overlap cost of each region's triangles
        // that overlap their own region along it.
        std::vector<std::vector<double>> overlapping(axis_count, std::vector<double>(region_count, 0.0));
        tbb::parallel_for(size_t(0), axis_count, [&](size_t a) {
            const auto& o = terms.overlaps[a];
            for (size_t t = 0; t < shell.triangle_count(); ++t) {
                const int r = region_of_triangle[t];
                if (r < 0) continue;
                for (uint32_t i = o.offset[t]; i < o.offset[t + 1]; ++i)
                    if (region_of_triangle[o.partner[i]] == r) {
                        overlapping[a][r] += overlap_weight;
                        break;
                    }
            }
        });
        std::vector<int> best(region_count, 0);
        for (int r = 0; r < region_count; ++r) {
            double best_cost = 1e300;
            for (size_t d = 0; d < direction_count; ++d) {
                const Vec3& dir = terms.directions.directions[d];
                double cost = -dot(normal_sum[r], dir) + overlapping[terms.axis_of_direction[d]][r];
                for (uint32_t t : thin_triangles[r]) cost -= std::abs(dot(shell.normal[t], dir));
                if (cost < best_cost) {
                    best_cost = cost;
                    best[r] = int(d);
                }
            }
        }
        return best;
    }

    //! argmin_{e∈r} C(e, r) for every region.
    std::vector<int> best_seeds(const std::vector<int>& directions) const {
        const int region_count = int(directions.size());
        std::vector<double> best_cost(region_count, 1e300);
        std::vector<int> best(region_count, -1);
        for (size_t e = 0; e < elements.triangles.size(); ++e) {
            const int r = region_of_triangle[elements.triangles[e][0]];
            if (r < 0) continue;
            const double cost = element_cost(int(e), r, directions[r]);
            if (cost < best_cost[r]) {
                best_cost[r] = cost;
                best[r] = int(e);
            }
        }
        return best;
    }
};

}  // namespace

int closest_direction(const MoldabilityTerms& terms, const Vec3& v) {
    int best = 0;
    double best_dot = -2;
    for (size_t d = 0; d < terms.directions.directions.size(); ++d) {
        const double c = dot(terms.directions.directions[d], v);
        if (c > best_dot) {
            best_dot = c;
            best = int(d);
        }
    }
    return best;
}

std::vector<std::vector<int>> connected_pieces(const Elements& elements) {
    const size_t element_count = elements.triangles.size();
    std::vector<int> piece(element_count, -1);
    std::vector<std::vector<int>> pieces;
    for (size_t start = 0; start < element_count; ++start) {
        if (piece[start] >= 0) continue;
        pieces.emplace_back();
        std::vector<int> stack{int(start)};
        piece[start] = int(pieces.size() - 1);
        while (!stack.empty()) {
            const int e = stack.back();
            stack.pop_back();
            pieces.back().push_back(e);
            for (int next : elements.adjacent[e])
                if (piece[next] < 0) {
                    piece[next] = piece[start];
                    stack.push_back(next);
                }
        }
    }
    return pieces;
}

void random_seeds(const Shell& shell, const MoldabilityTerms& terms, const Elements& elements, int count,
                  std::vector<int>& seeds, std::vector<int>& directions) {
    const size_t element_count = elements.triangles.size();
    const std::vector<std::vector<int>> pieces = connected_pieces(elements);
    std::mt19937 generator(20190101u + unsigned(count));
    seeds.clear();
    std::vector<char> taken(element_count, 0);
    const auto take = [&](int e) {
        taken[e] = 1;
        seeds.push_back(e);
    };
    for (const auto& members : pieces)
        if (int(seeds.size()) < count)
            take(members[std::uniform_int_distribution<size_t>(0, members.size() - 1)(generator)]);
    // A closed piece as one region is no two-piece mold (its shell traps the
    // core): with several pieces, each gets a second seed while count allows.
    if (pieces.size() > 1)
        for (const auto& members : pieces) {
            if (int(seeds.size()) >= count || members.size() < 2) continue;
            int e;
            do e = members[std::uniform_int_distribution<size_t>(0, members.size() - 1)(generator)];
            while (taken[e]);
            take(e);
        }
    const size_t available = std::min<size_t>(size_t(count), element_count);
    while (seeds.size() < available) {
        const int e = int(std::uniform_int_distribution<size_t>(0, element_count - 1)(generator));
        if (!taken[e]) take(e);
    }
    directions.clear();
    for (int e : seeds) directions.push_back(closest_direction(terms, shell.normal[elements.triangles[e][0]]));
}

Regions grow_regions(const Shell& shell, const MoldabilityTerms& terms, const Elements& elements,
                     std::vector<int> seeds, std::vector<int> directions, double overlap_weight,
                     int max_iterations, Progress& progress) {
    Grower grower{shell, terms, elements, overlap_weight, {}};
    Regions regions;
    const int region_count = int(seeds.size());
    for (int iteration = 0; iteration < max_iterations; ++iteration) {
        progress.update(double(iteration) / max_iterations);
        regions.cost_per_iteration.push_back(grower.grow(seeds, directions));
        regions.iterations = iteration + 1;
        const std::vector<int> next_directions = grower.best_directions(region_count);
        const std::vector<int> next_seeds = grower.best_seeds(next_directions);
        regions.direction = next_directions;
        if (next_seeds == seeds && next_directions == directions) break;
        seeds = next_seeds;
        directions = next_directions;
    }
    regions.region_of_triangle = std::move(grower.region_of_triangle);
    return regions;
}

}  // namespace fabvdb::surface
