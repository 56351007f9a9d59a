// bench_drain: `fabvdb drain` stage by stage on the shared models scaled to
// 80 mm with a 3 mm wall (automatic hole count), then the reference
// sand-pile simulation (no code in common with the model) through operator
// routines (as printed, then 9 turns drawn from the 162 directions with seeds
// 1 to R; the residual is the mean over the R routines, the expectation the
// model predicts, whose spread between single routines is wide):
// - the optimized holes against as many holes at the lowest points;
// - the model's ranking of random hole sets (1 to 4 holes drawn from the
//   candidate sites, seed 7) against the simulation's: Spearman's rank
//   correlation of predicted and simulated residuals.
// --sim-cache FILE keeps each simulated residual under the exact hole set
// (model, routines, every hole's figures in full precision) and reuses it:
// the simulation is most of the bench's time and does not depend on the
// model, so a change to the model is measured in seconds. Delete the file
// when the simulation or the hollowing changes.
// Usage: bench_drain [--sets N] [--routines R] [--sim-cache FILE] [model files in the shared meshes folder...]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <numeric>
#include <random>
#include <string>

#include "core/icosphere.h"
#include "io/mesh_io.h"
#include "powder/drain_part.h"
#include "powder/sandpile_routine.h"
#include "powder/sandpile_simulation.h"

namespace {

fabvdb::Mesh scaled(fabvdb::Mesh mesh, double size) {
    const fabvdb::BoundingBox box = fabvdb::bounding_box(mesh);
    double longest = 0;
    for (int k = 0; k < 3; ++k) longest = std::max(longest, box.max[k] - box.min[k]);
    for (auto& p : mesh.vertices)
        for (int k = 0; k < 3; ++k) p[k] = (p[k] - 0.5 * (box.min[k] + box.max[k])) * size / longest;
    return mesh;
}

//! Simulated residuals by hole set, read from and appended to a file (see --sim-cache).
class SimulationCache {
public:
    explicit SimulationCache(std::string path) : path_(std::move(path)) {
        if (path_.empty()) return;
        std::ifstream in(path_);
        std::string key;
        double value;
        while (std::getline(in, key, '\t') && in >> value && in.ignore(1)) entries_[key] = value;
    }
    static std::string key(const std::string& model, int routines, const std::vector<fabvdb::powder::DrainHole>& holes) {
        std::string text = model + " " + std::to_string(routines);
        char number[32];
        for (const auto& hole : holes)
            for (double v : {hole.center[0], hole.center[1], hole.center[2], hole.axis[0], hole.axis[1], hole.axis[2],
                             hole.diameter, hole.depth}) {
                std::snprintf(number, sizeof number, " %.17g", v);
                text += number;
            }
        return text;
    }
    bool find(const std::string& key, double& value) const {
        const auto found = entries_.find(key);
        if (found == entries_.end()) return false;
        value = found->second;
        return true;
    }
    void add(const std::string& key, double value) {
        if (path_.empty()) return;
        entries_[key] = value;
        std::ofstream out(path_, std::ios::app);
        char number[32];
        std::snprintf(number, sizeof number, "%.17g", value);
        out << key << '\t' << number << '\n';
    }

private:
    std::string path_;
    std::map<std::string, double> entries_;
};

//! The mean simulated residual fraction over the routines of seeds 1 to `routines`.
double simulate(const openvdb::FloatGrid& shell, const std::vector<fabvdb::powder::DrainHole>& holes, int routines,
                const std::string& model, SimulationCache& cache) {
    const std::string key = SimulationCache::key(model, routines, holes);
    double cached = 0.0;
    if (cache.find(key, cached)) return cached;
    std::vector<fabvdb::powder::SandpileHole> drills;
    for (const auto& hole : holes) drills.push_back({hole.center, hole.axis, hole.diameter, hole.depth});
    double sum = 0.0;
    for (int seed = 1; seed <= routines; ++seed) {
        fabvdb::powder::SandpileOptions options;
        options.cell_size = 1.0;
        options.routine =
            fabvdb::powder::operator_routine({0, 0, -1}, fabvdb::thesis_directions().directions, 10, uint64_t(seed));
        fabvdb::Progress progress;
        sum += fabvdb::powder::simulate_sandpile(shell, drills, options, progress).residual_fraction();
    }
    cache.add(key, sum / routines);
    return sum / routines;
}

std::vector<double> ranks(const std::vector<double>& values) {
    std::vector<size_t> order(values.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return values[a] < values[b]; });
    std::vector<double> rank(values.size());
    for (size_t a = 0; a < order.size();) {
        size_t b = a;
        while (b + 1 < order.size() && values[order[b + 1]] == values[order[a]]) ++b;
        for (size_t k = a; k <= b; ++k) rank[order[k]] = 0.5 * double(a + b);
        a = b + 1;
    }
    return rank;
}

