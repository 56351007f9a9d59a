// bench_drain: `fabvdb drain` stage by stage on the shared models scaled to
// 80 mm with a 3 mm wall, then the reference sand-pile simulation (no code in
// common with the model) of the optimized holes and of as many holes at the
// lowest points, through the same operator routine (as printed, then 9 turns
// drawn with seed 1 from the 162 directions). Prints per-stage seconds and
// the simulated residual powder of both hole sets.
#include <chrono>
#include <cstdio>
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

double simulate(const openvdb::FloatGrid& shell, const std::vector<fabvdb::powder::DrainHole>& holes) {
    std::vector<fabvdb::powder::SandpileHole> drills;
    for (const auto& hole : holes) drills.push_back({hole.center, hole.axis, hole.diameter, hole.depth});
    fabvdb::powder::SandpileOptions options;
    options.cell_size = 1.0;
    options.routine = fabvdb::powder::operator_routine({0, 0, -1}, fabvdb::thesis_directions().directions, 10, 1);
    fabvdb::Progress progress;
    return fabvdb::powder::simulate_sandpile(shell, drills, options, progress).residual_fraction();
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> models = {"bunny.off", "kitten.obj", "fertility.off", "armadillo_29k.obj", "airplane.obj"};
    if (argc > 1) models.assign(argv + 1, argv + argc);
    for (const std::string& name : models) {
        fabvdb::Progress progress;
        const fabvdb::Mesh mesh = scaled(fabvdb::io::read_mesh(std::string(FABVDB_SHARED_DATA) + "/meshes/" + name, progress), 80.0);
        fabvdb::powder::DrainPartOptions options;
        options.wall = 3.0;
        options.input_name = name;
        const auto start = std::chrono::steady_clock::now();
        const auto result = fabvdb::powder::drain_part(mesh, options, progress);
        const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::printf("%s: %.2f s total, %zu holes, %zu patches, %zu candidates, predicted residual %.2f%% (baseline %.2f%%)\n",
                    name.c_str(), total, result.plan.holes.size(), result.plan.patches.size(),
                    result.plan.candidate_count, 100 * result.plan.evaluation.residual_fraction(),
                    100 * result.plan.baseline_evaluation.residual_fraction());
        for (const auto& [stage, seconds] : result.timings) std::printf("  %-30s %.3f s\n", stage.c_str(), seconds);
        const double optimized = simulate(*result.shell, result.plan.holes);
        const double baseline = simulate(*result.shell, result.plan.baseline);
        std::printf("  simulated residual: optimized %.2f%%, baseline %.2f%% -> %s\n", 100 * optimized, 100 * baseline,
                    optimized < baseline ? "optimized better" : "baseline not beaten");
        std::fflush(stdout);
    }
    return 0;
}
