//! Exact snapping of cavity vertices to the inner offset (see snap_to_offset.h).
#include "volume/snap_to_offset.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "volume/crossing_pairs.h"
#include "volume/nearest_triangle.h"

namespace fabvdb::volume {

namespace {

using openvdb::Vec3d;

Vec3d vec(const Vec3& p) { return Vec3d(p[0], p[1], p[2]); }

Vec3d normal(const Mesh& mesh, const Triangle& t) {
    const Vec3d a = vec(mesh.vertices[t[0]]);
    return (vec(mesh.vertices[t[1]]) - a).cross(vec(mesh.vertices[t[2]]) - a);
}

}  // namespace

SnapStats snap_to_offset(Mesh& cavity, const Mesh& outer, const openvdb::Int32Grid& closest_triangle, double wall,
                         OffsetSnap mode, Progress& progress) {
    progress.stage("snap cavity to the wall offset");
    const NearestTriangle nearest(outer, closest_triangle);
    const std::vector<Vec3> original = cavity.vertices;
    std::vector<double> depth(cavity.vertices.size(), std::numeric_limits<double>::infinity());
    std::vector<char> moved(cavity.vertices.size(), 0);

    // Two Newton steps: the second corrects vertices whose closest triangle
    // changed with the first move.
    const auto measure_and_move = [&](const std::vector<uint32_t>* only, bool move) {
        const size_t count = only ? only->size() : cavity.vertices.size();
        tbb::parallel_for(tbb::blocked_range<size_t>(0, count, 512), [&](const tbb::blocked_range<size_t>& range) {
            NearestTriangle::Query distance(nearest);
            for (size_t k = range.begin(); k != range.end(); ++k) {
                if (progress.cancelled()) return;
                const size_t i = only ? (*only)[k] : k;
                const Vec3d p = vec(cavity.vertices[i]);
                const NearestTriangle::Result closest = distance(p);
                if (!closest.found() || closest.distance <= 0.0) continue;
                depth[i] = closest.distance;
                const bool shallow = closest.distance < wall;
                if (!move || (mode == OffsetSnap::at_least && !shallow) ||
                    std::abs(closest.distance - wall) <= 1e-9 * wall)
                    continue;
                const Vec3d target = closest.point + (p - closest.point) * (wall / closest.distance);
                cavity.vertices[i] = {target[0], target[1], target[2]};
                depth[i] = wall;
                moved[i] = 1;
            }
        });
        progress.check();
    };
    measure_and_move(nullptr, true);
    progress.update(0.4);
    measure_and_move(nullptr, true);
    progress.update(0.7);

    // Undo the moves that flip a triangle, until none does.
    std::vector<Vec3d> original_normal(cavity.triangles.size());
    {
        Mesh before;
        before.vertices = original;
        for (size_t t = 0; t < cavity.triangles.size(); ++t) original_normal[t] = normal(before, cavity.triangles[t]);
    }
    std::vector<uint32_t> reverted;
    for (int round = 0; round < 8; ++round) {
        std::vector<uint32_t> now_reverted;
        for (size_t t = 0; t < cavity.triangles.size(); ++t) {
            const Triangle& tri = cavity.triangles[t];
            if (!(moved[tri[0]] || moved[tri[1]] || moved[tri[2]]) || original_normal[t].lengthSqr() == 0.0)
                continue;
            if (normal(cavity, tri).dot(original_normal[t]) > 0.0) continue;
            for (uint32_t v : tri)
                if (moved[v]) {
                    cavity.vertices[v] = original[v];
                    moved[v] = 0;
                    now_reverted.push_back(v);
                }
        }
        if (now_reverted.empty()) break;
        reverted.insert(reverted.end(), now_reverted.begin(), now_reverted.end());
    }
    // Undo the moves of triangles that cross others (thin voids whose two
    // sides were pushed into each other), until none does.
    progress.update(0.8);
    for (int round = 0; round < 8; ++round) {
        std::vector<uint32_t> now_reverted;
        for (const auto& [a, b] : crossing_pairs(cavity))
            for (uint32_t t : {a, b})
                for (uint32_t v : cavity.triangles[t])
                    if (moved[v]) {
                        cavity.vertices[v] = original[v];
                        moved[v] = 0;
                        now_reverted.push_back(v);
                    }
        if (now_reverted.empty()) break;
        reverted.insert(reverted.end(), now_reverted.begin(), now_reverted.end());
        progress.check();
    }
    if (!reverted.empty()) measure_and_move(&reverted, false);
    progress.update(1.0);

    SnapStats stats;
    stats.min_depth = depth.empty() ? 0.0 : *std::min_element(depth.begin(), depth.end());
    stats.moved = size_t(std::count(moved.begin(), moved.end(), 1));
    stats.kept_back = reverted.size();
    return stats;
}

}  // namespace fabvdb::volume
