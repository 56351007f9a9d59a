// Per-stage timings of mold generation's building blocks on synthetic parts
// of growing size: sweeping a standing ring into a double height field
// (volume), and assembling the two-piece mold of a flat torus (parting
// surface, features, exact booleans). Stage times come from the progress
// callback. Usage: bench_mold [voxel_mm] [grid_step_mm]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

#include <openvdb/tools/MeshToVolume.h>

#include "core/progress.h"
#include "surface/mold_assembly.h"
#include "volume/extract_mesh.h"
#include "volume/sweep.h"

namespace {

using Clock = std::chrono::steady_clock;

struct StageTimer {
    std::map<std::string, double> seconds;
    std::string stage;
    Clock::time_point since = Clock::now();
    static int callback(void* user, const char* stage, double) {
        auto* self = static_cast<StageTimer*>(user);
        if (self->stage != stage) {
            const auto now = Clock::now();
            if (!self->stage.empty()) self->seconds[self->stage] += std::chrono::duration<double>(now - self->since).count();
            self->stage = stage;
            self->since = now;
        }
        return 0;
    }
    void finish() { callback(this, "", 1.0); }
    void print(const char* what) const {
        for (const auto& [name, s] : seconds) std::printf("  %-40s %8.3f s   (%s)\n", name.c_str(), s, what);
    }
};

fabvdb::Mesh torus(double major, double minor, int segments_major, int segments_minor) {
    fabvdb::Mesh mesh;
    for (int i = 0; i < segments_major; ++i)
        for (int j = 0; j < segments_minor; ++j) {
            const double u = 2 * M_PI * i / segments_major, v = 2 * M_PI * j / segments_minor;
            const double r = major + minor * std::cos(v);
            mesh.vertices.push_back({r * std::cos(u), r * std::sin(u), minor * std::sin(v)});
        }
    auto index = [&](int i, int j) {
        return uint32_t((i % segments_major) * segments_minor + (j % segments_minor));
    };
    for (int i = 0; i < segments_major; ++i)
        for (int j = 0; j < segments_minor; ++j) {
            mesh.triangles.push_back({index(i, j), index(i + 1, j), index(i + 1, j + 1)});
            mesh.triangles.push_back({index(i, j), index(i + 1, j + 1), index(i, j + 1)});
        }
    return mesh;
}

}  // namespace

int main(int argc, char** argv) {
    openvdb::initialize();
    const double voxel = argc > 1 ? std::atof(argv[1]) : 0.25;
    const double grid_step = argc > 2 ? std::atof(argv[2]) : 1.25;

    for (int scale : {1, 2}) {
        const double major = 20.0 * scale, minor = 6.0 * scale;
        fabvdb::Mesh ring = torus(major, minor, 96 * scale, 32 * scale);
        for (auto& p : ring.vertices) p = {p[0], -p[2], p[1]};  // standing: not moldable along z
        std::vector<openvdb::Vec3s> points;
        std::vector<openvdb::Vec3I> triangles;
        for (const auto& p : ring.vertices) points.emplace_back(float(p[0]), float(p[1]), float(p[2]));
        for (const auto& t : ring.triangles) triangles.emplace_back(t[0], t[1], t[2]);
        auto transform = openvdb::math::Transform::createLinearTransform(voxel);
        auto level_set = openvdb::tools::meshToLevelSet<openvdb::FloatGrid>(*transform, points, triangles, 3.0f);

        StageTimer timer;
        fabvdb::Progress progress(&StageTimer::callback, &timer, nullptr);
        fabvdb::volume::SweepStats stats;
        auto swept = fabvdb::volume::sweep_double_height_field(*level_set, {0.3, -0.2, 1.0}, {}, {}, progress, &stats);
        const fabvdb::Mesh part = fabvdb::volume::extract_mesh(*swept, 0.0, progress);
        timer.finish();
        std::printf("standing ring R=%.0f r=%.0f mm, voxel %.2f mm: %zu active voxels, volume %.0f -> %.0f mm^3, "
                    "%zu triangles\n",
                    major, minor, voxel, size_t(level_set->activeVoxelCount()), stats.volume_before,
                    stats.volume_after, part.triangles.size());
        timer.print("sweep");

        const fabvdb::Mesh flat = torus(major, minor, 96 * scale, 32 * scale);
        StageTimer mold_timer;
        fabvdb::Progress mold_progress(&StageTimer::callback, &mold_timer, nullptr);
        fabvdb::surface::MoldOptions options;
        options.margin = 10.0;
        options.grid_step = grid_step;
        const auto start = Clock::now();
        const auto mold = fabvdb::surface::assemble_mold(flat, {0, 0, 1}, options, mold_progress);
        mold_timer.finish();
        std::printf("flat torus mold (%zu part triangles, grid %.2f mm): top %zu, bottom %zu triangles, %.2f s\n",
                    flat.triangles.size(), grid_step, mold.top.triangles.size(), mold.bottom.triangles.size(),
                    std::chrono::duration<double>(Clock::now() - start).count());
        mold_timer.print("mold");
    }
    return 0;
}
