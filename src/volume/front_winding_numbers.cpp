//! Winding numbers in front of patches (see front_winding_numbers.h).
//!
//! The winding number w is constant off the surface between the cut curves
//! and grows by one across a triangle against its normal, so it is the same
//! just in front of every triangle of a patch. It is counted along a ray
//! from the centre of one of the patch's triangles: +1 for every triangle
//! the ray leaves through (along its normal), −1 for every one it enters
//! through, and −1 more when the ray starts behind its own triangle.
#include "volume/front_winding_numbers.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "core/vec3_ops.h"

namespace fabvdb::volume {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;

Point point(const Vec3& p) { return Point(p[0], p[1], p[2]); }

//! The rays' direction (generic: no two components alike, none simple) and
//! two unit vectors across it: rays and triangles are compared seen along it.
struct View {
    Vec3 along, u, v;
    View() {
        const Vec3 direction = {0.5390457218399, 0.6928203230276, 0.4789995612345};
        const double length = std::sqrt(dot(direction, direction));
        along = {direction[0] / length, direction[1] / length, direction[2] / length};
        const double across = std::hypot(along[0], along[1]);
        u = {along[1] / across, -along[0] / across, 0.0};
        v = cross(along, u);
    }
};

//! A ray from the centre of one triangle of a patch to beyond the mesh.
struct Ray {
    uint32_t patch = 0, triangle = 0;
    Vec3 origin{}, far{};
    double u = 0.0, v = 0.0, depth = 0.0;  //!< the origin seen along the view
};

//! The rays' counts, from one pass over the triangles: per ray the signed
//! number of triangles it leaves through (decisive unless `undecided`).
struct RayCounts {
    std::vector<int> count;
    std::vector<char> undecided;
};

RayCounts cast(const Mesh& mesh, const View& view, const std::vector<Ray>& rays, double tolerance,
               Progress& progress) {
    std::vector<uint32_t> by_u(rays.size());
    std::iota(by_u.begin(), by_u.end(), 0u);
    std::sort(by_u.begin(), by_u.end(), [&](uint32_t a, uint32_t b) { return rays[a].u < rays[b].u; });
    std::vector<double> sorted_u(rays.size());
    for (size_t r = 0; r < rays.size(); ++r) sorted_u[r] = rays[by_u[r]].u;

    struct Local {
        std::vector<int> count;
        std::vector<char> undecided;
    };
    tbb::enumerable_thread_specific<Local> locals([&] {
        return Local{std::vector<int>(rays.size(), 0), std::vector<char>(rays.size(), 0)};
    });
    tbb::parallel_for(tbb::blocked_range<size_t>(0, mesh.triangles.size(), 4096),
                      [&](const tbb::blocked_range<size_t>& range) {
        if (progress.cancelled()) return;
        Local& local = locals.local();
        for (size_t t = range.begin(); t != range.end(); ++t) {
            const Triangle& tri = mesh.triangles[t];
            double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
            for (uint32_t corner : tri) {
                const Vec3& p = mesh.vertices[corner];
                const double along[3] = {dot(view.u, p), dot(view.v, p), dot(view.along, p)};
                for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], along[k]), hi[k] = std::max(hi[k], along[k]);
            }
            auto r = std::lower_bound(sorted_u.begin(), sorted_u.end(), lo[0] - tolerance) - sorted_u.begin();
            for (; r < ptrdiff_t(rays.size()) && sorted_u[r] <= hi[0] + tolerance; ++r) {
                const uint32_t index = by_u[r];
                const Ray& ray = rays[index];
                if (ray.triangle == t || ray.v < lo[1] - tolerance || ray.v > hi[1] + tolerance ||
                    hi[2] < ray.depth - tolerance)
                    continue;
                const Point a = point(mesh.vertices[tri[0]]), b = point(mesh.vertices[tri[1]]),
                            c = point(mesh.vertices[tri[2]]), o = point(ray.origin), q = point(ray.far);
                const CGAL::Orientation side_origin = CGAL::orientation(a, b, c, o);
                const CGAL::Orientation side_far = CGAL::orientation(a, b, c, q);
                if (side_origin == side_far && side_origin != CGAL::COPLANAR) continue;
                const CGAL::Orientation around[3] = {CGAL::orientation(o, q, a, b), CGAL::orientation(o, q, b, c),
                                                     CGAL::orientation(o, q, c, a)};
                const bool positive = std::count(around, around + 3, CGAL::POSITIVE) > 0;
                const bool negative = std::count(around, around + 3, CGAL::NEGATIVE) > 0;
                if (positive && negative) continue;  // the line passes beside the triangle
                // Through an edge or a vertex, or the triangle meets the ray's
                // start or end: not decisive.
                if (!(positive || negative) || std::count(around, around + 3, CGAL::COPLANAR) > 0 ||
                    side_origin == CGAL::COPLANAR || side_far == CGAL::COPLANAR) {
                    local.undecided[index] = 1;
                    continue;
                }
                // A crossing right at the start: a triangle overlapping the
                // ray's own, up to the rounding of its centre.
                const Vec3 normal = triangle_normal(mesh, tri);
                const Vec3& corner = mesh.vertices[tri[0]];
                const double to_plane = dot(normal, corner - ray.origin) / norm(normal);
                if (std::abs(to_plane) <= tolerance) {
                    local.undecided[index] = 1;
                    continue;
                }
                local.count[index] += side_far == CGAL::POSITIVE ? 1 : -1;
            }
        }
    });
    progress.check();
    RayCounts counts{std::vector<int>(rays.size(), 0), std::vector<char>(rays.size(), 0)};
    for (const Local& local : locals)
        for (size_t r = 0; r < rays.size(); ++r) {
            counts.count[r] += local.count[r];
            counts.undecided[r] |= local.undecided[r];
        }
    return counts;
}

}  // namespace