double spearman(const std::vector<double>& x, const std::vector<double>& y) {
    const std::vector<double> rx = ranks(x), ry = ranks(y);
    const double n = double(x.size());
    const double mx = std::accumulate(rx.begin(), rx.end(), 0.0) / n, my = std::accumulate(ry.begin(), ry.end(), 0.0) / n;
    double sxy = 0, sxx = 0, syy = 0;
    for (size_t i = 0; i < rx.size(); ++i) {
        sxy += (rx[i] - mx) * (ry[i] - my);
        sxx += (rx[i] - mx) * (rx[i] - mx);
        syy += (ry[i] - my) * (ry[i] - my);
    }
    return sxx > 0 && syy > 0 ? sxy / std::sqrt(sxx * syy) : 0.0;
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> models;
    int set_count = 10, routines = 1;
    std::string cache_path;
    for (int a = 1; a < argc; ++a) {
        if (std::strcmp(argv[a], "--sets") == 0 && a + 1 < argc)
            set_count = std::atoi(argv[++a]);
        else if (std::strcmp(argv[a], "--routines") == 0 && a + 1 < argc)
            routines = std::max(1, std::atoi(argv[++a]));
        else if (std::strcmp(argv[a], "--sim-cache") == 0 && a + 1 < argc)
            cache_path = argv[++a];
        else
            models.push_back(argv[a]);
    }
    if (models.empty()) models = {"bunny.off", "kitten.obj", "fertility.off", "armadillo_29k.obj", "airplane.obj"};
    SimulationCache cache(cache_path);
    for (const std::string& name : models) {
        fabvdb::Progress progress;
        const fabvdb::Mesh mesh =
            scaled(fabvdb::io::read_mesh(std::string(FABVDB_SHARED_DATA) + "/meshes/" + name, progress), 80.0);
        fabvdb::powder::DrainPartOptions options;
        options.wall = 3.0;
        options.input_name = name;
        std::vector<std::vector<fabvdb::powder::DrainHole>> random_sets;
        std::vector<double> predicted;
        double inspect_seconds = 0.0;
        options.plan.inspect = [&](const fabvdb::powder::DrainabilityModel& model,
                                   const std::vector<fabvdb::powder::DrainHole>& candidates) {
            const auto inspect_start = std::chrono::steady_clock::now();
            std::mt19937_64 generator(7);
            for (int s = 0; s < set_count; ++s) {
                std::vector<fabvdb::powder::DrainHole> holes;
                const size_t size = 1 + generator() % 4;
                for (size_t tries = 0; holes.size() < size && tries < 1000; ++tries) {
                    const auto& candidate = candidates[generator() % candidates.size()];
                    if (fabvdb::powder::spaced_from(candidate, holes, 2.0 * candidate.diameter)) holes.push_back(candidate);
                }
                predicted.push_back(model.evaluate(holes).residual_fraction());
                random_sets.push_back(std::move(holes));
            }
            inspect_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - inspect_start).count();
        };
        const auto start = std::chrono::steady_clock::now();
        const auto result = fabvdb::powder::drain_part(mesh, options, progress);
        // Without the evaluation of the random sets, which `fabvdb drain` does not do.
        const double total =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() - inspect_seconds;
        std::printf("%s: %.2f s total, %zu holes, %zu patches, %zu candidates, predicted residual %.2f%% (baseline %.2f%%)\n",
                    name.c_str(), total, result.plan.holes.size(), result.plan.patches.size(),
                    result.plan.candidate_count, 100 * result.plan.evaluation.residual_fraction(),
                    100 * result.plan.baseline_evaluation.residual_fraction());
        for (const auto& [stage, seconds] : result.timings) std::printf("  %-30s %.3f s\n", stage.c_str(), seconds);
        const double optimized = simulate(*result.shell, result.plan.holes, routines, name, cache);
        const double baseline = simulate(*result.shell, result.plan.baseline, routines, name, cache);
        std::printf("  simulated residual (mean of %d routines), %zu holes: optimized %.2f%%, lowest points %.2f%% -> %s\n",
                    routines, result.plan.holes.size(), 100 * optimized, 100 * baseline,
                    optimized < baseline ? "optimized better" : "baseline not beaten");
        std::vector<double> simulated;
        for (size_t s = 0; s < random_sets.size(); ++s) {
            simulated.push_back(simulate(*result.shell, random_sets[s], routines, name, cache));
            std::printf("  random set %zu (%zu holes): predicted %.2f%%, simulated %.2f%%\n", s, random_sets[s].size(),
                        100 * predicted[s], 100 * simulated.back());
        }
        if (!random_sets.empty())
            std::printf("  Spearman(predicted, simulated) over %zu random sets: %.3f\n", random_sets.size(),
                        spearman(predicted, simulated));
        std::fflush(stdout);
    }
    return 0;
}
