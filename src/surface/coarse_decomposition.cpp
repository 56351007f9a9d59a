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

double deepest_undercut(const Shell& shell, const MoldabilityTerms& terms, const Decomposition& d, double reach) {
    std::vector<double> depth(d.parts.size(), 0.0);
    const double spacing = undercut_line_spacing(shell);
    tbb::parallel_for(size_t(0), d.parts.size(), [&](size_t p) {
        depth[p] = undercut_depth(shell, d.part_of_triangle, int(p), terms.directions.directions[d.parts[p].direction],
                                  spacing, reach)
                       .depth;
    });
    return depth.empty() ? 0.0 : *std::max_element(depth.begin(), depth.end());
}

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
    for (int count = first; count <= last_count; ++count) {
        progress.stage("coarse decomposition");
        std::map<std::string, double> seconds;
        StageClock clock(seconds);
        std::vector<int> seeds, directions;
        random_seeds(shell, terms, elements, count, seeds, directions);
        const Regions regions = grow_regions(shell, terms, elements, seeds, directions, options.overlap_weight,
                                             options.max_iterations, progress);
        const double grow_seconds = clock.lap("grow");
        Decomposition attempt;
        attempt.part_of_triangle = regions.region_of_triangle;
        attempt.parts = parting_lines(shell, terms, attempt.part_of_triangle, regions.direction, options.weights);
        const double cut_seconds = clock.lap("parting_line");
        const double energy = attempt.total_energy();
        const double depth = deepest_undercut(shell, terms, attempt, undercut_reach(shell, options));
        log.push_back({{"parts", int(seeds.size())},
                       {"undercut_depth", depth},
                       {"iterations", regions.iterations},
                       {"region_cost_per_iteration", regions.cost_per_iteration},
                       {"moldability_energy", energy},
                       {"timings",
                        {{"per_iteration", grow_seconds / regions.iterations}, {"parting_line", cut_seconds}}}});
        const bool under = energy < options.gamma;
        if (under && best_under_depth == 1e300) last_count = std::min(last, count + options.depth_attempts);
        if (under && depth < best_under_depth) {
            best_under_depth = depth;
            best_under = std::move(attempt);
        } else if (!under && energy < best_energy) {
            best_energy = energy;
            best = std::move(attempt);
        }
        if ((under && depth <= depth_bound) || int(seeds.size()) < count) break;
    }
    return best_under_depth < 1e300 ? best_under : best;
}

}  // namespace fabvdb::surface
