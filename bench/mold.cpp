// The whole `fabvdb mold` chain per shared model scaled to 100 mm (longest
// side): decomposition, input level set, detail restoration, sweeps, part
// surfaces, mold assembly (parting surface, solids, booleans), distance to
// the input; per-stage seconds from the progress callback, plus the figures a
// maker checks (parts, added volume, distance ratios, triangles).
// Usage: bench_mold [model ...] (default: bunny.off kitten.obj fertility.off)
//        environment FABVDB_BENCH_VOXEL=mm to override the default voxel,
//        FABVDB_BENCH_DEFORM=0 to run without the ARAP overhang deformation,
//        FABVDB_BENCH_MAX_DEFORMATION=mm to bound its displacement (default one voxel).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include <openvdb/openvdb.h>

#include "core/error.h"
#include "core/progress.h"
#include "io/mesh_io.h"
#include "surface/decompose.h"
#include "surface/decomposition_io.h"
#include "surface/decomposition_parts.h"
#include "surface/mold_generation.h"

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
};

}  // namespace

int main(int argc, char** argv) {
    openvdb::initialize();
    std::vector<std::string> models;
    for (int i = 1; i < argc; ++i) models.push_back(argv[i]);
    if (models.empty()) models = {"bunny.off", "kitten.obj", "fertility.off"};
    const char* voxel = std::getenv("FABVDB_BENCH_VOXEL");
    for (const std::string& name : models) {
        try {
            StageTimer timer;
            fabvdb::Progress progress(&StageTimer::callback, &timer, nullptr);
            const auto start = Clock::now();
            fabvdb::Mesh input = fabvdb::io::read_mesh(std::string(FABVDB_SHARED_DATA "/meshes/") + name, progress);
            const fabvdb::BoundingBox box = fabvdb::bounding_box(input);
            const double longest =
                std::max({box.max[0] - box.min[0], box.max[1] - box.min[1], box.max[2] - box.min[2]});
            // Scaled as `--fit 100mm` scales, so the figures are those of `fabvdb mold --fit 100mm`.
            const double factor = 100 / longest;
            for (fabvdb::Vec3& p : input.vertices)
                for (double& c : p) c *= factor;

            // The shell thickness `fabvdb mold` uses by default (3% of the
            // longest side, computed the same way: the decomposition changes
            // with its last bit, e.g. fertility's parts at 3.0 and at
            // 2.999999999999999 mm differ).
            const fabvdb::BoundingBox fitted = fabvdb::bounding_box(input);
            fabvdb::surface::DecomposeSettings settings;
            settings.shell.thickness = 0.03 * std::max({fitted.max[0] - fitted.min[0], fitted.max[1] - fitted.min[1],
                                                        fitted.max[2] - fitted.min[2]});
            const auto decomposition = fabvdb::surface::decompose_mesh(input, settings, {}, progress);
            const auto document = fabvdb::surface::decomposition_document(
                decomposition.shell, decomposition.terms, decomposition.decomposition, settings.decomposition);
            const auto model = fabvdb::surface::decomposed_parts(document, name, input);
            const double decompose_seconds = std::chrono::duration<double>(Clock::now() - start).count();

            fabvdb::surface::MoldGenerationOptions options;
            if (voxel) options.voxel_size = std::atof(voxel);
            if (const char* deform = std::getenv("FABVDB_BENCH_DEFORM")) options.deform_overhangs = std::atoi(deform) != 0;
            if (const char* bound = std::getenv("FABVDB_BENCH_MAX_DEFORMATION")) options.max_deformation = std::atof(bound);
            const auto molds = fabvdb::surface::generate_molds(input, model, options, progress);
            timer.finish();
            const double total = std::chrono::duration<double>(Clock::now() - start).count();

            size_t part_triangles = 0, mold_triangles = 0;
            double added = 0, restored = 0;
            for (const auto& part : molds.parts) {
                part_triangles += part.part.triangles.size();
                mold_triangles += part.mold.top.triangles.size() + part.mold.bottom.triangles.size();
                added += part.added_volume;
                restored += part.restored_volume;
            }
            std::printf("%s (100 mm, %zu triangles): %zu parts, voxel %.3f mm, added volume %.1f%%, "
                        "distance to the input mean %.4f%% max %.3f%% of the diagonal, part triangles %zu, "
                        "mold triangles %zu; decomposition %.1f s, total %.1f s\n",
                        name.c_str(), input.triangles.size(), molds.parts.size(), molds.voxel_size,
                        100 * added / restored, 100 * molds.mean_distance / molds.diagonal,
                        100 * molds.max_distance / molds.diagonal, part_triangles, mold_triangles, decompose_seconds,
                        total);
            for (const auto& part : molds.parts)
                std::printf("  part %d: restored %.0f mm3, ARAP %zu handles, moved max %.3f mean %.3f mm, "
                            "volume change %+.1f mm3; handed over %.0f mm3, received %.0f mm3; sweep added %.0f mm3 "
                            "(%.2f%%), kept out %.0f mm3, %zu columns trimmed; distance mean %.4f%% max %.3f%%\n",
                            part.id, part.restored_volume, part.deformation_handles, part.deformation_max,
                            part.deformation_mean, part.deformed_volume_change, part.given_volume,
                            part.received_volume, part.added_volume, 100 * part.added_volume / part.restored_volume,
                            part.removed_by_keep_out, part.columns_trimmed,
                            100 * part.mean_distance / molds.diagonal, 100 * part.max_distance / molds.diagonal);
            for (const auto& [stage, seconds] : molds.seconds)
                std::printf("  mold stage %-28s %8.2f s\n", stage.c_str(), seconds);
            for (const auto& [stage, seconds] : timer.seconds)
                if (seconds >= 0.05) std::printf("  progress stage %-40s %8.2f s\n", stage.c_str(), seconds);
        } catch (const fabvdb::Error& e) {
            std::printf("%s: failed: %s\n", name.c_str(), e.what());
        }
    }
    return 0;
}
