// bench_drain: `fabvdb drain` stage by stage on models scaled to --size mm
// (default 80) with a 3 mm wall (--holes auto or a count), then the
// reference sand-pile simulation (no code in common with the model):
// - the optimized holes against as many holes at the lowest points, each
//   through R operator routines (as printed, then 9 turns drawn from the 162
//   directions with seeds 1 to R; the mean, whose spread between single
//   routines is wide);
// - the optimized holes through the cleaning routine the drain recommends,
//   against the mean of the random routines;
// - the model's ranking of random hole sets (1 to 4 holes drawn from the
//   candidate sites, seed 7) against the simulation's: Spearman's rank
//   correlation of predicted and simulated residuals, and the mean absolute
//   error of the prediction in points.
// Each is given twice: with the prediction as `fabvdb drain` reports it (the
// mean of the model's own 64 routines), and with the model run through the
// very routines the simulation runs (seeds 1 to R). The second takes the
// operator's luck out of the comparison: the simulation's spread between
// single routines is wide (see docs/benchmarks.md), and a mean of R of them
// ranks hole sets by the routines drawn as much as by the holes.
// The simulation's rules can be varied to check that the model does not
// hold only under the rules it was fitted to: --sim-repose DEG (angle of
// repose of the simulated grains; the model keeps 35°), --sim-window N
// (cells over which a pile's slope is measured: the toppling neighbourhood),
// --sim-cell MM (grain cell size, default 1).
// --trace prints, for the optimized holes and each of the R routines, the
// residual after every turn by the model and by the simulation.
// --sim-cache FILE keeps each simulated residual under the exact hole set,
// routine and rules, and reuses it: the simulation is most of the bench's
// time and does not depend on the model, so a change to the model is
// measured in seconds. Delete the file when the simulation or the
// hollowing changes.
// A model is a file in the shared meshes folder, or a path (e.g. a corpus
// mesh). A table of every model's figures closes the output.
// Usage: bench_drain [--sets N] [--routines R] [--size MM] [--holes auto|K] [--sim-repose DEG]
//                    [--sim-window N] [--sim-cell MM] [--sim-cache FILE] [--trace] [models...]
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

//! The simulation's rules (see the top).
struct Rules {
    double repose_degrees = 35.0;
    int window = 4;
    double cell = 1.0;
    std::string key() const {
        char text[96];
        std::snprintf(text, sizeof text, " rules %.17g %d %.17g", repose_degrees, window, cell);
        return text;
    }
};

fabvdb::powder::SandpileResult simulate_turns(const openvdb::FloatGrid& shell,
                                              const std::vector<fabvdb::powder::DrainHole>& holes,
                                              const std::vector<fabvdb::Vec3>& routine, const Rules& rules) {
    std::vector<fabvdb::powder::SandpileHole> drills;
    for (const auto& hole : holes) drills.push_back({hole.center, hole.axis, hole.diameter, hole.depth});
    fabvdb::powder::SandpileOptions options;
    options.cell_size = rules.cell;
    options.repose_radians = rules.repose_degrees * M_PI / 180.0;
    options.slope_window = rules.window;
    options.routine = routine;
    fabvdb::Progress progress;
    return fabvdb::powder::simulate_sandpile(shell, drills, options, progress);
}

//! The simulation's operator routine of `seed`: as printed, then 9 turns drawn from the 162 directions.
std::vector<fabvdb::Vec3> simulation_routine(int seed) {
    return fabvdb::powder::operator_routine({0, 0, -1}, fabvdb::thesis_directions().directions, 10, uint64_t(seed));
}

//! The mean simulated residual fraction over the routines of seeds 1 to
//! `routines`. With `turns`, each routine's result is kept there (the
//! cache then cannot answer: it keeps the mean alone).
double simulate(const openvdb::FloatGrid& shell, const std::vector<fabvdb::powder::DrainHole>& holes, int routines,
                const std::string& model, const Rules& rules, SimulationCache& cache,
                std::vector<fabvdb::powder::SandpileResult>* turns = nullptr) {
    const std::string key = SimulationCache::key(model, routines, holes) + rules.key();
    double cached = 0.0;
    if (!turns && cache.find(key, cached)) return cached;
    double sum = 0.0;
    for (int seed = 1; seed <= routines; ++seed) {
        const fabvdb::powder::SandpileResult result = simulate_turns(shell, holes, simulation_routine(seed), rules);
        sum += result.residual_fraction();
        if (turns) turns->push_back(result);
    }
    cache.add(key, sum / routines);
    return sum / routines;
}

