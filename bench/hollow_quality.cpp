// bench_hollow_quality INPUT FIT_MM HOLLOWED: the quality figures of a
// hollowed mesh, measured independently of the hollowing code. The output's
// components are split by the sign of their volume (outer shells positive,
// cavity shells negative); the wall is the CGAL AABB distance from samples of
// every cavity triangle (corners, edge midpoints, centroid) to the outer
// triangles; the outer deviation is the distance from the output's outer
// vertices to the input scaled like `fabvdb --fit FIT_MM`. Prints one line:
// wall_min wall_median outer_deviation_max outer_deviation_mean (mm).
// bench_hollow_quality --scaled INPUT FIT_MM OUT [SUBDIVISIONS] writes the
// input scaled that way instead (one file both slicers read), its triangles
// split in four SUBDIVISIONS times (default 0; the surface does not move).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numeric>
#include <string>

#include "core/error.h"
#include "io/mesh_io.h"
#include "subdivided.h"
#include "support/cgal_mesh.h"

namespace {

using fabvdb::test::cgal::Point;
using fabvdb::test::cgal::point;
using fabvdb::test::cgal::Tree;
using fabvdb::test::cgal::triangle;
using fabvdb::test::cgal::Triangle3;

//! Scales `mesh` like `fabvdb --fit fit_mm`: its longest side becomes fit_mm.
void fit(fabvdb::Mesh& mesh, double fit_mm) {
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
    for (const auto& p : mesh.vertices)
        for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
    const double scale = fit_mm / std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
    for (auto& p : mesh.vertices)
        for (double& x : p) x *= scale;
}

}  // namespace

int main(int argc, char** argv) {
    const bool scaled_copy = (argc == 5 || argc == 6) && std::string(argv[1]) == "--scaled";
    if (argc != 4 && !scaled_copy) {
        std::fprintf(stderr,
                     "usage: bench_hollow_quality INPUT FIT_MM HOLLOWED | --scaled INPUT FIT_MM OUT [SUBDIVISIONS]\n");
        return 1;
    }
    try {
        fabvdb::Progress progress;
        if (scaled_copy) {
            fabvdb::Mesh input = fabvdb::io::read_mesh(argv[2], progress);
            fit(input, std::atof(argv[3]));
            for (int k = argc == 6 ? std::atoi(argv[5]) : 0; k > 0; --k) input = fabvdb::bench::subdivided(input);
            fabvdb::io::write_mesh(input, argv[4]);
            return 0;
        }
        fabvdb::Mesh input = fabvdb::io::read_mesh(argv[1], progress);
        const fabvdb::Mesh output = fabvdb::io::read_mesh(argv[3], progress);
        fit(input, std::atof(argv[2]));

        // Components by union-find over shared vertices, signed volume each.
        std::vector<uint32_t> parent(output.vertices.size());
        std::iota(parent.begin(), parent.end(), 0u);
        const auto find = [&](uint32_t v) {
            while (parent[v] != v) v = parent[v] = parent[parent[v]];
            return v;
        };
        for (const auto& t : output.triangles) parent[find(t[0])] = find(t[1]), parent[find(t[1])] = find(t[2]);
        std::vector<double> volume(output.vertices.size(), 0.0);
        for (const auto& t : output.triangles) {
            const Triangle3 tri = triangle(output, t);
            volume[find(t[0])] += CGAL::volume(Point(0, 0, 0), tri[0], tri[1], tri[2]);
        }
        std::vector<Triangle3> outer, cavity;
        std::vector<uint32_t> outer_vertices;
        for (const auto& t : output.triangles) {
            const bool is_outer = volume[find(t[0])] > 0;
            (is_outer ? outer : cavity).push_back(triangle(output, t));
            if (is_outer) outer_vertices.insert(outer_vertices.end(), t.begin(), t.end());
        }
        Tree outer_tree(outer.begin(), outer.end());
        outer_tree.accelerate_distance_queries();
        std::vector<double> wall;
        for (const Triangle3& t : cavity) {
            const Point samples[] = {t[0], t[1], t[2], CGAL::midpoint(t[0], t[1]), CGAL::midpoint(t[1], t[2]),
                                     CGAL::midpoint(t[2], t[0]), CGAL::centroid(t[0], t[1], t[2])};
            for (const Point& p : samples) wall.push_back(std::sqrt(outer_tree.squared_distance(p)));
        }
        std::sort(wall.begin(), wall.end());

        const std::vector<Triangle3> input_triangles = fabvdb::test::cgal::triangles_of(input);
        Tree input_tree(input_triangles.begin(), input_triangles.end());
        input_tree.accelerate_distance_queries();
        std::sort(outer_vertices.begin(), outer_vertices.end());
        outer_vertices.erase(std::unique(outer_vertices.begin(), outer_vertices.end()), outer_vertices.end());
        double deviation_max = 0, deviation_sum = 0;
        for (uint32_t v : outer_vertices) {
            const double d = std::sqrt(input_tree.squared_distance(point(output.vertices[v])));
            deviation_max = std::max(deviation_max, d);
            deviation_sum += d;
        }
        std::printf("%.4f %.4f %.5f %.5f\n", wall.empty() ? 0.0 : wall.front(), wall.empty() ? 0.0 : wall[wall.size() / 2],
                    deviation_max, outer_vertices.empty() ? 0.0 : deviation_sum / double(outer_vertices.size()));
    } catch (const fabvdb::Error& e) {
        std::fprintf(stderr, "bench_hollow_quality: %s\n", e.what());
        return 2;
    }
    return 0;
}
