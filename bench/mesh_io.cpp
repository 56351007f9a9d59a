// Mesh I/O speed: reads each format (written from the 86k-triangle armadillo,
// plus the largest shared files as they come) with fabvdb and with OpenMesh 9,
// best of three runs each, and writes each format with fabvdb.
//   bench_mesh_io            (prints one table; no arguments)
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "io/mesh_io.h"

namespace {

double best_of_three_ms(const std::function<void()>& run) {
    double best = 1e300;
    for (int i = 0; i < 3; ++i) {
        const auto start = std::chrono::steady_clock::now();
        run();
        best = std::min(best, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    return best;
}

}  // namespace

int main() {
    const std::string meshes = FABVDB_SHARED_DATA "/meshes/";
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / "fabvdb_bench_mesh_io";
    std::filesystem::create_directories(folder);
    fabvdb::Progress progress;
    const fabvdb::Mesh armadillo = fabvdb::io::read_mesh(meshes + "armadillo_86k.obj", progress);

    std::vector<std::string> files = {meshes + "armadillo_86k.obj", meshes + "stanford-bunny.obj",
                                      meshes + "camelhead.off", meshes + "bunny_trimesh_broken.ply"};
    std::printf("%-28s %9s %11s %11s %11s %8s\n", "file", "MB", "write ms", "fabvdb ms", "OpenMesh ms", "ratio");
    for (const char* extension : {"stl", "obj", "ply", "off", "3mf"}) {
        const std::string path = (folder / (std::string("armadillo.") + extension)).string();
        const double write_ms = best_of_three_ms([&] { fabvdb::io::write_mesh(armadillo, path); });
        std::printf("%-28s %9.2f %11.1f\n", ("armadillo." + std::string(extension)).c_str(),
                    std::filesystem::file_size(path) / 1e6, write_ms);
        files.push_back(path);
    }
    for (const std::string& path : files) {
        size_t triangles = 0;
        const double ours = best_of_three_ms([&] {
            fabvdb::Progress quiet;
            triangles = fabvdb::io::read_mesh(path, quiet).triangles.size();
        });
        const bool openmesh_reads = path.substr(path.size() - 3) != "3mf";
        size_t openmesh_faces = 0;
        const double theirs = openmesh_reads ? best_of_three_ms([&] {
            OpenMesh::TriMesh_ArrayKernelT<> mesh;
            OpenMesh::IO::read_mesh(mesh, path);
            openmesh_faces = mesh.n_faces();
        })
                                             : 0.0;
        const std::string name = std::filesystem::path(path).filename().string();
        if (openmesh_reads)
            std::printf("%-28s %9.2f %11s %11.1f %11.1f %8.2f   (%zu vs %zu triangles)\n", name.c_str(),
                        std::filesystem::file_size(path) / 1e6, "", ours, theirs, theirs / ours, triangles,
                        openmesh_faces);
        else
            std::printf("%-28s %9.2f %11s %11.1f %11s %8s   (%zu triangles)\n", name.c_str(),
                        std::filesystem::file_size(path) / 1e6, "", ours, "-", "-", triangles);
    }
    std::filesystem::remove_all(folder);
    return 0;
}
