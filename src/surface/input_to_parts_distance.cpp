//! Distance from the input surface to the cast parts (see input_to_parts_distance.h).
#include "surface/input_to_parts_distance.h"

#include <algorithm>
#include <cmath>

#include "core/vec3_ops.h"
#include "volume/surface_distance.h"
#include "volume/winding_number.h"

namespace fabvdb::surface {

using volume::SurfaceDistance;
namespace {

//! mm: input surface facing its own solid across a narrower slit has no
//! surface a cast part could carry: its mold would need a blade that thin,
//! under the narrowest recess that resin printing reproduces (0.3–0.5 mm).
constexpr double kClosedSlit = 0.3;

}  // namespace

InputToParts input_to_parts_distance(const Mesh& input, const std::vector<const Mesh*>& parts, double spacing,
                                     Progress& progress) {
    progress.stage("mold: distance to the input");
    Mesh all;
    std::vector<size_t> part_of_triangle;
    for (size_t p = 0; p < parts.size(); ++p) {
        append(all, *parts[p]);
        part_of_triangle.insert(part_of_triangle.end(), parts[p]->triangles.size(), p);
    }
    const SurfaceDistance distance(all);
    const volume::WindingNumber winding(input);
    const SurfaceDistance input_distance(input);
    const double probe = 0.05 * spacing;
    // True where the input's solid lies on both sides of the surface at
    // `point`, whose normal (any length) is `normal`: behind it, and in front
    // of it either at once or across a slit narrower than kClosedSlit. A slit
    // needs other input surface inside the ball of that diameter standing on
    // the point, which one nearest-point query rules out on most surface.
    const auto enclosed = [&](const Vec3& point, const Vec3& normal) {
        const double length = norm(normal);
        if (!(length > 0)) return false;
        const Vec3 unit = (1.0 / length) * normal;
        double front = winding(point + probe * unit);
        const double radius = 0.5 * kClosedSlit;
        if (std::abs(front) < 0.5 && input_distance.nearest(point + radius * unit).distance < (1 - 1e-3) * radius)
            for (int quarter = 4; quarter >= 1 && std::abs(front) < 0.5; --quarter)
                front = winding(point + (0.25 * quarter * kClosedSlit) * unit);
        if (std::abs(front) < 0.5) return false;  // most surface: open space in front
        const double back = winding(point - probe * unit);
        return front > 0 ? back >= 0.5 : back <= -0.5;
    };
    InputToParts result;
    result.part_max.assign(parts.size(), 0.0);
    std::vector<double> sum(parts.size(), 0.0), weight(parts.size(), 0.0);
    double total = 0, total_weight = 0;
    const auto add = [&](const Vec3& point, const Vec3& normal, double w) {
        const SurfaceDistance::Nearest nearest = distance.nearest(point);
        if (nearest.distance > 0.5 * spacing && enclosed(point, normal)) {
            ++result.enclosed_samples;
            return;
        }
        const size_t p = part_of_triangle[nearest.triangle];
        sum[p] += w * nearest.distance;
        weight[p] += w;
        result.part_max[p] = std::max(result.part_max[p], nearest.distance);
        result.max = std::max(result.max, nearest.distance);
        total += w * nearest.distance;
        total_weight += w;
    };
    std::vector<double> vertex_weight(input.vertices.size(), 0.0);
    std::vector<Vec3> vertex_normal(input.vertices.size(), Vec3{0, 0, 0});
    std::vector<char> used(input.vertices.size(), 0);
    for (size_t t = 0; t < input.triangles.size(); ++t) {
        const Triangle& tri = input.triangles[t];
        const Vec3 &a = input.vertices[tri[0]], &b = input.vertices[tri[1]], &c = input.vertices[tri[2]];
        const Vec3 normal = cross(b - a, c - a);
        const double area = 0.5 * norm(normal);
        const double longest = std::max({norm(b - a), norm(c - b), norm(a - c)});
        const int n = std::max(1, int(std::ceil(longest / spacing)));
        const double share = area / double((n + 1) * (n + 2) / 2);
        for (uint32_t v : tri) {
            vertex_weight[v] += share;
            vertex_normal[v] = vertex_normal[v] + normal;
            used[v] = 1;
        }
        for (int i = 0; i <= n; ++i)
            for (int j = 0; i + j <= n; ++j) {
                const bool corner = ((i == 0 || i == n) && j == 0) || (i == 0 && j == n);
                if (!corner) add(a + (double(i) / n) * (b - a) + (double(j) / n) * (c - a), normal, share);
            }
        if (t % 4096 == 0) progress.update(0.5 * double(t) / double(input.triangles.size()));
    }
    for (size_t v = 0; v < input.vertices.size(); ++v) {
        if (used[v]) add(input.vertices[v], vertex_normal[v], vertex_weight[v]);
        if (v % 4096 == 0) progress.update(0.5 + 0.5 * double(v) / double(input.vertices.size()));
    }
    result.mean = total_weight > 0 ? total / total_weight : 0.0;
    result.part_mean.assign(parts.size(), 0.0);
    for (size_t p = 0; p < parts.size(); ++p)
        if (weight[p] > 0) result.part_mean[p] = sum[p] / weight[p];
    return result;
}

}  // namespace fabvdb::surface
