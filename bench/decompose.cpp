// Mold decomposition against the thesis' timings (Tables 3.2 and 3.3, single
// thread, Intel Core i7 2.2 GHz): per model, at the thesis' S_low size, the
// pre-computation per direction, the coarse decomposition per iteration, the
// part count, the cut and merge edits and the boundary smoothing; each next
// to the thesis' figure as a ratio (thesis / ours, > 1 is faster). Also the
// energy, the smoothness before and after smoothing, and the merged part's
// E_P with the ranked direction candidates against all 81 axes. Times are
// processor times (single thread), so other processes sharing the machine
// do not inflate them. Runs single-threaded unless
// --threads N is given. Usage: bench_decompose [--threads N] [model ...]
#include <tbb/global_control.h>

#include <algorithm>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <string>
#include <vector>

#include "core/error.h"
#include "io/mesh_io.h"
#include "surface/decompose.h"
#include "core/vec3_ops.h"

using namespace fabvdb;
using namespace fabvdb::surface;

namespace {

struct ThesisRow {
    const char* name;
    const char* file;
    size_t low_res;           // S_low triangles in Table 3.2
    double per_direction_ms;  // pre-computation per direction
    double per_iteration_ms;  // coarse decomposition per iteration
    int parts;
    double cut_ms, merge_ms;  // Table 3.3
    double smoothing_ms;      // Table 3.3, smoothing all snake vertices
};

const ThesisRow rows[] = {
    {"sphere", "sphere.obj", 320, 3.84, 11.0, 2, 5.60, 26.2, 90.8},
    {"torus", "torus.obj", 1152, 34.9, 82.0, 2, 15.0, 71.4, 665},
    {"kitten", "kitten.obj", 2310, 136, 396, 2, 47.4, 209, 3964},
    {"airplane", "airplane.obj", 19136, 13910.28, 31711, 2, 692, 1872, 176574},
    {"fertility", "fertility.off", 8788, 2011.67, 4886.17, 2, 208, 891, 51580},
    {"bunny", "bunny.off", 2740, 210, 2110, 2, 53.2, 232, 3430},
};

//! Processor time of this process in milliseconds: with one thread it is the
//! run's own work, unaffected by other processes sharing the cores.
double cpu_ms() {
    timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return 1e3 * double(t.tv_sec) + 1e-6 * double(t.tv_nsec);
}

}  // namespace

