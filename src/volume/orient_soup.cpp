//! Consistent, outward orientation of a triangle soup (see orient_soup.h).
#include "volume/orient_soup.h"

#include <algorithm>
#include <array>
#include <numeric>
#include <utility>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>

#include "core/disjoint_sets.h"
#include "volume/winding_number.h"

namespace fabvdb::volume {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;

// A triangle's point indices in increasing order.
Triangle sorted_corners(const Triangle& t) {
    Triangle sorted = t;
    std::sort(sorted.begin(), sorted.end());
    return sorted;
}

// The triangles CGAL's repair_polygon_soup would keep, as fixed-size
// polygons, with coincident points merged: each triangle's corners are
// distinct and no two triangles have the same corners (of duplicates the
// first is kept). Done by sorting, which on a 1.8M-triangle scan is several
// times faster than CGAL's std::map of points and its vector per polygon.
// Polygons stay in input order.
std::vector<std::array<std::size_t, 3>> merged_soup(const Mesh& mesh) {
    std::vector<uint32_t> order(mesh.vertices.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(),
              [&](uint32_t a, uint32_t b) { return mesh.vertices[a] < mesh.vertices[b]; });
    std::vector<uint32_t> merged(mesh.vertices.size());
    for (size_t i = 0; i < order.size(); ++i) {
        const bool repeat = i > 0 && mesh.vertices[order[i]] == mesh.vertices[order[i - 1]];
        merged[order[i]] = repeat ? merged[order[i - 1]] : order[i];
    }
    std::vector<std::pair<Triangle, uint32_t>> keyed;  // (sorted corners, input triangle)
    keyed.reserve(mesh.triangles.size());
    for (uint32_t i = 0; i < mesh.triangles.size(); ++i) {
        const Triangle& t = mesh.triangles[i];
        const Triangle corners = sorted_corners({merged[t[0]], merged[t[1]], merged[t[2]]});
        if (corners[0] != corners[1] && corners[1] != corners[2]) keyed.emplace_back(corners, i);
    }
    std::sort(keyed.begin(), keyed.end());
    std::vector<uint32_t> source;
    for (size_t i = 0; i < keyed.size(); ++i)
        if (i == 0 || keyed[i].first != keyed[i - 1].first) source.push_back(keyed[i].second);
    std::sort(source.begin(), source.end());
    std::vector<std::array<std::size_t, 3>> soup;
    soup.reserve(source.size());
    for (uint32_t i : source) {
        const Triangle& t = mesh.triangles[i];
        soup.push_back({merged[t[0]], merged[t[1]], merged[t[2]]});
    }
    return soup;
}

// Records which polygons CGAL's orientation reversed.
struct ReversalVisitor : CGAL::Polygon_mesh_processing::Default_orientation_visitor {
    std::vector<char>* reversed;
    void polygon_orientation_reversed(std::size_t polygon) { (*reversed)[polygon] ^= 1; }
};

// A piece that the input oriented inward (by the area of its triangles whose
// input order disagrees with the outward one: `as_given`; for an input
// stored inside out as a whole, agrees) and that lies
// wholly inside the solid of the outward pieces (their winding number at
// each of its points) is the wall of a cavity: it is turned back inward.
// Other pieces stay outward.
void keep_cavities_inward(Mesh& oriented, const std::vector<char>& as_given, DisjointSets& pieces) {
    // Per piece (indexed by its root vertex): area whose input order agrees
    // with the outward one, and total area. An input stored inside out as a
    // whole (most of its area inward: its voids' walls then face out) is
    // read turned round.
    std::vector<double> agreeing(oriented.vertices.size(), 0.0), total(oriented.vertices.size(), 0.0);
    double all_agreeing = 0.0, all = 0.0;
    for (size_t i = 0; i < oriented.triangles.size(); ++i) {
        const double area = triangle_area(oriented, oriented.triangles[i]);
        all += area;
        if (as_given[i]) all_agreeing += area;
    }
    const bool turned = all_agreeing < 0.5 * all;
    for (size_t i = 0; i < oriented.triangles.size(); ++i) {
        const Triangle& t = oriented.triangles[i];
        const uint32_t root = pieces.find(t[0]);
        const double area = triangle_area(oriented, t);
        total[root] += area;
        if (bool(as_given[i]) != turned) agreeing[root] += area;
    }
    std::vector<char> cavity(oriented.vertices.size(), 0);
    bool any_inward = false;
    for (uint32_t root = 0; root < total.size(); ++root)
        if (total[root] > 0.0 && agreeing[root] < 0.5 * total[root]) cavity[root] = any_inward = true;
    if (!any_inward) return;
    Mesh outward;
    outward.vertices = oriented.vertices;
    for (const Triangle& t : oriented.triangles)
        if (!cavity[pieces.find(t[0])]) outward.triangles.push_back(t);
    if (outward.triangles.empty()) return;

    // A cavity lies wholly inside: every one of its points (a piece that only
    // overlaps the solid is an inverted solid of its own, to be united).
    const WindingNumber solid(outward);
    for (uint32_t v = 0; v < oriented.vertices.size(); ++v) {
        const uint32_t root = pieces.find(v);
        if (cavity[root] && solid(oriented.vertices[v]) < 0.5) cavity[root] = false;
    }
    for (Triangle& t : oriented.triangles)
        if (cavity[pieces.find(t[0])]) std::swap(t[1], t[2]);
}

}  // namespace