//! The simulated residual fraction through one given routine (first turn included).
double simulate(const openvdb::FloatGrid& shell, const std::vector<fabvdb::powder::DrainHole>& holes,
                const std::vector<fabvdb::Vec3>& routine, const std::string& model, const Rules& rules,
                SimulationCache& cache) {
    std::string key = SimulationCache::key(model, 0, holes) + rules.key() + " routine";
    char number[32];
    for (const auto& g : routine)
        for (double v : g) {
            std::snprintf(number, sizeof number, " %.17g", v);
            key += number;
        }
    double cached = 0.0;
    if (cache.find(key, cached)) return cached;
    const double residual = simulate_turns(shell, holes, routine, rules).residual_fraction();
    cache.add(key, residual);
    return residual;
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

//! The simulation's routines of seeds 1 to `routines` as the model's
//! routines of later turns.
std::vector<fabvdb::powder::Routine> simulated_routines(const fabvdb::powder::DrainabilityModel& model, int routines) {
    const std::vector<fabvdb::Vec3>& directions = fabvdb::thesis_directions().directions;
    std::vector<fabvdb::powder::Routine> result;
    for (int seed = 1; seed <= routines; ++seed) {
        const std::vector<fabvdb::Vec3> gravities = simulation_routine(seed);
        fabvdb::powder::Routine routine;
        for (size_t turn = 1; turn < gravities.size(); ++turn) {
            uint32_t best = 0;
            double best_dot = -2.0;
            for (uint32_t k = 0; k < directions.size(); ++k) {
                const fabvdb::Vec3& g = model.turn_gravity(k);
                const double dot = g[0] * gravities[turn][0] + g[1] * gravities[turn][1] + g[2] * gravities[turn][2];
                if (dot > best_dot) best_dot = dot, best = k;
            }
            if (best_dot < 1.0 - 1e-9) {
                std::fprintf(stderr, "the model's orientations are not the simulation's\n");
                std::exit(1);
            }
            routine.push_back(best);
        }
        result.push_back(std::move(routine));
    }
    return result;
}

double mean_absolute_error(const std::vector<double>& x, const std::vector<double>& y) {
    double sum = 0.0;
    for (size_t i = 0; i < x.size(); ++i) sum += std::fabs(x[i] - y[i]);
    return x.empty() ? NAN : sum / double(x.size());
}

struct Row {
    std::string model;
    size_t holes = 0;
    double predicted = 0, predicted_baseline = 0, predicted_routine = 0;
    //! The model through the simulation's routines (see the top).
    double paired = 0, paired_baseline = 0;
    double simulated = 0, simulated_baseline = 0, simulated_routine = 0;
    double spearman = NAN, spearman_paired = NAN, error = NAN, error_paired = NAN;
    double seconds = 0;
};

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> models;
    int set_count = 10, routines = 1, hole_count = 0;
    double size = 80.0;
    Rules rules;
    std::string cache_path;
    bool trace = false;
    for (int a = 1; a < argc; ++a) {
        auto next = [&]() -> const char* {
            if (a + 1 >= argc) {
                std::fprintf(stderr, "%s needs a value\n", argv[a]);
                std::exit(1);
            }
            return argv[++a];
        };
        if (std::strcmp(argv[a], "--sets") == 0)
            set_count = std::atoi(next());
        else if (std::strcmp(argv[a], "--routines") == 0)
            routines = std::max(1, std::atoi(next()));
        else if (std::strcmp(argv[a], "--size") == 0)
            size = std::atof(next());
        else if (std::strcmp(argv[a], "--holes") == 0) {
            const char* value = next();
            hole_count = std::strcmp(value, "auto") == 0 ? 0 : std::atoi(value);
        } else if (std::strcmp(argv[a], "--sim-repose") == 0)
            rules.repose_degrees = std::atof(next());
        else if (std::strcmp(argv[a], "--sim-window") == 0)
            rules.window = std::atoi(next());
        else if (std::strcmp(argv[a], "--sim-cell") == 0)
            rules.cell = std::atof(next());
        else if (std::strcmp(argv[a], "--sim-cache") == 0)
            cache_path = next();
        else if (std::strcmp(argv[a], "--trace") == 0)
            trace = true;
        else
            models.push_back(argv[a]);
    }
    if (models.empty()) models = {"bunny.off", "kitten.obj", "fertility.off", "armadillo_29k.obj", "airplane.obj"};
    SimulationCache cache(cache_path);
    std::vector<Row> rows;
    for (const std::string& name : models) {
        fabvdb::Progress progress;
        const std::string path =
            name.find('/') == std::string::npos ? std::string(FABVDB_SHARED_DATA) + "/meshes/" + name : name;
        const std::string label = name.substr(name.find_last_of('/') + 1) + " " + std::to_string(int(size)) + "mm";
        const fabvdb::Mesh mesh = scaled(fabvdb::io::read_mesh(path, progress), size);
        fabvdb::powder::DrainPartOptions options;
        options.wall = 3.0;
        options.input_name = name;
        options.plan.search.hole_count = hole_count;
        std::vector<std::vector<fabvdb::powder::DrainHole>> random_sets;
        std::vector<double> predicted, paired;
        double paired_optimized = 0.0, paired_baseline = 0.0;
        double inspect_seconds = 0.0;
        // Per simulated routine: the model's residual fraction after each turn (--trace).
        std::vector<std::vector<double>> model_turns;
        options.plan.inspect = [&](const fabvdb::powder::DrainabilityModel& model,
                                   const std::vector<fabvdb::powder::DrainHole>& candidates,
                                   const fabvdb::powder::DrainPlan& plan) {
            const auto inspect_start = std::chrono::steady_clock::now();
            const std::vector<fabvdb::powder::Routine> same = simulated_routines(model, routines);
            const auto through_same = [&](const std::vector<fabvdb::powder::DrainHole>& holes) {
                return model.evaluate(model.drain(holes), same).residual_fraction();
            };
            const fabvdb::powder::HoleSetDrain optimized = model.drain(plan.holes);
            paired_optimized = model.evaluate(optimized, same).residual_fraction();
            if (trace) {
                for (const fabvdb::powder::Routine& routine : same) {
                    model_turns.emplace_back();
                    for (size_t t = 0; t <= routine.size(); ++t) {
                        const fabvdb::powder::Routine prefix(routine.begin(), routine.begin() + long(t));
                        model_turns.back().push_back(model.evaluate(optimized, {prefix}).residual_fraction());
                    }
                }
            }
            paired_baseline = through_same(plan.baseline);
            std::mt19937_64 generator(7);
            for (int s = 0; s < set_count; ++s) {
                std::vector<fabvdb::powder::DrainHole> holes;
                const size_t count = 1 + generator() % 4;
                for (size_t tries = 0; holes.size() < count && tries < 1000; ++tries) {
                    const auto& candidate = candidates[generator() % candidates.size()];
                    if (fabvdb::powder::spaced_from(candidate, holes, 2.0 * candidate.diameter)) holes.push_back(candidate);
                }
                predicted.push_back(model.evaluate(holes).residual_fraction());
                paired.push_back(through_same(holes));
                random_sets.push_back(std::move(holes));
            }
            inspect_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - inspect_start).count();
        };
        const auto start = std::chrono::steady_clock::now();
        fabvdb::powder::DrainPartResult result;
        try {
            result = fabvdb::powder::drain_part(mesh, options, progress);
        } catch (const std::exception& e) {
            std::printf("%s: drain failed: %s\n", label.c_str(), e.what());
            continue;
        }
        const auto& plan = result.plan;
        Row row;
        row.model = label;
        row.holes = plan.holes.size();
        // Without the evaluation of the random sets, which `fabvdb drain` does not do.
        row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() - inspect_seconds;
        row.predicted = plan.evaluation.residual_fraction();
        row.predicted_baseline = plan.baseline_evaluation.residual_fraction();
        row.predicted_routine = plan.routine_evaluation.residual_fraction();
        row.paired = paired_optimized;
        row.paired_baseline = paired_baseline;
        std::printf("%s: %.2f s total, %zu holes, %zu patches, %zu candidates, predicted residual %.2f%% (baseline "
                    "%.2f%%), under the routine %.2f%%\n",
                    label.c_str(), row.seconds, row.holes, plan.patches.size(), plan.candidate_count,
                    100 * row.predicted, 100 * row.predicted_baseline, 100 * row.predicted_routine);
        for (const auto& [stage, seconds] : result.timings) std::printf("  %-30s %.3f s\n", stage.c_str(), seconds);
        if (plan.holes.empty()) {
            rows.push_back(row);
            continue;
        }
        std::vector<fabvdb::powder::SandpileResult> simulated_turns;
        row.simulated =
            simulate(*result.shell, plan.holes, routines, label, rules, cache, trace ? &simulated_turns : nullptr);
        row.simulated_baseline = simulate(*result.shell, plan.baseline, routines, label, rules, cache);
        for (size_t r = 0; r < model_turns.size() && r < simulated_turns.size(); ++r) {
            const fabvdb::powder::SandpileResult& turns = simulated_turns[r];
            std::printf("  routine %zu, residual %% after each turn, model / simulated:", r + 1);
            for (size_t t = 0; t < model_turns[r].size() && t < turns.residual_after_turn.size(); ++t)
                std::printf(" %.2f/%.2f", 100 * model_turns[r][t],
                            100 * turns.residual_after_turn[t] / turns.initial_volume);
            std::printf("\n");
        }
        std::vector<fabvdb::Vec3> routine{plan.first_gravity};
        routine.insert(routine.end(), plan.routine.begin(), plan.routine.end());
        row.simulated_routine = simulate(*result.shell, plan.holes, routine, label, rules, cache);
        std::printf("  simulated residual (mean of %d routines), %zu holes: optimized %.2f%%, lowest points %.2f%% -> %s\n",
                    routines, row.holes, 100 * row.simulated, 100 * row.simulated_baseline,
                    row.simulated < row.simulated_baseline ? "optimized better" : "baseline not beaten");
        std::printf("  the model through the same %d routines: optimized %.2f%%, lowest points %.2f%%\n", routines,
                    100 * row.paired, 100 * row.paired_baseline);
        std::printf("  simulated through the recommended routine: %.2f%% (random routines: %.2f%%) -> %s\n",
                    100 * row.simulated_routine, 100 * row.simulated,
                    row.simulated_routine < row.simulated ? "routine better" : "routine not better");
        std::vector<double> simulated;
        for (size_t s = 0; s < random_sets.size(); ++s) {
            simulated.push_back(simulate(*result.shell, random_sets[s], routines, label, rules, cache));
            std::printf("  random set %zu (%zu holes): predicted %.2f%% (through the same routines %.2f%%), "
                        "simulated %.2f%%\n",
                        s, random_sets[s].size(), 100 * predicted[s], 100 * paired[s], 100 * simulated.back());
        }
        if (!random_sets.empty()) {
            row.error = 100 * mean_absolute_error(predicted, simulated);
            row.error_paired = 100 * mean_absolute_error(paired, simulated);
        }
        if (random_sets.size() > 1) {
            row.spearman = spearman(predicted, simulated);
            row.spearman_paired = spearman(paired, simulated);
            std::printf("  over %zu random sets: Spearman(predicted, simulated) %.3f, through the same routines %.3f; "
                        "mean absolute error %.2f points, through the same routines %.2f\n",
                        random_sets.size(), row.spearman, row.spearman_paired, row.error, row.error_paired);
        }
        rows.push_back(row);
        std::fflush(stdout);
    }
    std::printf("\n| model | holes | predicted opt / lowest / routine %% | same routines opt / lowest %% | "
                "simulated opt / lowest %% | less powder | simulated routine %% | Spearman / same routines | "
                "error / same routines (points) | drain s |\n|---|---|---|---|---|---|---|---|---|---|\n");
    double reduction_sum = 0.0;
    int compared = 0;
    for (const Row& row : rows) {
        const double reduction =
            row.simulated_baseline > 0 ? 1.0 - row.simulated / row.simulated_baseline : NAN;
        if (std::isfinite(reduction)) {
            reduction_sum += reduction;
            ++compared;
        }
        std::printf("| %s | %zu | %.2f / %.2f / %.2f | %.2f / %.2f | %.2f / %.2f | %.0f%% | %.2f | %.3f / %.3f | "
                    "%.2f / %.2f | %.2f |\n",
                    row.model.c_str(), row.holes, 100 * row.predicted, 100 * row.predicted_baseline,
                    100 * row.predicted_routine, 100 * row.paired, 100 * row.paired_baseline, 100 * row.simulated,
                    100 * row.simulated_baseline, 100 * reduction, 100 * row.simulated_routine, row.spearman,
                    row.spearman_paired, row.error, row.error_paired, row.seconds);
    }
    if (compared > 0)
        std::printf("\nmean reduction against the lowest-point holes (simulated, %d models with powder left by "
                    "either): %.0f%%; rules: repose %.0f deg, window %d, cell %.2f mm, %d routines\n",
                    compared, 100 * reduction_sum / compared, rules.repose_degrees, rules.window, rules.cell, routines);
    return 0;
}
