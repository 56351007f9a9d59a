//! The clean-solid test (see clean_solid.h).
#include "volume/clean_solid.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numeric>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Surface_mesh.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include "volume/closed_manifold.h"
#include "volume/crossing_pairs.h"

namespace fabvdb::volume {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;

Kernel::Point_3 point(const Vec3& p) { return Kernel::Point_3(p[0], p[1], p[2]); }

bool has_degenerate_triangle(const Mesh& mesh) {
    std::atomic<bool> degenerate{false};
    tbb::parallel_for(tbb::blocked_range<size_t>(0, mesh.triangles.size(), 4096),
                      [&](const tbb::blocked_range<size_t>& range) {
        for (size_t i = range.begin(); i != range.end() && !degenerate; ++i) {
            const Triangle& t = mesh.triangles[i];
            if (CGAL::collinear(point(mesh.vertices[t[0]]), point(mesh.vertices[t[1]]), point(mesh.vertices[t[2]])))
                degenerate = true;
        }
    });
    return degenerate;
}

struct Box {
    double lo[3], hi[3];
    explicit Box(const Mesh& mesh, const Triangle& t) {
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min({mesh.vertices[t[0]][k], mesh.vertices[t[1]][k], mesh.vertices[t[2]][k]});
            hi[k] = std::max({mesh.vertices[t[0]][k], mesh.vertices[t[1]][k], mesh.vertices[t[2]][k]});
        }
    }
    bool meets(const Box& other) const {
        for (int k = 0; k < 3; ++k)
            if (hi[k] < other.lo[k] || other.hi[k] < lo[k]) return false;
        return true;
    }
};

//! The triangles, in index order, whose bounding box meets a candidate's:
//! only they can be in a crossing pair with a candidate. The candidates'
//! boxes go into cubic cells as wide as the widest of them (so each meets at
//! most 8); a triangle looks in the cells its own box meets. Two boxes that
//! share a point share that point's cell: the cell index floor((x − origin)
//! / side) never decreases with x, rounding included. A triangle meeting
//! more than `max_cells` cells is compared with every candidate instead.
std::vector<uint32_t> near_candidates(const Mesh& mesh, const std::vector<char>& candidates) {
    constexpr int64_t max_cells = 64;
    constexpr int cell_bits = 21;
    std::vector<uint32_t> listed;
    for (size_t t = 0; t < candidates.size(); ++t)
        if (candidates[t]) listed.push_back(uint32_t(t));
    if (listed.empty()) return {};
    std::vector<Box> boxes;
    boxes.reserve(listed.size());
    double origin[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, top[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL}, side = 0.0;
    for (uint32_t t : listed) {
        const Box& box = boxes.emplace_back(mesh, mesh.triangles[t]);
        for (int k = 0; k < 3; ++k) {
            origin[k] = std::min(origin[k], box.lo[k]);
            top[k] = std::max(top[k], box.hi[k]);
            side = std::max(side, box.hi[k] - box.lo[k]);
        }
    }
    for (int k = 0; k < 3; ++k) side = std::max(side, (top[k] - origin[k]) / double(int64_t(1) << (cell_bits - 1)));
    side = std::max(side, 1e-300);
    int64_t last[3];
    const auto cell = [&](double x, int k) { return int64_t(std::floor((x - origin[k]) / side)); };
    for (int k = 0; k < 3; ++k) last[k] = cell(top[k], k);
    const auto key = [](int64_t x, int64_t y, int64_t z) {
        return uint64_t(x) << (2 * cell_bits) | uint64_t(y) << cell_bits | uint64_t(z);
    };
    std::vector<std::pair<uint64_t, uint32_t>> cells;  // (cell, index into listed)
    for (uint32_t c = 0; c < listed.size(); ++c) {
        const Box& box = boxes[c];
        for (int64_t x = cell(box.lo[0], 0); x <= cell(box.hi[0], 0); ++x)
            for (int64_t y = cell(box.lo[1], 1); y <= cell(box.hi[1], 1); ++y)
                for (int64_t z = cell(box.lo[2], 2); z <= cell(box.hi[2], 2); ++z) cells.emplace_back(key(x, y, z), c);
    }
    tbb::parallel_sort(cells.begin(), cells.end());

    std::vector<char> near(mesh.triangles.size(), 0);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, mesh.triangles.size(), 4096),
                      [&](const tbb::blocked_range<size_t>& range) {
        for (size_t t = range.begin(); t != range.end(); ++t) {
            if (candidates[t]) {
                near[t] = 1;
                continue;
            }
            const Box box(mesh, mesh.triangles[t]);
            int64_t lo[3], hi[3], count = 1;
            for (int k = 0; k < 3; ++k) {
                lo[k] = std::max<int64_t>(cell(box.lo[k], k), 0);
                hi[k] = std::min(cell(box.hi[k], k), last[k]);
                count *= std::max<int64_t>(hi[k] - lo[k] + 1, 0);
            }
            if (count == 0) continue;
            if (count > max_cells) {
                near[t] = std::any_of(boxes.begin(), boxes.end(), [&](const Box& other) { return box.meets(other); });
                continue;
            }
            for (int64_t x = lo[0]; x <= hi[0] && !near[t]; ++x)
                for (int64_t y = lo[1]; y <= hi[1] && !near[t]; ++y)
                    for (int64_t z = lo[2]; z <= hi[2] && !near[t]; ++z)
                        for (auto it = std::lower_bound(cells.begin(), cells.end(), std::make_pair(key(x, y, z), 0u));
                             it != cells.end() && it->first == key(x, y, z); ++it)
                            if (box.meets(boxes[it->second])) {
                                near[t] = 1;
                                break;
                            }
        }
    });
    std::vector<uint32_t> result;
    for (size_t t = 0; t < near.size(); ++t)
        if (near[t]) result.push_back(uint32_t(t));
    return result;
}