Mesh orient_soup(const Mesh& mesh, Progress& progress) {
    progress.stage("orient");
    std::vector<Point> points;
    points.reserve(mesh.vertices.size());
    for (const Vec3& v : mesh.vertices) points.emplace_back(v[0], v[1], v[2]);
    std::vector<std::array<std::size_t, 3>> soup = merged_soup(mesh);
    namespace PMP = CGAL::Polygon_mesh_processing;
    PMP::remove_isolated_points_in_polygon_soup(points, soup);
    progress.update(0.4);
    std::vector<char> reversed(soup.size(), 0);
    ReversalVisitor visitor;
    visitor.reversed = &reversed;
    PMP::orient_polygon_soup(points, soup, CGAL::parameters::visitor(visitor));
    progress.update(0.8);

    Mesh oriented;
    oriented.vertices.reserve(points.size());
    for (const Point& p : points) oriented.vertices.push_back({p.x(), p.y(), p.z()});
    oriented.triangles.reserve(soup.size());
    for (const auto& polygon : soup)
        oriented.triangles.push_back({uint32_t(polygon[0]), uint32_t(polygon[1]), uint32_t(polygon[2])});

    // Connected pieces by shared vertices, then each piece's signed volume
    // about its own centroid (translation-invariant for open pieces too).
    DisjointSets pieces(oriented.vertices.size());
    for (const Triangle& t : oriented.triangles) {
        pieces.unite(t[0], t[1]);
        pieces.unite(t[0], t[2]);
    }
    std::vector<std::array<double, 4>> centroid(oriented.vertices.size(), {0, 0, 0, 0});
    for (const Triangle& t : oriented.triangles) {
        auto& c = centroid[pieces.find(t[0])];
        for (uint32_t v : t)
            for (int k = 0; k < 3; ++k) c[k] += oriented.vertices[v][k];
        c[3] += 3.0;
    }
    std::vector<double> volume(oriented.vertices.size(), 0.0);
    for (const Triangle& t : oriented.triangles) {
        const uint32_t root = pieces.find(t[0]);
        const auto& c = centroid[root];
        Vec3 p[3];
        for (int i = 0; i < 3; ++i)
            for (int k = 0; k < 3; ++k) p[i][k] = oriented.vertices[t[i]][k] - c[k] / c[3];
        volume[root] += six_signed_tetrahedron_volume(p[0], p[1], p[2]);
    }
    // Whether each triangle now lists its input corners in their input order.
    std::vector<char> as_given(oriented.triangles.size());
    for (size_t i = 0; i < oriented.triangles.size(); ++i) {
        Triangle& t = oriented.triangles[i];
        const bool flip = volume[pieces.find(t[0])] < 0.0;
        if (flip) std::swap(t[1], t[2]);
        as_given[i] = !(reversed[i] ^ flip);
    }
    progress.update(0.9);
    keep_cavities_inward(oriented, as_given, pieces);
    progress.update(1.0);
    return oriented;
}

}  // namespace fabvdb::volume
