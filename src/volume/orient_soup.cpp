//! Consistent, outward orientation of a triangle soup (see orient_soup.h).
#include "volume/orient_soup.h"

#include <numeric>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>

namespace fabvdb::volume {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;

uint32_t find_root(std::vector<uint32_t>& parent, uint32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
}

}  // namespace

Mesh orient_soup(const Mesh& mesh, Progress& progress) {
    progress.stage("orient");
    std::vector<Point> points;
    points.reserve(mesh.vertices.size());
    for (const Vec3& v : mesh.vertices) points.emplace_back(v[0], v[1], v[2]);
    std::vector<std::vector<std::size_t>> soup;
    soup.reserve(mesh.triangles.size());
    for (const Triangle& t : mesh.triangles) soup.push_back({t[0], t[1], t[2]});
    namespace PMP = CGAL::Polygon_mesh_processing;
    PMP::repair_polygon_soup(points, soup);
    progress.update(0.4);
    PMP::orient_polygon_soup(points, soup);
    progress.update(0.8);

    Mesh oriented;
    oriented.vertices.reserve(points.size());
    for (const Point& p : points) oriented.vertices.push_back({p.x(), p.y(), p.z()});
    oriented.triangles.reserve(soup.size());
    for (const auto& polygon : soup)
        if (polygon.size() == 3)
            oriented.triangles.push_back({uint32_t(polygon[0]), uint32_t(polygon[1]), uint32_t(polygon[2])});

    // Connected pieces by shared vertices, then each piece's signed volume
    // about its own centroid (translation-invariant for open pieces too).
    std::vector<uint32_t> parent(oriented.vertices.size());
    std::iota(parent.begin(), parent.end(), 0u);
    for (const Triangle& t : oriented.triangles) {
        const uint32_t a = find_root(parent, t[0]);
        parent[find_root(parent, t[1])] = a;
        parent[find_root(parent, t[2])] = a;
    }
    std::vector<std::array<double, 4>> centroid(oriented.vertices.size(), {0, 0, 0, 0});
    for (const Triangle& t : oriented.triangles) {
        auto& c = centroid[find_root(parent, t[0])];
        for (uint32_t v : t)
            for (int k = 0; k < 3; ++k) c[k] += oriented.vertices[v][k];
        c[3] += 3.0;
    }
    std::vector<double> volume(oriented.vertices.size(), 0.0);
    for (const Triangle& t : oriented.triangles) {
        const uint32_t root = find_root(parent, t[0]);
        const auto& c = centroid[root];
        double p[3][3];
        for (int i = 0; i < 3; ++i)
            for (int k = 0; k < 3; ++k) p[i][k] = oriented.vertices[t[i]][k] - c[k] / c[3];
        volume[root] += p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1]) -
                        p[0][1] * (p[1][0] * p[2][2] - p[1][2] * p[2][0]) +
                        p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0]);
    }
    for (Triangle& t : oriented.triangles)
        if (volume[find_root(parent, t[0])] < 0.0) std::swap(t[1], t[2]);
    progress.update(1.0);
    return oriented;
}

}  // namespace fabvdb::volume
