//! Snapping an extracted surface onto its input (see snap_to_mesh.h).
#include "volume/snap_to_mesh.h"

#include <algorithm>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "core/float_coordinates.h"
#include "volume/crossing_pairs.h"
#include "volume/feature_targets.h"
#include "volume/nearest_triangle.h"

namespace fabvdb::volume {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Vector = Kernel::Vector_3;

// The input along the surface: |cos| of the angle between normals.
constexpr double min_facing = 0.5;
// A moved triangle keeps its orientation (cos of the turn) and some area.
constexpr double min_turn = 0.2;
constexpr double min_area_ratio = 0.05;
// Sharp edges and corners draw vertices from this many max_distances.
constexpr double feature_reach = 1.5;

Point point(const Vec3& v) { return Point(v[0], v[1], v[2]); }

Vector normal(const Mesh& mesh, const Triangle& t) {
    const Vec3 n = triangle_normal(mesh, t);
    return Vector(n[0], n[1], n[2]);
}

// Moves the moved corners of triangle t back, marking them in went_back;
// returns how many went back.
size_t revert(Mesh& surface, const Mesh& original, const Triangle& t, std::vector<char>& moved,
              std::vector<char>& went_back) {
    size_t reverted = 0;
    for (uint32_t v : t)
        if (moved[v]) {
            moved[v] = 0;
            went_back[v] = 1;
            surface.vertices[v] = original.vertices[v];
            ++reverted;
        }
    return reverted;
}

// Moves every vertex of the surface whose closest input point is within
// max_distance onto it when the input there faces the surface's way.
void move_onto_input(Mesh& surface, const Mesh& input, const openvdb::Int32Grid& closest_triangle,
                     double max_distance, const CentredFrame* float_frame, std::vector<char>& moved,
                     Progress& progress) {
    const auto stored = [float_frame](const Vec3& p) { return float_frame ? stored_position(p, *float_frame) : p; };
    const NearestTriangle nearest(input, closest_triangle);
    const std::vector<Vec3> vertex_normal = area_weighted_vertex_normals(surface);
    // The closest input point of each vertex and the unit normal there; a
    // vertex with no input triangle near it is its own closest point, with a
    // zero normal that faces nothing, so it stays.
    std::vector<Vec3> closest(surface.vertices.size()), input_normal(surface.vertices.size(), Vec3{0, 0, 0});
    tbb::parallel_for(tbb::blocked_range<size_t>(0, surface.vertices.size(), 4096),
                      [&](const tbb::blocked_range<size_t>& range) {
                          if (progress.cancelled()) return;
                          NearestTriangle::Query query(nearest);
                          for (size_t v = range.begin(); v != range.end(); ++v) {
                              const Vec3& p = surface.vertices[v];
                              const NearestTriangle::Result found = query(openvdb::Vec3d(p[0], p[1], p[2]));
                              if (!found.found()) {
                                  closest[v] = p;
                                  continue;
                              }
                              const Vec3 n = triangle_normal(input, input.triangles[found.triangle]);
                              const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
                              closest[v] = {found.point[0], found.point[1], found.point[2]};
                              if (length > 0.0) input_normal[v] = {n[0] / length, n[1] / length, n[2] / length};
                          }
                      });
    progress.check();
    const FeatureTargets features =
        feature_targets(surface, vertex_normal, input_normal, input, feature_reach * max_distance);
    progress.check();
    const double max_squared = max_distance * max_distance;
    for (size_t v = 0; v < surface.vertices.size(); ++v) {
        if (features.has_target[v]) {
            surface.vertices[v] = stored(features.target[v]);
            moved[v] = 1;
            continue;
        }
        if (CGAL::squared_distance(point(surface.vertices[v]), point(closest[v])) > max_squared) continue;
        const Vector n_input(input_normal[v][0], input_normal[v][1], input_normal[v][2]);
        const Vector n_surface(vertex_normal[v][0], vertex_normal[v][1], vertex_normal[v][2]);
        const double length = std::sqrt(n_surface.squared_length());
        if (!(length > 0.0) || std::abs(n_input * n_surface) < min_facing * length) continue;
        surface.vertices[v] = stored(closest[v]);
        moved[v] = 1;
    }
    progress.check();
}

}  // namespace

SnapResult snap_to_mesh(Mesh& surface, const Mesh& input, const openvdb::Int32Grid& closest_triangle,
                        double max_distance, const CentredFrame* float_frame, Progress& progress) {
    progress.stage("snap");
    SnapResult result;
    if (float_frame) {
        const std::vector<Vec3> computed = surface.vertices;
        for (Vec3& p : surface.vertices) p = stored_position(p, *float_frame);
        // Corners of a triangle that rounding flattens keep their computed
        // position; the writer's float rounding places them (float_rounding.h).
        for (const Triangle& t : surface.triangles)
            if (CGAL::collinear(point(surface.vertices[t[0]]), point(surface.vertices[t[1]]),
                                point(surface.vertices[t[2]])))
                for (uint32_t v : t) surface.vertices[v] = computed[v];
    }
    const Mesh original = surface;
    std::vector<char> moved(surface.vertices.size(), 0);
    move_onto_input(surface, input, closest_triangle, max_distance, float_frame, moved, progress);
    progress.update(0.6);

    // Undo moves that flip or squash a triangle, then moves that make two
    // triangles cross, until no move does. The first crossing test takes every
    // pair, later ones only the triangles whose corners went back since.
    const auto touches = [&](const Triangle& t, const std::vector<char>& marked) {
        return marked[t[0]] || marked[t[1]] || marked[t[2]];
    };
    std::vector<char> went_back(surface.vertices.size(), 0);
    std::vector<char> candidates;  // empty: every triangle
    for (bool first = true;; first = false) {
        progress.check();
        for (size_t reverted = 1; reverted > 0;) {
            reverted = 0;
            for (const Triangle& t : surface.triangles) {
                if (!touches(t, moved)) continue;
                const Vector before = normal(original, t), after = normal(surface, t);
                const double b = before.squared_length(), a = after.squared_length();
                if (a < min_area_ratio * min_area_ratio * b || after * before < min_turn * std::sqrt(a * b))
                    reverted += revert(surface, original, t, moved, went_back);
            }
        }
        if (!first) {
            candidates.assign(surface.triangles.size(), 0);
            for (size_t t = 0; t < surface.triangles.size(); ++t)
                candidates[t] = touches(surface.triangles[t], went_back);
            std::fill(went_back.begin(), went_back.end(), 0);
        }
        const auto pairs = crossing_pairs(surface, candidates);
        for (const auto& [i, j] : pairs)
            if (!touches(surface.triangles[i], moved) && !touches(surface.triangles[j], moved))
                result.self_intersecting = true;
        size_t reverted = 0;
        for (const auto& [i, j] : pairs)
            reverted += revert(surface, original, surface.triangles[i], moved, went_back) +
                        revert(surface, original, surface.triangles[j], moved, went_back);
        if (reverted == 0) break;
    }
    progress.update(1.0);
    for (char m : moved) result.moved_vertices += m;
    return result;
}

}  // namespace fabvdb::volume
