//! Self-intersections: bounding boxes of all triangles are intersected with
//! CGAL's box_self_intersection_d (closed boxes, so touching counts); pairs that
//! share a welded vertex are dropped; the rest are tested with CGAL's exact
//! do_intersect in parallel batches, between the progress updates.
#include "surface/self_intersections.h"

#include <algorithm>
#include <variant>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>
#include <tbb/parallel_for.h>

#include "surface/weld_vertices.h"

namespace fabvdb::surface {
namespace {

using Kernel = CGAL::Epick;
using Point = Kernel::Point_3;
using Shape = std::variant<Kernel::Triangle_3, Kernel::Segment_3, Point>;
// Boxes are identified by the address of their shape (thread-safe, unlike CGAL's id counter).
using Box = CGAL::Box_intersection_d::Box_with_handle_d<double, 3, const Shape*>;

//! The point set of the triangle's corners: a triangle, or the segment or point
//! it collapses to (CGAL's triangle tests require non-degenerate triangles).
Shape corner_hull(const Point& a, const Point& b, const Point& c) {
    if (!CGAL::collinear(a, b, c)) return Kernel::Triangle_3(a, b, c);
    // Collinear points are ordered along their line as they are lexicographically.
    const Point lo = std::min({a, b, c}), hi = std::max({a, b, c});
    if (lo == hi) return lo;
    return Kernel::Segment_3(lo, hi);
}

bool share_position(const Triangle& a, const Triangle& b) {
    for (uint32_t u : a)
        for (uint32_t v : b)
            if (u == v) return true;
    return false;
}

}  // namespace

std::vector<std::pair<uint32_t, uint32_t>> self_intersecting_pairs(const Mesh& mesh, Progress& progress) {
    progress.stage("self-intersections: candidate pairs");
    const std::vector<uint32_t> position = coincident_vertex_map(mesh);
    const size_t count = mesh.triangles.size();
    std::vector<Triangle> welded(count);
    std::vector<Shape> shapes(count);
    std::vector<Box> boxes;
    boxes.reserve(count);
    for (size_t t = 0; t < count; ++t) {
        Point p[3];
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = mesh.triangles[t][k];
            welded[t][k] = position[v];
            p[k] = Point(mesh.vertices[v][0], mesh.vertices[v][1], mesh.vertices[v][2]);
        }
        shapes[t] = corner_hull(p[0], p[1], p[2]);
        // Box corners are the coordinates themselves (no rounding): the broad phase misses nothing.
        boxes.emplace_back(p[0].bbox() + p[1].bbox() + p[2].bbox(), &shapes[t]);
    }

    std::vector<std::pair<uint32_t, uint32_t>> candidates;
    size_t reported = 0;
    CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& x, const Box& y) {
        if ((++reported & 0xffff) == 0) progress.check();
        const auto index_x = uint32_t(x.handle() - shapes.data()), index_y = uint32_t(y.handle() - shapes.data());
        const uint32_t i = std::min(index_x, index_y), j = std::max(index_x, index_y);
        if (!share_position(welded[i], welded[j])) candidates.push_back({i, j});
    });
    std::sort(candidates.begin(), candidates.end());

    progress.stage("self-intersections: exact tests");
    std::vector<char> intersecting(candidates.size(), 0);
    const size_t batch = std::max<size_t>(1024, candidates.size() / 100);
    for (size_t start = 0; start < candidates.size(); start += batch) {
        const size_t end = std::min(candidates.size(), start + batch);
        tbb::parallel_for(tbb::blocked_range<size_t>(start, end), [&](const tbb::blocked_range<size_t>& range) {
            if (progress.cancelled()) return;
            for (size_t c = range.begin(); c != range.end(); ++c)
                intersecting[c] = std::visit([](const auto& a, const auto& b) { return CGAL::do_intersect(a, b); },
                                             shapes[candidates[c].first], shapes[candidates[c].second]);
        });
        progress.update(double(end) / double(candidates.size()));
    }
    progress.check();

    std::vector<std::pair<uint32_t, uint32_t>> pairs;
    for (size_t c = 0; c < candidates.size(); ++c)
        if (intersecting[c]) pairs.push_back(candidates[c]);
    return pairs;
}

}  // namespace fabvdb::surface
