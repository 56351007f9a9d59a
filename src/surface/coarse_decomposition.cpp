//! coarse_decomposition: region growing for N_P = 2, 3, ... with parting lines
//! and undercut depths computed in parallel over the parts.
#include "surface/coarse_decomposition.h"

#include <algorithm>
#include <map>
#include <string>

#include <tbb/parallel_for.h>

#include "core/stage_clock.h"
#include "surface/undercut_depth.h"

namespace fabvdb::surface {

double Decomposition::total_energy() const {
    double sum = 0;
    for (const PartMolding& p : parts) sum += p.energy.total;
    return sum;
}

std::vector<PartMolding> parting_lines(const Shell& shell, const MoldabilityTerms& terms,
                                       const std::vector<int>& part_of_triangle, const std::vector<int>& directions,
                                       const MoldabilityWeights& weights) {
    std::vector<PartMolding> parts(directions.size());
    tbb::parallel_for(size_t(0), directions.size(), [&](size_t p) {
        parts[p] = parting_line(shell, terms, part_of_triangle, int(p), directions[p], weights);
    });
    return parts;
}

double undercut_line_spacing(const Shell& shell) { return 0.005 / shell.unit_scale; }

double undercut_reach(const Shell& shell, const DecompositionOptions& options) {
    return 2 * std::max(options.max_undercut_depth, 0.02) / shell.unit_scale;
}

UndercutDepth deepest_undercut(const Shell& shell, const MoldabilityTerms& terms, const Decomposition& d,
                               double reach) {
    std::vector<UndercutDepth> depth(d.parts.size());
    const double spacing = undercut_line_spacing(shell);
    tbb::parallel_for(size_t(0), d.parts.size(), [&](size_t p) {
        depth[p] = undercut_depth(shell, d.part_of_triangle, int(p), terms.directions.directions[d.parts[p].direction],
                                  spacing, reach);
    });
    UndercutDepth deepest;
    for (const UndercutDepth& part : depth)
        if (part.depth > deepest.depth) deepest = part;
    return deepest;
}

namespace {

Vec3 triangle_centre(const Mesh& mesh, size_t t) {
    const Triangle& corners = mesh.triangles[t];
    Vec3 centre{0, 0, 0};
    for (int k = 0; k < 3; ++k)
        centre[k] = (mesh.vertices[corners[0]][k] + mesh.vertices[corners[1]][k] + mesh.vertices[corners[2]][k]) / 3.0;
    return centre;
}

// The S_low triangle in the domain whose centre lies nearest `point`; -1
// when no triangle is in the domain.
int domain_triangle_nearest(const Shell& shell, const Elements& elements, const Vec3& point) {
    int nearest = -1;
    double best = 1e300;
    for (size_t t = 0; t < shell.triangle_count(); ++t) {
        if (elements.element_of_triangle[t] < 0) continue;
        const Vec3 centre = triangle_centre(shell.outer, t);
        double d2 = 0;
        for (int k = 0; k < 3; ++k) d2 += (centre[k] - point[k]) * (centre[k] - point[k]);
        if (d2 < best) {
            best = d2;
            nearest = int(t);
        }
    }
    return nearest;
}

// The next attempt's seeds when an attempt under γ is too deep: its own
// regions' last seeds and directions, plus the element at its deepest
// undercut facing the candidate direction nearest its normal, so a part can
// form there with a direction that casts it. Empty when that element already
// seeds a region. `seeded_at`: the centre of the triangle chosen.
struct TargetedSeeds {
    std::vector<int> seeds, directions;
    Vec3 seeded_at{0, 0, 0};
};

TargetedSeeds seeds_at_undercut(const Shell& shell, const MoldabilityTerms& terms, const Elements& elements,
                                const Regions& regions, const Vec3& undercut_at) {
    TargetedSeeds next;
    const int t = domain_triangle_nearest(shell, elements, undercut_at);
    if (t < 0) return next;
    const int element = elements.element_of_triangle[t];
    if (std::find(regions.seed.begin(), regions.seed.end(), element) != regions.seed.end()) return next;
    next.seeds = regions.seed;
    next.directions = regions.direction;
    next.seeds.push_back(element);
    next.directions.push_back(closest_direction(terms, shell.normal[t]));
    next.seeded_at = triangle_centre(shell.outer, t);
    return next;
}

}  // namespace

Decomposition coarse_decomposition(const Shell& shell, const MoldabilityTerms& terms,
                                   const DecompositionOptions& options, nlohmann::json& log, Progress& progress) {
    const Elements elements = make_elements(shell, {}, std::vector<char>(shell.triangle_count(), 1));
    // Regions are connected: a surface of several pieces needs a part per
    // piece cast solid, else two (a closed shell as one part traps its core),
    // whatever was asked.
    const int pieces = int(connected_pieces(elements).size());
    const int per_piece = shell.solid ? 1 : 2;
    const int first = std::max(options.parts, per_piece * pieces);
    const int last = std::max(options.parts > 0 ? options.parts : options.max_parts, first);
    const double depth_bound = options.max_undercut_depth / shell.unit_scale;
    Decomposition best, best_under;
    double best_energy = 1e300, best_under_depth = 1e300;
    int last_count = last;
    TargetedSeeds targeted;
    for (int count = first; count <= last_count; ++count) {
        progress.stage("coarse decomposition");
        std::map<std::string, double> seconds;
        StageClock clock(seconds);
        std::vector<int> seeds, directions;
        const bool at_undercut = int(targeted.seeds.size()) == count;
        if (at_undercut) {
            seeds = targeted.seeds;
            directions = targeted.directions;
        } else {
            random_seeds(shell, terms, elements, count, seeds, directions);
        }
        const Regions regions = grow_regions(shell, terms, elements, seeds, directions, options.overlap_weight,
                                             options.max_iterations, progress);
        const double grow_seconds = clock.lap("grow");
        Decomposition attempt;
        attempt.part_of_triangle = regions.region_of_triangle;
        attempt.parts = parting_lines(shell, terms, attempt.part_of_triangle, regions.direction, options.weights);
        const double cut_seconds = clock.lap("parting_line");
        const double energy = attempt.total_energy();
        const UndercutDepth deepest = deepest_undercut(shell, terms, attempt, undercut_reach(shell, options));
        nlohmann::json record = {{"parts", int(seeds.size())},
                                 {"seeds", at_undercut ? "previous attempt's, and one at its deepest undercut" : "random"},
                                 {"undercut_depth", deepest.depth},
                                 {"undercut_at", deepest.at},
                                 {"iterations", regions.iterations},
                                 {"region_cost_per_iteration", regions.cost_per_iteration},
                                 {"moldability_energy", energy},
                                 {"timings",
                                  {{"per_iteration", grow_seconds / regions.iterations}, {"parting_line", cut_seconds}}}};
        if (at_undercut) record["seeded_at"] = targeted.seeded_at;
        log.push_back(std::move(record));
        const bool under = energy < options.gamma;
        if (under && best_under_depth == 1e300) last_count = std::min(last, count + options.depth_attempts);
        targeted = under && deepest.depth > 0 && deepest.depth > depth_bound
                       ? seeds_at_undercut(shell, terms, elements, regions, deepest.at)
                       : TargetedSeeds{};
        if (under && deepest.depth < best_under_depth) {
            best_under_depth = deepest.depth;
            best_under = std::move(attempt);
        } else if (!under && energy < best_energy) {
            best_energy = energy;
            best = std::move(attempt);
        }
        if ((under && deepest.depth <= depth_bound) || int(seeds.size()) < count) break;
    }
    return best_under_depth < 1e300 ? best_under : best;
}

}  // namespace fabvdb::surface
