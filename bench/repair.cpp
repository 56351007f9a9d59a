// bench_repair: the whole `fabvdb repair` against the floor of plain OpenVDB
// (meshToLevelSet + volumeToMesh, which does less and fails on holes), side by
// side at the same voxel size, on the clean shared models scaled to 100 mm;
// then a ~1.4M-triangle scan (armadillo_86k subdivided twice) at the default
// resolution. Each run is a forked child, so its peak memory (ru_maxrss) and
// time are its own. Usage: bench_repair [voxel_mm (0.2)] [model ...]
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <openvdb/tools/MeshToVolume.h>
#include <openvdb/tools/VolumeToMesh.h>

#include "io/mesh_io.h"
#include "subdivided.h"
#include "volume/repair.h"

namespace {

struct Run {
    double seconds = 0.0;
    double peak_mib = 0.0;
    bool ok = false;
};

// Runs `body` in a forked child; returns its wall time and peak resident memory.
template <class Body>
Run in_child(const Body& body) {
    int pipe_fds[2];
    if (pipe(pipe_fds) != 0) return {};
    const pid_t pid = fork();
    if (pid == 0) {
        close(pipe_fds[0]);
        const auto start = std::chrono::steady_clock::now();
        body();
        Run run;
        run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        rusage usage{};
        getrusage(RUSAGE_SELF, &usage);
        run.peak_mib = double(usage.ru_maxrss) / 1024.0;
        run.ok = true;
        if (write(pipe_fds[1], &run, sizeof run) != ssize_t(sizeof run)) _exit(1);
        _exit(0);
    }
    close(pipe_fds[1]);
    Run run;
    if (read(pipe_fds[0], &run, sizeof run) != ssize_t(sizeof run)) run = Run{};
    close(pipe_fds[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    return run;
}

fabvdb::Mesh scaled_to(fabvdb::Mesh mesh, double longest_side) {
    const fabvdb::BoundingBox box = fabvdb::bounding_box(mesh);
    double longest = 0.0;
    for (int k = 0; k < 3; ++k) longest = std::max(longest, box.max[k] - box.min[k]);
    for (auto& v : mesh.vertices)
        for (int k = 0; k < 3; ++k) v[k] = (v[k] - box.min[k]) * longest_side / longest;
    return mesh;
}

void repair_once(const fabvdb::Mesh& mesh, double voxel) {
    fabvdb::Progress progress;
    fabvdb::volume::RepairOptions options;
    options.distance.voxel_size = voxel;
    const auto result = fabvdb::volume::repair(mesh, options, progress);
    if (result.mesh.triangles.empty()) _exit(2);
}

void openvdb_floor(const fabvdb::Mesh& mesh, double voxel) {
    openvdb::initialize();
    auto transform = openvdb::math::Transform::createLinearTransform(voxel);
    std::vector<openvdb::Vec3s> points;
    for (const auto& v : mesh.vertices) points.emplace_back(float(v[0]), float(v[1]), float(v[2]));  // world space
    std::vector<openvdb::Vec3I> triangles;
    for (const auto& t : mesh.triangles) triangles.emplace_back(t[0], t[1], t[2]);
    std::vector<openvdb::Vec4I> quads;
    auto grid = openvdb::tools::meshToLevelSet<openvdb::FloatGrid>(*transform, points, triangles, quads, 3.0f);
    std::vector<openvdb::Vec3s> out_points;
    std::vector<openvdb::Vec3I> out_triangles;
    std::vector<openvdb::Vec4I> out_quads;
    openvdb::tools::volumeToMesh(*grid, out_points, out_triangles, out_quads, 0.0, 0.0);
    if (out_quads.empty() && out_triangles.empty()) _exit(2);
}

}  // namespace

int main(int argc, char** argv) {
    const double voxel = argc > 1 ? std::atof(argv[1]) : 0.2;
    std::vector<std::string> models = {"bunny.off", "kitten.obj", "fertility.off", "armadillo_29k.obj",
                                       "armadillo_86k.obj", "max-planck_decimated.obj", "airplane.obj",
                                       "torus.obj", "sphere.obj", "spot.obj", "elephant.obj", "fandisk.obj",
                                       "rocker-arm.obj", "3holes.off"};
    if (argc > 2) models.assign(argv + 2, argv + argc);
    std::printf("voxel %.3f mm, models scaled to 100 mm\n", voxel);
    std::printf("%-26s %9s %10s %10s %7s %11s %11s\n", "model", "triangles", "repair s", "openvdb s", "ratio",
                "repair MiB", "openvdb MiB");
    double ratio_sum = 0.0;
    int count = 0;
    for (const std::string& name : models) {
        fabvdb::Progress progress;
        const fabvdb::Mesh mesh = scaled_to(fabvdb::io::read_mesh(FABVDB_SHARED_DATA "/meshes/" + name, progress), 100.0);
        const Run repair = in_child([&] { repair_once(mesh, voxel); });
        const Run floor = in_child([&] { openvdb_floor(mesh, voxel); });
        const double ratio = repair.seconds / floor.seconds;
        std::printf("%-26s %9zu %10.2f %10.2f %7.2f %11.0f %11.0f%s\n", name.c_str(), mesh.triangles.size(),
                    repair.seconds, floor.seconds, ratio, repair.peak_mib, floor.peak_mib,
                    repair.ok && floor.ok ? "" : "  (a run failed)");
        ratio_sum += ratio;
        ++count;
    }
    if (count) std::printf("mean ratio %.2f\n", ratio_sum / count);

    fabvdb::Progress progress;
    const fabvdb::Mesh scan = fabvdb::bench::subdivided(fabvdb::bench::subdivided(
        scaled_to(fabvdb::io::read_mesh(FABVDB_SHARED_DATA "/meshes/armadillo_86k.obj", progress), 100.0)));
    const double default_voxel = fabvdb::volume::voxel_size_for_resolution(scan, 400, "scan");
    for (double v : {default_voxel, voxel}) {
        const Run run = in_child([&] { repair_once(scan, v); });
        std::printf("scan: %zu triangles, voxel %.3f mm: repair %.2f s, peak %.0f MiB%s\n", scan.triangles.size(), v,
                    run.seconds, run.peak_mib, run.ok ? "" : " (failed)");
    }
    return 0;
}
