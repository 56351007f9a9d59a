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

#include "volume/winding_number.h"

namespace fabvdb::volume {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;

uint32_t find_root(std::vector<uint32_t>& parent, uint32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
}

// Point indices in increasing order of position (lexicographic).
std::vector<uint32_t> sorted_by_position(const std::vector<Vec3>& points) {
    std::vector<uint32_t> order(points.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return points[a] < points[b]; });
    return order;
}

// A triangle's (merged) point indices in increasing order.
Triangle sorted_corners(const Triangle& t) {
    Triangle sorted = t;
    std::sort(sorted.begin(), sorted.end());
    return sorted;
}

// Whether t and u list the same corners in the same cyclic order.
bool same_cycle(const Triangle& t, const Triangle& u) {
    for (int r = 0; r < 3; ++r)
        if (t[0] == u[r] && t[1] == u[(r + 1) % 3] && t[2] == u[(r + 2) % 3]) return true;
    return false;
}

// A piece that the input oriented inward (by the area of its triangles whose
// input order disagrees with the outward one) and that lies wholly inside the
// solid of the outward pieces (their winding number at each of its points) is
// the wall of a cavity: it is turned back inward. Other pieces stay outward.
void keep_cavities_inward(const Mesh& input, Mesh& oriented, std::vector<uint32_t>& parent) {
    // Each input triangle in the merged points' indices, by sorted corners
    // (sorted arrays and binary search: a million-triangle scan's hash
    // tables cost more than the orientation itself).
    const std::vector<uint32_t> by_position = sorted_by_position(oriented.vertices);
    const auto merged = [&](const Vec3& p) -> int64_t {
        const auto it = std::lower_bound(by_position.begin(), by_position.end(), p,
                                         [&](uint32_t v, const Vec3& q) { return oriented.vertices[v] < q; });
        return it != by_position.end() && oriented.vertices[*it] == p ? int64_t(*it) : -1;
    };
    std::vector<std::pair<Triangle, Triangle>> input_order;  // (sorted corners, input order)
    input_order.reserve(input.triangles.size());
    for (const Triangle& t : input.triangles) {
        Triangle u;
        bool found = true;
        for (int k = 0; k < 3 && found; ++k) {
            const int64_t m = merged(input.vertices[t[k]]);
            found = m >= 0;
            u[k] = uint32_t(std::max<int64_t>(m, 0));
        }
        if (found) input_order.emplace_back(sorted_corners(u), u);
    }
    std::sort(input_order.begin(), input_order.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    const auto input_cycle = [&](const Triangle& t) -> const Triangle* {
        const Triangle key = sorted_corners(t);
        const auto it = std::lower_bound(input_order.begin(), input_order.end(), key,
                                         [](const auto& entry, const Triangle& k) { return entry.first < k; });
        return it != input_order.end() && it->first == key ? &it->second : nullptr;
    };

    // Per piece (indexed by its root vertex): area whose input order agrees
    // with the outward one, and total area.
    std::vector<double> agreeing(oriented.vertices.size(), 0.0), total(oriented.vertices.size(), 0.0);
    for (const Triangle& t : oriented.triangles) {
        const uint32_t root = find_root(parent, t[0]);
        const double area = triangle_area(oriented, t);
        total[root] += area;
        const Triangle* given = input_cycle(t);
        if (given && same_cycle(t, *given)) agreeing[root] += area;
    }
    std::vector<char> cavity(oriented.vertices.size(), 0);
    bool any_inward = false;
    for (uint32_t root = 0; root < total.size(); ++root)
        if (total[root] > 0.0 && agreeing[root] < 0.5 * total[root]) cavity[root] = any_inward = true;
    if (!any_inward) return;
    Mesh outward;
    outward.vertices = oriented.vertices;
    for (const Triangle& t : oriented.triangles)
        if (!cavity[find_root(parent, t[0])]) outward.triangles.push_back(t);
    if (outward.triangles.empty()) return;

    // A cavity lies wholly inside: every one of its points (a piece that only
    // overlaps the solid is an inverted solid of its own, to be united).
    const WindingNumber solid(outward);
    for (uint32_t v = 0; v < oriented.vertices.size(); ++v) {
        const uint32_t root = find_root(parent, v);
        if (cavity[root] && solid(oriented.vertices[v]) < 0.5) cavity[root] = false;
    }
    for (Triangle& t : oriented.triangles)
        if (cavity[find_root(parent, t[0])]) std::swap(t[1], t[2]);
}

}  // namespace

Mesh orient_soup(const Mesh& mesh, Progress& progress) {
    progress.stage("orient");
    std::vector<Point> points;
    points.reserve(mesh.vertices.size());
    for (const Vec3& v : mesh.vertices) points.emplace_back(v[0], v[1], v[2]);
    // CGAL's repair_polygon_soup for triangles, on fixed-size polygons (a
    // vector per triangle costs a million allocations on a large scan), with
    // coincident points merged by sorting (its std::map took half of this
    // step's time on a 1.8M-triangle scan): its simplification and pinch
    // splitting both come down to dropping a triangle with a repeated corner
    // once coincident points are merged.
    std::vector<uint32_t> merged(mesh.vertices.size());
    const std::vector<uint32_t> by_position = sorted_by_position(mesh.vertices);
    for (size_t i = 0; i < by_position.size(); ++i) {
        const uint32_t v = by_position[i];
        const bool repeat = i > 0 && mesh.vertices[v] == mesh.vertices[by_position[i - 1]];
        merged[v] = repeat ? merged[by_position[i - 1]] : v;
    }
    std::vector<std::array<std::size_t, 3>> soup;
    soup.reserve(mesh.triangles.size());
    for (const Triangle& t : mesh.triangles) soup.push_back({merged[t[0]], merged[t[1]], merged[t[2]]});
    namespace PMP = CGAL::Polygon_mesh_processing;
    soup.erase(std::remove_if(soup.begin(), soup.end(),
                              [](const auto& t) { return t[0] == t[1] || t[1] == t[2] || t[2] == t[0]; }),
               soup.end());
    PMP::merge_duplicate_polygons_in_polygon_soup(points, soup);
    PMP::remove_isolated_points_in_polygon_soup(points, soup);
    progress.update(0.4);
    PMP::orient_polygon_soup(points, soup);
    progress.update(0.8);

    Mesh oriented;
    oriented.vertices.reserve(points.size());
    for (const Point& p : points) oriented.vertices.push_back({p.x(), p.y(), p.z()});
    oriented.triangles.reserve(soup.size());
    for (const auto& polygon : soup)
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
        Vec3 p[3];
        for (int i = 0; i < 3; ++i)
            for (int k = 0; k < 3; ++k) p[i][k] = oriented.vertices[t[i]][k] - c[k] / c[3];
        volume[root] += six_signed_tetrahedron_volume(p[0], p[1], p[2]);
    }
    for (Triangle& t : oriented.triangles)
        if (volume[find_root(parent, t[0])] < 0.0) std::swap(t[1], t[2]);
    progress.update(0.9);
    keep_cavities_inward(mesh, oriented, parent);
    progress.update(1.0);
    return oriented;
}

}  // namespace fabvdb::volume
