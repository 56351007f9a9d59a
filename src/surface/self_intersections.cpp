//! Self-intersections: the triangles whose bounding boxes overlap are found
//! by the broad phase the crossing test uses (triangle_box_pairs.h; closed
//! boxes, so touching counts); pairs that share a welded vertex are dropped;
//! the rest are tested with CGAL's exact do_intersect in parallel batches,
//! between the progress updates.
#include "surface/self_intersections.h"

#include <algorithm>
#include <variant>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "surface/weld_vertices.h"
#include "volume/triangle_box_pairs.h"

namespace fabvdb::surface {
namespace {

using Kernel = CGAL::Epick;
using Point = Kernel::Point_3;
using Shape = std::variant<Kernel::Triangle_3, Kernel::Segment_3, Point>;

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
    tbb::parallel_for(size_t(0), count, [&](size_t t) {
        Point p[3];
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = mesh.triangles[t][k];
            welded[t][k] = position[v];
            p[k] = Point(mesh.vertices[v][0], mesh.vertices[v][1], mesh.vertices[v][2]);
        }
        shapes[t] = corner_hull(p[0], p[1], p[2]);
    });
    progress.check();

    tbb::enumerable_thread_specific<std::vector<std::pair<uint32_t, uint32_t>>> found;
    volume::for_each_overlapping_box_pair(mesh, [&](uint32_t a, uint32_t b) {
        const uint32_t i = std::min(a, b), j = std::max(a, b);
        if (!share_position(welded[i], welded[j])) found.local().push_back({i, j});
    });
    std::vector<std::pair<uint32_t, uint32_t>> candidates;
    for (const auto& some : found) candidates.insert(candidates.end(), some.begin(), some.end());
    std::sort(candidates.begin(), candidates.end());
    progress.check();

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
