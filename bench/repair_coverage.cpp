// bench_repair_coverage: how far the input lies from the repaired output,
// measured apart from the repair (CGAL AABB tree over the output's
// triangles). Samples: every input vertex that a triangle uses (files may
// hold stray points), every edge midpoint and 16 random points per triangle.
// Prints, per resolution (voxels along the longest side, as `fabvdb repair
// --resolution N` with its other options at their defaults), the largest
// and mean distance in voxels, how many samples lie beyond one voxel, and
// the farthest sample.
// Usage: bench_repair_coverage MODEL [RESOLUTION ...] (default 96 400);
// MODEL is a file name in the shared meshes folder.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "io/mesh_io.h"
#include "support/cgal_mesh.h"
#include "volume/repair.h"

namespace {

using fabvdb::test::cgal::Point;
using fabvdb::test::cgal::point;
using fabvdb::test::cgal::Tree;
using fabvdb::test::cgal::Triangle3;

std::vector<Point> samples(const fabvdb::Mesh& mesh) {
    std::vector<Point> points;
    std::vector<char> used(mesh.vertices.size(), 0);
    for (const auto& t : mesh.triangles)
        for (uint32_t v : t) used[v] = 1;
    for (size_t v = 0; v < mesh.vertices.size(); ++v)
        if (used[v]) points.push_back(point(mesh.vertices[v]));
    std::mt19937 random(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (const auto& t : mesh.triangles) {
        const Point p[3] = {point(mesh.vertices[t[0]]), point(mesh.vertices[t[1]]), point(mesh.vertices[t[2]])};
        for (int k = 0; k < 3; ++k) points.push_back(CGAL::midpoint(p[k], p[(k + 1) % 3]));
        for (int s = 0; s < 16; ++s) {
            double a = unit(random), b = unit(random);
            if (a + b > 1.0) a = 1.0 - a, b = 1.0 - b;
            points.push_back(p[0] + a * (p[1] - p[0]) + b * (p[2] - p[0]));
        }
    }
    return points;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: bench_repair_coverage MODEL [RESOLUTION ...]\n");
        return 2;
    }
    std::vector<int> resolutions;
    for (int i = 2; i < argc; ++i) resolutions.push_back(std::atoi(argv[i]));
    if (resolutions.empty()) resolutions = {96, 400};
    fabvdb::Progress progress;
    const fabvdb::Mesh input = fabvdb::io::read_mesh(FABVDB_SHARED_DATA "/meshes/" + std::string(argv[1]), progress);
    const std::vector<Point> points = samples(input);
    std::printf("%s: %zu triangles, %zu samples\n", argv[1], input.triangles.size(), points.size());
    for (int resolution : resolutions) {
        fabvdb::volume::RepairOptions options;
        options.distance.voxel_size = fabvdb::volume::voxel_size_for_resolution(input, resolution, argv[1]);
        const fabvdb::volume::RepairResult result = fabvdb::volume::repair(input, options, progress);
        const std::vector<Triangle3> triangles = fabvdb::test::cgal::triangles_of(result.mesh);
        Tree tree(triangles.begin(), triangles.end());
        tree.accelerate_distance_queries();
        std::vector<double> distance(points.size());
        tbb::parallel_for(tbb::blocked_range<size_t>(0, points.size()), [&](const tbb::blocked_range<size_t>& range) {
            for (size_t i = range.begin(); i != range.end(); ++i)
                distance[i] = std::sqrt(tree.squared_distance(points[i]));
        });
        const double voxel = options.distance.voxel_size;
        const size_t farthest = size_t(std::max_element(distance.begin(), distance.end()) - distance.begin());
        double sum = 0.0;
        size_t beyond = 0;
        for (double d : distance) {
            sum += d;
            beyond += d > voxel;
        }
        std::printf("resolution %d (voxel %.4g): max %.3f voxel, mean %.4f voxel, %zu samples beyond 1 voxel, "
                    "farthest at (%.4g, %.4g, %.4g)\n",
                    resolution, voxel, distance[farthest] / voxel, sum / double(points.size()) / voxel, beyond,
                    points[farthest].x(), points[farthest].y(), points[farthest].z());
    }
    return 0;
}
