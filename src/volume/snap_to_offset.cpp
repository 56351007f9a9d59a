//! Exact snapping of cavity vertices to the inner offset (see snap_to_offset.h).
#include "volume/snap_to_offset.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace fabvdb::volume {

namespace {

using openvdb::Vec3d;

Vec3d vec(const Vec3& p) { return Vec3d(p[0], p[1], p[2]); }

//! The point of triangle abc closest to p, by the Voronoi region of p
//! (vertex, edge or face) computed from barycentric dot products.
Vec3d closest_point_on_triangle(const Vec3d& p, const Vec3d& a, const Vec3d& b, const Vec3d& c) {
    const Vec3d ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0 && d2 <= 0) return a;
    const Vec3d bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
    const Vec3d cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    const double denominator = 1.0 / (va + vb + vc);
    return a + ab * (vb * denominator) + ac * (vc * denominator);
}

//! Triangles around each vertex of the outer surface (compressed rows).
struct VertexTriangles {
    std::vector<uint32_t> first, triangles;
    explicit VertexTriangles(const Mesh& mesh) : first(mesh.vertices.size() + 1, 0) {
        for (const Triangle& t : mesh.triangles)
            for (uint32_t v : t) ++first[v + 1];
        for (size_t i = 1; i < first.size(); ++i) first[i] += first[i - 1];
        triangles.resize(first.back());
        std::vector<uint32_t> fill(first.begin(), first.end() - 1);
        for (uint32_t t = 0; t < mesh.triangles.size(); ++t)
            for (uint32_t v : mesh.triangles[t]) triangles[fill[v]++] = t;
    }
};

struct Closest {
    Vec3d point;
    double distance = std::numeric_limits<double>::infinity();
    bool found() const { return std::isfinite(distance); }
};

//! Exact distance from p to the outer surface, over the closest triangles the
//! index grid holds in the 27 voxels around p and the triangles around the
//! best one's corners.
class OuterDistance {
public:
    OuterDistance(const Mesh& outer, const VertexTriangles& around, const openvdb::Int32Grid& index)
        : outer_(outer), around_(around), index_(index), accessor_(index.getConstAccessor()) {}

    Closest operator()(const Vec3d& p) {
        candidates_.clear();
        const openvdb::Coord center = index_.transform().worldToIndexNodeCentered(p);
        for (int dx = -1; dx <= 1; ++dx)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dz = -1; dz <= 1; ++dz) {
                    openvdb::Int32 triangle;
                    if (accessor_.probeValue(center.offsetBy(dx, dy, dz), triangle) && triangle >= 0 &&
                        size_t(triangle) < outer_.triangles.size())
                        candidates_.push_back(uint32_t(triangle));
                }
        Closest best;
        uint32_t best_triangle = 0;
        consider(p, best, best_triangle);
        if (!best.found()) return best;
        candidates_.clear();
        for (uint32_t v : outer_.triangles[best_triangle])
            for (uint32_t k = around_.first[v]; k < around_.first[v + 1]; ++k)
                candidates_.push_back(around_.triangles[k]);
        consider(p, best, best_triangle);
        return best;
    }

private:
    void consider(const Vec3d& p, Closest& best, uint32_t& best_triangle) {
        std::sort(candidates_.begin(), candidates_.end());
        candidates_.erase(std::unique(candidates_.begin(), candidates_.end()), candidates_.end());
        for (uint32_t t : candidates_) {
            const Triangle& tri = outer_.triangles[t];
            const Vec3d q = closest_point_on_triangle(p, vec(outer_.vertices[tri[0]]), vec(outer_.vertices[tri[1]]),
                                                      vec(outer_.vertices[tri[2]]));
            const double distance = (p - q).length();
            if (distance < best.distance) {
                best.distance = distance;
                best.point = q;
                best_triangle = t;
            }
        }
    }

    const Mesh& outer_;
    const VertexTriangles& around_;
    const openvdb::Int32Grid& index_;
    openvdb::Int32Grid::ConstAccessor accessor_;
    std::vector<uint32_t> candidates_;
};

Vec3d normal(const Mesh& mesh, const Triangle& t) {
    const Vec3d a = vec(mesh.vertices[t[0]]);
    return (vec(mesh.vertices[t[1]]) - a).cross(vec(mesh.vertices[t[2]]) - a);
}

//! The triangle pairs of `mesh` that cross each other (CGAL, exact
//! predicates); empty when the triangles do not form a manifold surface.
std::vector<std::pair<uint32_t, uint32_t>> crossing_triangles(const Mesh& mesh) {
    using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
    using Surface = CGAL::Surface_mesh<Kernel::Point_3>;
    Surface surface;
    std::vector<Surface::Vertex_index> vertex;
    vertex.reserve(mesh.vertices.size());
    for (const Vec3& p : mesh.vertices) vertex.push_back(surface.add_vertex(Kernel::Point_3(p[0], p[1], p[2])));
    for (const Triangle& t : mesh.triangles)
        if (surface.add_face(vertex[t[0]], vertex[t[1]], vertex[t[2]]) == Surface::null_face()) return {};
    std::vector<std::pair<Surface::Face_index, Surface::Face_index>> faces;
    CGAL::Polygon_mesh_processing::self_intersections<CGAL::Parallel_if_available_tag>(surface,
                                                                                          std::back_inserter(faces));
    std::vector<std::pair<uint32_t, uint32_t>> pairs;
    for (const auto& [a, b] : faces) pairs.emplace_back(uint32_t(a.idx()), uint32_t(b.idx()));
    return pairs;
}

}  // namespace

SnapStats snap_to_offset(Mesh& cavity, const Mesh& outer, const openvdb::Int32Grid& closest_triangle, double wall,
                         OffsetSnap mode, Progress& progress) {
    progress.stage("snap cavity to the wall offset");
    const VertexTriangles around(outer);
    const std::vector<Vec3> original = cavity.vertices;
    std::vector<double> depth(cavity.vertices.size(), std::numeric_limits<double>::infinity());
    std::vector<char> moved(cavity.vertices.size(), 0);

    // Two Newton steps: the second corrects vertices whose closest triangle
    // changed with the first move.
    const auto measure_and_move = [&](const std::vector<uint32_t>* only, bool move) {
        const size_t count = only ? only->size() : cavity.vertices.size();
        tbb::parallel_for(tbb::blocked_range<size_t>(0, count, 512), [&](const tbb::blocked_range<size_t>& range) {
            OuterDistance distance(outer, around, closest_triangle);
            for (size_t k = range.begin(); k != range.end(); ++k) {
                if (progress.cancelled()) return;
                const size_t i = only ? (*only)[k] : k;
                const Vec3d p = vec(cavity.vertices[i]);
                const Closest closest = distance(p);
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
        for (const auto& [a, b] : crossing_triangles(cavity))
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