std::optional<std::vector<int>> front_winding_numbers(const Mesh& mesh, const std::vector<uint32_t>& patch,
                                                      size_t patch_count, Progress& progress) {
    constexpr int attempts = 4;
    const View view;
    const BoundingBox box = bounding_box(mesh);
    const double diagonal = box.diagonal();
    const double tolerance = 1e-9 * diagonal;
    // Each patch's candidate triangles, those facing the direction most first.
    std::vector<std::vector<std::pair<double, uint32_t>>> candidates(patch_count);
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const Vec3 n = triangle_normal(mesh, mesh.triangles[t]);
        auto& list = candidates[patch[t]];
        list.emplace_back(std::abs(dot(n, view.along)), uint32_t(t));
        if (list.size() > size_t(attempts)) {
            std::nth_element(list.begin(), list.begin() + attempts, list.end(), std::greater<>());
            list.resize(attempts);
        }
    }
    for (auto& list : candidates) std::sort(list.begin(), list.end(), std::greater<>());

    std::vector<int> front(patch_count, 0);
    std::vector<char> known(patch_count, 0);
    for (int attempt = 0; attempt < attempts; ++attempt) {
        std::vector<Ray> rays;
        for (uint32_t p = 0; p < patch_count; ++p) {
            if (known[p] || size_t(attempt) >= candidates[p].size() || candidates[p][attempt].first <= 0.0) continue;
            Ray ray;
            ray.patch = p;
            ray.triangle = candidates[p][attempt].second;
            const Triangle& t = mesh.triangles[ray.triangle];
            for (int k = 0; k < 3; ++k)
                ray.origin[k] = (mesh.vertices[t[0]][k] + mesh.vertices[t[1]][k] + mesh.vertices[t[2]][k]) / 3.0;
            const double reach = 2.0 * diagonal + 1.0;
            for (int k = 0; k < 3; ++k) ray.far[k] = ray.origin[k] + reach * view.along[k];
            ray.u = dot(view.u, ray.origin);
            ray.v = dot(view.v, ray.origin);
            ray.depth = dot(view.along, ray.origin);
            rays.push_back(ray);
        }
        if (rays.empty()) break;
        const RayCounts counts = cast(mesh, view, rays, tolerance, progress);
        for (size_t r = 0; r < rays.size(); ++r) {
            if (counts.undecided[r]) continue;
            const Ray& ray = rays[r];
            const Triangle& t = mesh.triangles[ray.triangle];
            // Which side of its own triangle the ray runs into.
            const CGAL::Orientation start = CGAL::orientation(point(mesh.vertices[t[0]]), point(mesh.vertices[t[1]]),
                                                              point(mesh.vertices[t[2]]), point(ray.far));
            if (start == CGAL::COPLANAR) continue;
            front[ray.patch] = counts.count[r] - (start == CGAL::NEGATIVE ? 1 : 0);
            known[ray.patch] = 1;
        }
    }
    if (std::count(known.begin(), known.end(), 0) > 0) return std::nullopt;
    return front;
}

}  // namespace fabvdb::volume
