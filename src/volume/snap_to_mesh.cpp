//! Snapping an extracted surface onto its input (see snap_to_mesh.h).
#include "volume/snap_to_mesh.h"

#include <atomic>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

namespace fabvdb::volume {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Vector = Kernel::Vector_3;
using Triangle3 = Kernel::Triangle_3;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, std::vector<Triangle3>::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
using Box = CGAL::Box_intersection_d::Box_with_handle_d<double, 3, size_t, CGAL::Box_intersection_d::ID_EXPLICIT>;

// The input facing the surface's way: |cos| of the angle between normals.
constexpr double min_facing = 0.5;
// A moved triangle keeps its orientation (cos of the turn) and some area.
constexpr double min_turn = 0.2;
constexpr double min_area_ratio = 0.05;

Point point(const Vec3& v) { return Point(v[0], v[1], v[2]); }

Vector normal(const Mesh& mesh, const Triangle& t) {
    return CGAL::cross_product(point(mesh.vertices[t[1]]) - point(mesh.vertices[t[0]]),
                               point(mesh.vertices[t[2]]) - point(mesh.vertices[t[0]]));
}

bool share_vertex(const Triangle& a, const Triangle& b) {
    for (uint32_t u : a)
        for (uint32_t v : b)
            if (u == v) return true;
    return false;
}

// Reverts every moved vertex of the triangles marked bad; returns how many
// vertices went back.
size_t revert(Mesh& surface, const Mesh& original, const std::vector<Triangle>& triangles,
              const std::vector<char>& bad, std::vector<char>& moved) {
    size_t reverted = 0;
    for (size_t t = 0; t < triangles.size(); ++t) {
        if (!bad[t]) continue;
        for (uint32_t v : triangles[t])
            if (moved[v]) {
                moved[v] = 0;
                surface.vertices[v] = original.vertices[v];
                ++reverted;
            }
    }
    return reverted;
}

}  // namespace

uint64_t snap_to_mesh(Mesh& surface, const Mesh& input, double max_distance, Progress& progress) {
    progress.stage("snap");
    std::vector<Triangle3> input_triangles;
    input_triangles.reserve(input.triangles.size());
    for (const Triangle& t : input.triangles) {
        Triangle3 triangle(point(input.vertices[t[0]]), point(input.vertices[t[1]]), point(input.vertices[t[2]]));
        if (!triangle.is_degenerate()) input_triangles.push_back(triangle);
    }
    if (input_triangles.empty() || surface.triangles.empty()) return 0;
    Tree tree(input_triangles.begin(), input_triangles.end());
    tree.accelerate_distance_queries();
    progress.update(0.2);
    progress.check();

    std::vector<Vector> vertex_normal(surface.vertices.size(), Vector(0, 0, 0));
    for (const Triangle& t : surface.triangles) {
        const Vector n = normal(surface, t);
        for (uint32_t v : t) vertex_normal[v] = vertex_normal[v] + n;
    }
    const Mesh original = surface;
    std::vector<char> moved(surface.vertices.size(), 0);
    const double max_squared = max_distance * max_distance;
    tbb::parallel_for(tbb::blocked_range<size_t>(0, surface.vertices.size(), 4096),
                      [&](const tbb::blocked_range<size_t>& range) {
                          if (progress.cancelled()) return;
                          for (size_t v = range.begin(); v != range.end(); ++v) {
                              const Point p = point(original.vertices[v]);
                              const auto [closest, primitive] = tree.closest_point_and_primitive(p);
                              if (CGAL::squared_distance(p, closest) > max_squared) continue;
                              const Vector n_input = primitive->supporting_plane().orthogonal_vector();
                              const Vector& n_surface = vertex_normal[v];
                              const double length = std::sqrt(n_input.squared_length() * n_surface.squared_length());
                              if (!(length > 0.0) || std::abs(n_input * n_surface) < min_facing * length) continue;
                              surface.vertices[v] = {closest.x(), closest.y(), closest.z()};
                              moved[v] = 1;
                          }
                      });
    progress.check();
    progress.update(0.6);

    // Undo moves that flip or squash a triangle or make it cross another one
    // (exact predicates), until no move does.
    std::vector<char> bad(surface.triangles.size(), 0);
    for (bool changed = true; changed;) {
        progress.check();
        for (size_t t = 0; t < surface.triangles.size(); ++t) {
            const Triangle& tri = surface.triangles[t];
            bad[t] = 0;
            if (!moved[tri[0]] && !moved[tri[1]] && !moved[tri[2]]) continue;
            const Vector before = normal(original, tri), after = normal(surface, tri);
            const double b = before.squared_length(), a = after.squared_length();
            bad[t] = a < min_area_ratio * min_area_ratio * b || after * before < min_turn * std::sqrt(a * b);
        }
        if (revert(surface, original, surface.triangles, bad, moved) > 0) continue;

        std::vector<Box> moved_boxes, all_boxes;
        all_boxes.reserve(surface.triangles.size());
        for (size_t t = 0; t < surface.triangles.size(); ++t) {
            const Triangle& tri = surface.triangles[t];
            const Triangle3 triangle(point(surface.vertices[tri[0]]), point(surface.vertices[tri[1]]),
                                     point(surface.vertices[tri[2]]));
            all_boxes.emplace_back(triangle.bbox(), t);
            if (moved[tri[0]] || moved[tri[1]] || moved[tri[2]]) moved_boxes.emplace_back(triangle.bbox(), t);
        }
        const auto test = [&](const Box& a, const Box& b) {
            const size_t i = a.handle(), j = b.handle();
            const Triangle &ti = surface.triangles[i], &tj = surface.triangles[j];
            if (i == j || share_vertex(ti, tj)) return;
            const Triangle3 first(point(surface.vertices[ti[0]]), point(surface.vertices[ti[1]]),
                                  point(surface.vertices[ti[2]]));
            const Triangle3 second(point(surface.vertices[tj[0]]), point(surface.vertices[tj[1]]),
                                   point(surface.vertices[tj[2]]));
            if (CGAL::do_intersect(first, second)) bad[i] = bad[j] = 1;
        };
        CGAL::box_intersection_d(moved_boxes.begin(), moved_boxes.end(), all_boxes.begin(), all_boxes.end(), test);
        changed = revert(surface, original, surface.triangles, bad, moved) > 0;
    }
    progress.update(1.0);
    uint64_t count = 0;
    for (char m : moved) count += m;
    return count;
}

}  // namespace fabvdb::volume