//! The crossing pairs with a candidate in them, found among the triangles
//! near the candidates alone (crossing_pairs on that part of the mesh: a
//! vertex whose fan is cut off there counts as not embedded, so its pairs
//! are tested exactly and the pairs are the same).
std::vector<std::pair<uint32_t, uint32_t>> candidate_crossings(const Mesh& mesh, const std::vector<char>& candidates) {
    const std::vector<uint32_t> near = near_candidates(mesh, candidates);
    Mesh part{mesh.vertices, {}};
    std::vector<char> part_candidates(near.size());
    part.triangles.reserve(near.size());
    for (size_t i = 0; i < near.size(); ++i) {
        part.triangles.push_back(mesh.triangles[near[i]]);
        part_candidates[i] = candidates[near[i]];
    }
    std::vector<std::pair<uint32_t, uint32_t>> pairs = crossing_pairs(part, part_candidates);
    for (auto& [i, j] : pairs) i = near[i], j = near[j];
    return pairs;
}

bool is_one_shell(const Mesh& mesh) {
    std::vector<uint32_t> parent(mesh.vertices.size());
    std::iota(parent.begin(), parent.end(), 0u);
    const auto root = [&](uint32_t v) {
        while (parent[v] != v) v = parent[v] = parent[parent[v]];
        return v;
    };
    for (const Triangle& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = root(t[k]), b = root(t[(k + 1) % 3]);
            if (a != b) parent[a] = b;
        }
    const uint32_t shell = root(mesh.triangles.front()[0]);
    for (const Triangle& t : mesh.triangles)
        if (root(t[0]) != shell) return false;
    return true;
}

//! Whether a closed oriented manifold whose triangles do not cross bounds a
//! volume. One such shell always bounds a region, outward exactly when its
//! volume is positive; several must also nest consistently (CGAL), and CGAL
//! also accepts a mesh turned wholly inside out (it bounds the unbounded
//! complement), whose volume is negative.
bool bounds_volume(const Mesh& mesh) {
    if (signed_volume(mesh) <= 0.0) return false;
    if (is_one_shell(mesh)) return true;
    // Only the vertices triangles use: CGAL's volume test fails on isolated ones.
    SurfaceMesh surface;
    std::vector<SurfaceMesh::Vertex_index> vertex(mesh.vertices.size(), SurfaceMesh::null_vertex());
    for (const Triangle& t : mesh.triangles)
        for (uint32_t v : t)
            if (vertex[v] == SurfaceMesh::null_vertex()) vertex[v] = surface.add_vertex(point(mesh.vertices[v]));
    for (const Triangle& t : mesh.triangles)
        if (surface.add_face(vertex[t[0]], vertex[t[1]], vertex[t[2]]) == SurfaceMesh::null_face()) return false;
    return CGAL::Polygon_mesh_processing::does_bound_a_volume(surface);
}

}  // namespace

SolidCheck check_solid(const Mesh& mesh, Progress& progress, const std::vector<char>& candidates) {
    progress.stage("check input surface");
    SolidCheck result;
    if (mesh.triangles.empty() || !is_closed_manifold(mesh) || has_degenerate_triangle(mesh)) return result;
    progress.update(0.2);
    result.crossings = candidates.empty() ? crossing_pairs(mesh) : candidate_crossings(mesh, candidates);
    if (!result.crossings.empty()) return result;
    progress.update(0.8);
    result.clean = bounds_volume(mesh);
    progress.update(1.0);
    return result;
}

}  // namespace fabvdb::volume