int main(int argc, char** argv) {
    int threads = 1;
    std::vector<std::string> only;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--threads") && i + 1 < argc)
            threads = std::atoi(argv[++i]);
        else
            only.push_back(argv[i]);
    }
    tbb::global_control control(tbb::global_control::max_allowed_parallelism, size_t(std::max(threads, 1)));
    std::printf("threads %d; ratio = thesis / ours (higher is faster); edits in processor time, stages in wall time "
                "x the run's processor share\n",
                threads);
    std::printf("%-9s %6s | %-25s | %-25s | %-13s | %-25s | %-25s | %-27s | %s\n", "model", "S_low",
                "precompute/dir ms (ratio)", "coarse/iter ms (ratio)", "parts", "cut ms (ratio)", "merge ms (ratio)",
                "smoothing ms (ratio)", "E_P (gamma 0.05), E_smooth before -> after; merge E_P ranked/exhaustive");
    for (const ThesisRow& row : rows) {
        if (!only.empty() && std::find(only.begin(), only.end(), row.name) == only.end()) continue;
        Progress progress;
        const Mesh input = io::read_mesh(std::string(FABVDB_SHARED_DATA "/meshes/") + row.file, progress);
        const BoundingBox box = bounding_box(input);
        DecomposeSettings settings;
        settings.shell.target_triangles = row.low_res;
        settings.shell.thickness =
            0.03 * std::max({box.max[0] - box.min[0], box.max[1] - box.min[1], box.max[2] - box.min[2]});
        const double wall_start = double(std::chrono::duration_cast<std::chrono::microseconds>(
                                              std::chrono::steady_clock::now().time_since_epoch())
                                              .count());
        const double cpu_start = cpu_ms();
        DecomposeResult r = decompose_mesh(input, settings, {}, progress);
        // The report's stage times are wall-clock; on a shared machine they are
        // scaled by this run's processor share (processor time / wall time).
        const double share =
            (cpu_ms() - cpu_start) /
            (1e-3 * (double(std::chrono::duration_cast<std::chrono::microseconds>(
                                std::chrono::steady_clock::now().time_since_epoch())
                                .count()) -
                     wall_start));
        const double per_direction = double(r.report["timings"]["precompute_per_direction"]) * 1000 * share;
        const nlohmann::json& last = r.report["attempts"].back();
        const double per_iteration = double(last["timings"]["per_iteration"]) * 1000 * share;
        const double smoothing_ms = double(r.report["timings"]["smoothing"]) * 1000 * share;
        const nlohmann::json& smoothness = r.report["smoothing"]["smoothness"];
        // Cut: a closed loop around the middle of part 0; merge it back.
        Shell& shell = r.shell;
        Decomposition& d = r.decomposition;
        Vec3 centre{0, 0, 0}, axis{0, 0, 0};
        size_t count = 0;
        for (size_t t = 0; t < shell.triangle_count(); ++t)
            if (d.part_of_triangle[t] == 0) {
                const Triangle& f = shell.outer.triangles[t];
                centre = centre + (1.0 / 3.0) * (shell.outer.vertices[f[0]] + shell.outer.vertices[f[1]] +
                                                  shell.outer.vertices[f[2]]);
                ++count;
            }
        centre = (1.0 / double(count)) * centre;
        size_t seed = 0;
        double nearest = 1e300;
        for (size_t t = 0; t < shell.triangle_count(); ++t) {
            if (d.part_of_triangle[t] != 0) continue;
            const Vec3& p = shell.outer.vertices[shell.outer.triangles[t][0]];
            if (norm(p - centre) < nearest) nearest = norm(p - centre), seed = t;
        }
        const Vec3 p0 = shell.outer.vertices[shell.outer.triangles[seed][0]];
        axis = shell.normal[seed];
        const Vec3 u = normalized(cross(axis, std::abs(axis[0]) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0}));
        const Vec3 v = cross(axis, u);
        const double ring = 0.08 / shell.unit_scale;
        Edit cut;
        cut.type = Edit::cut;
        cut.closed = true;
        for (int i = 0; i < 12; ++i)
            cut.points.push_back(p0 + ring * (std::cos(2 * M_PI * i / 12) * u + std::sin(2 * M_PI * i / 12) * v));
        double cut_ms = NAN, merge_ms = NAN, ranked = NAN, exhaustive = NAN;
        try {
            double start = cpu_ms();
            apply_edit(shell, r.terms, settings.decomposition, cut, 0, d, progress);
            cut_ms = cpu_ms() - start;
            // Merge the cap with a part across one of its boundary edges.
            const int cap = d.part_of_triangle[seed];
            Edit merge;
            merge.type = Edit::merge;
            const auto centroid = [&](size_t t) {
                const Triangle& f = shell.outer.triangles[t];
                return (1.0 / 3.0) * (shell.outer.vertices[f[0]] + shell.outer.vertices[f[1]] + shell.outer.vertices[f[2]]);
            };
            for (size_t t = 0; t < shell.triangle_count() && merge.points.empty(); ++t)
                for (int k = 0; k < 3 && merge.points.empty(); ++k)
                    if (d.part_of_triangle[t] == cap && d.part_of_triangle[shell.neighbor[t][k]] != cap)
                        merge.points = {centroid(t), centroid(size_t(shell.neighbor[t][k]))};
            start = cpu_ms();
            const nlohmann::json record = apply_edit(shell, r.terms, settings.decomposition, merge, 1, d, progress);
            merge_ms = cpu_ms() - start;
            // The merged part's direction from the ranked candidates against all 81 axes.
            const int merged = record["parts_touched"][0];
            ranked = d.parts[merged].energy.total;
            exhaustive = best_parting_line(shell, r.terms, d.part_of_triangle, merged, settings.decomposition.weights,
                                           {}, progress, 81)
                             .energy.total;
        } catch (const Error& e) {
            std::fprintf(stderr, "%s: edit skipped: %s\n", row.name, e.what());
        }
        std::printf("%-9s %6zu | %8.2f vs %8.2f (%5.1fx) | %8.2f vs %8.0f (%5.1fx) | %2zu (thesis %d) | %7.2f vs %6.1f "
                    "(%5.1fx) | %7.2f vs %6.1f (%5.1fx) | %8.1f vs %8.0f (%5.1fx) | %.4f, %.3f -> %.3f; %.4f/%.4f\n",
                    row.name, shell.triangle_count(), per_direction, row.per_direction_ms,
                    row.per_direction_ms / per_direction, per_iteration, row.per_iteration_ms,
                    row.per_iteration_ms / per_iteration, r.report["parts"].size(), row.parts, cut_ms, row.cut_ms,
                    row.cut_ms / cut_ms, merge_ms, row.merge_ms, row.merge_ms / merge_ms, smoothing_ms,
                    row.smoothing_ms, row.smoothing_ms / smoothing_ms, double(r.report["total_moldability_energy"]),
                    double(smoothness.front()), double(smoothness.back()), ranked, exhaustive);
        std::fflush(stdout);
    }
    return 0;
}
