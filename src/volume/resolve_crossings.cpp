//! Resolving crossing triangles (see resolve_crossings.h).
//!
//! The winding number w is constant off the surface between the cut curves
//! and grows by one across a triangle against its normal. So across a patch
//! w goes from w_front to w_front + 1, and the patch bounds {w ≥ 1} exactly
//! when w_front = 0. w_front is counted along a ray from the centre of one of
//! the patch's triangles: +1 for every triangle the ray leaves through (along
//! its normal), −1 for every one it enters through, and −1 more when the ray
//! starts behind its own triangle.
#include "volume/resolve_crossings.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <numeric>
#include <tuple>
#include <unordered_set>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Surface_mesh.h>

#include "volume/clean_solid.h"
#include "volume/mesh_shells.h"
#include "volume/vertex_corners.h"

namespace fabvdb::volume {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;

Point point(const Vec3& p) { return Point(p[0], p[1], p[2]); }

uint64_t edge_key(uint32_t a, uint32_t b) { return uint64_t(a) << 32 | b; }

//! The input with its crossing triangles split along the intersection curves.
struct Refined {
    Mesh mesh;                  //!< the input's vertices, then the cut points
    size_t first_piece = 0;     //!< the untouched triangles come first, then the pieces
    std::unordered_set<uint64_t> cut_edges;  //!< edge_key(a, b) and (b, a) of every edge along a cut
};

//! Whether a corner of b that is not a corner of a lies exactly in a's
//! plane (exact predicate): b touches a there, or lies in its plane.
bool touches_plane(const Mesh& mesh, uint32_t a, uint32_t b) {
    const Triangle& s = mesh.triangles[a];
    const Triangle& t = mesh.triangles[b];
    for (int k = 0; k < 3; ++k) {
        if (t[k] == s[0] || t[k] == s[1] || t[k] == s[2]) continue;
        if (CGAL::orientation(point(mesh.vertices[s[0]]), point(mesh.vertices[s[1]]), point(mesh.vertices[s[2]]),
                              point(mesh.vertices[t[k]])) == CGAL::COPLANAR)
            return true;
    }
    return false;
}

//! Splits the crossing triangles (only them: every triangle a cut passes
//! through crosses another) by CGAL's autorefinement. Each side of a cut
//! keeps its own copies of the cut points, so the result is still a closed
//! oriented manifold by its indices. Nothing when a corner of one crossing
//! triangle lies exactly in the other's plane (a flat fold, a vertex on a
//! face): CGAL 5.5's autorefinement crashes on such inputs (corpus
//! brucewick.obj, egret.ply).
std::optional<Refined> refine(const Mesh& mesh, const std::vector<std::pair<uint32_t, uint32_t>>& crossings) {
    for (const auto& [a, b] : crossings)
        if (touches_plane(mesh, a, b) || touches_plane(mesh, b, a)) return std::nullopt;
    std::vector<char> crossing(mesh.triangles.size(), 0);
    for (const auto& [a, b] : crossings) crossing[a] = crossing[b] = 1;
    SurfaceMesh part;
    std::vector<uint32_t> local(mesh.vertices.size(), UINT32_MAX), global;
    Refined refined;
    refined.mesh.vertices = mesh.vertices;
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        if (!crossing[t]) {
            refined.mesh.triangles.push_back(mesh.triangles[t]);
            continue;
        }
        SurfaceMesh::Vertex_index corner[3];
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = mesh.triangles[t][k];
            if (local[v] == UINT32_MAX) {
                local[v] = uint32_t(global.size());
                global.push_back(v);
                part.add_vertex(point(mesh.vertices[v]));
            }
            corner[k] = SurfaceMesh::Vertex_index(local[v]);
        }
        if (part.add_face(corner[0], corner[1], corner[2]) == SurfaceMesh::null_face()) return std::nullopt;
    }
    refined.first_piece = refined.mesh.triangles.size();

    auto cut = part.add_property_map<SurfaceMesh::Edge_index, bool>("e:cut", false).first;
    try {
        CGAL::Polygon_mesh_processing::experimental::autorefine(
            part, CGAL::Polygon_mesh_processing::parameters::edge_is_constrained_map(cut));
    } catch (const std::exception&) {
        return std::nullopt;  // a configuration the corefinement does not handle
    }

    // The first vertices are the input's, in order; the cut points follow.
    // The autorefinement orders the cut points, the pieces and their corners
    // differently from run to run: they are put in order of position (the
    // cut points, each piece from its least corner, the pieces), so that the
    // result is the same every run.
    const auto position = [&](SurfaceMesh::Vertex_index v) {
        const Point& p = part.point(v);
        return Vec3{p.x(), p.y(), p.z()};
    };
    std::vector<uint32_t> index(part.number_of_vertices() + part.number_of_removed_vertices(), UINT32_MAX);
    std::vector<SurfaceMesh::Vertex_index> cut_points;
    for (SurfaceMesh::Vertex_index v : part.vertices()) {
        if (size_t(v) < global.size()) {
            index[v] = global[v];
            if (position(v) != mesh.vertices[global[v]]) return std::nullopt;
        } else {
            cut_points.push_back(v);
        }
    }
    std::sort(cut_points.begin(), cut_points.end(),
              [&](SurfaceMesh::Vertex_index a, SurfaceMesh::Vertex_index b) { return position(a) < position(b); });
    for (SurfaceMesh::Vertex_index v : cut_points) {
        index[v] = uint32_t(refined.mesh.vertices.size());
        refined.mesh.vertices.push_back(position(v));
    }
    const std::vector<Vec3>& at = refined.mesh.vertices;
    std::vector<Triangle> pieces;
    for (SurfaceMesh::Face_index f : part.faces()) {
        Triangle t;
        int k = 0;
        for (SurfaceMesh::Vertex_index v : CGAL::vertices_around_face(part.halfedge(f), part)) {
            if (k == 3) return std::nullopt;
            t[k++] = index[v];
        }
        if (k != 3) return std::nullopt;
        std::rotate(t.begin(), std::min_element(t.begin(), t.end(), [&](uint32_t a, uint32_t b) { return at[a] < at[b]; }),
                    t.end());
        pieces.push_back(t);
    }
    std::sort(pieces.begin(), pieces.end(), [&](const Triangle& a, const Triangle& b) {
        return std::tie(at[a[0]], at[a[1]], at[a[2]]) < std::tie(at[b[0]], at[b[1]], at[b[2]]);
    });
    refined.mesh.triangles.insert(refined.mesh.triangles.end(), pieces.begin(), pieces.end());
    for (SurfaceMesh::Edge_index e : part.edges())
        if (cut[e]) {
            const uint32_t a = index[part.source(part.halfedge(e))], b = index[part.target(part.halfedge(e))];
            refined.cut_edges.insert(edge_key(a, b));
            refined.cut_edges.insert(edge_key(b, a));
        }
    return refined;
}

//! The surface's patches: triangles joined across every edge but the cuts.
struct Patches {
    std::vector<uint32_t> of_triangle;
    size_t count = 0;
    //! For every cut edge, the patches of the triangles on its two sides
    //! (one sheet): the winding number in front of them differs by one.
    std::vector<std::pair<uint32_t, uint32_t>> across_cuts;
};

//! Nothing when some edge has no single opposite (not a manifold by its
//! indices) or a cut does not part its two sides (a cut that ends inside a
//! patch, as at a branch point, where no winding number holds for a patch).
std::optional<Patches> patches(const Refined& refined) {
    const auto& triangles = refined.mesh.triangles;
    const VertexCorners corners(refined.mesh);
    // For every edge k (corner k to k + 1) of every triangle, the one
    // triangle running along it the other way; UINT32_MAX if not one.
    std::vector<uint32_t> opposite(3 * triangles.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, triangles.size()), [&](const tbb::blocked_range<size_t>& range) {
        for (size_t t = range.begin(); t != range.end(); ++t)
            for (int k = 0; k < 3; ++k) {
                const VertexCorners::Across other = corners.across(refined.mesh, uint32_t(t), k);
                opposite[3 * t + k] = other.count == 1 ? other.first : UINT32_MAX;
            }
    });
    std::vector<uint32_t> parent(triangles.size());
    std::iota(parent.begin(), parent.end(), 0u);
    const auto root = [&](uint32_t t) {
        while (parent[t] != t) t = parent[t] = parent[parent[t]];
        return t;
    };
    std::vector<std::pair<uint32_t, uint32_t>> cut_sides;  // triangles
    for (size_t t = 0; t < triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = triangles[t][k], b = triangles[t][(k + 1) % 3], other = opposite[3 * t + k];
            if (other == UINT32_MAX) return std::nullopt;
            // Cut edges run between pieces only: an untouched triangle's
            // edge has a piece on its other side when it lies on a cut.
            const bool untouched = t < refined.first_piece && other < refined.first_piece;
            if (untouched || !refined.cut_edges.count(edge_key(a, b)))
                parent[root(uint32_t(t))] = root(other);
            else if (a < b)
                cut_sides.emplace_back(uint32_t(t), other);
        }
    Patches result;
    result.of_triangle.resize(triangles.size());
    std::vector<uint32_t> number(triangles.size(), UINT32_MAX);
    for (size_t t = 0; t < triangles.size(); ++t) {
        uint32_t& n = number[root(uint32_t(t))];
        if (n == UINT32_MAX) n = uint32_t(result.count++);
        result.of_triangle[t] = n;
    }
    for (const auto& [t, u] : cut_sides) {
        const uint32_t p = result.of_triangle[t], q = result.of_triangle[u];
        if (p == q) return std::nullopt;
        result.across_cuts.emplace_back(p, q);
    }
    return result;
}

using Vec = std::array<double, 3>;
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

//! The rays' direction (generic: no two components alike, none simple) and
//! two unit vectors across it: rays and triangles are compared seen along it.
struct View {
    Vec along, u, v;
    View() {
        const Vec direction = {0.5390457218399, 0.6928203230276, 0.4789995612345};
        const double length = std::sqrt(dot(direction, direction));
        along = {direction[0] / length, direction[1] / length, direction[2] / length};
        const double across = std::hypot(along[0], along[1]);
        u = {along[1] / across, -along[0] / across, 0.0};
        v = {along[1] * u[2] - along[2] * u[1], along[2] * u[0] - along[0] * u[2], along[0] * u[1] - along[1] * u[0]};
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
                const double to_plane = (normal[0] * (corner[0] - ray.origin[0]) +
                                         normal[1] * (corner[1] - ray.origin[1]) +
                                         normal[2] * (corner[2] - ray.origin[2])) /
                                        std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
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

//! Per patch, the winding number just in front of it; nothing when some
//! patch gets no decisive ray from its `attempts` largest-facing triangles.
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

//! Parts the sheets of `mesh` where they touch at a single vertex: a vertex
//! whose triangles form several closed fans (a cut curve that runs through
//! an input vertex, as where a fold turns around one, leaves the union's
//! boundary pinched there) gets a copy per fan, moved `pinch_parting` of
//! the way toward the centre of that fan's ring, into the fan's own cone.
//! Returns the moved vertices, or nothing when some vertex's triangles do
//! not form closed fans (nothing is changed then).
std::optional<std::vector<uint32_t>> part_pinches(Mesh& mesh) {
    constexpr double pinch_parting = 0.01;
    const VertexCorners corners(mesh);
    // Per vertex (in parallel, without allocating for the usual single fan),
    // its fans when it has several; whether every vertex's are closed.
    std::atomic<bool> closed{true};
    tbb::enumerable_thread_specific<std::vector<std::pair<uint32_t, std::vector<uint32_t>>>> local_fans;
    tbb::enumerable_thread_specific<std::vector<char>> local_visited;
    tbb::parallel_for(tbb::blocked_range<uint32_t>(0, uint32_t(mesh.vertices.size())),
                      [&](const tbb::blocked_range<uint32_t>& range) {
        std::vector<char>& visited = local_visited.local();
        for (uint32_t v = range.begin(); v != range.end() && closed; ++v) {
            const auto begin = corners.corner.begin() + corners.first[v];
            const auto end = corners.corner.begin() + corners.first[v + 1];
            const auto ring = [&](uint32_t c, uint32_t step) { return mesh.triangles[c / 3][(c % 3 + step) % 3]; };
            const auto next_of = [&](auto at) {
                const uint32_t next = ring(*at, 2);
                return std::find_if(begin, end, [&](const auto& c) { return ring(c, 1) == next; });
            };
            for (auto c = begin; c != end; ++c)
                for (auto d = begin; d != c; ++d)
                    if (ring(*c, 1) == ring(*d, 1)) closed = false;
            visited.assign(size_t(end - begin), 0);
            size_t cycles = 0;
            for (auto start = begin; start != end && closed; ++start) {
                if (visited[size_t(start - begin)]) continue;
                auto at = start;
                do {
                    visited[size_t(at - begin)] = 1;
                    at = next_of(at);
                    if (at == end) break;
                } while (!visited[size_t(at - begin)]);
                if (at != start) closed = false;
                ++cycles;
            }
            if (cycles < 2 || !closed) continue;
            visited.assign(size_t(end - begin), 0);
            for (auto start = begin; start != end; ++start) {
                if (visited[size_t(start - begin)]) continue;
                std::vector<uint32_t> fan;
                for (auto at = start; !visited[size_t(at - begin)]; at = next_of(at)) {
                    visited[size_t(at - begin)] = 1;
                    fan.push_back(*at / 3);
                }
                local_fans.local().emplace_back(v, std::move(fan));
            }
        }
    });
    if (!closed) return std::nullopt;
    std::vector<std::pair<uint32_t, std::vector<uint32_t>>> fans;  // vertex, its fan's triangles, in vertex order
    for (auto& part : local_fans)
        for (auto& fan : part) fans.push_back(std::move(fan));
    std::stable_sort(fans.begin(), fans.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<uint32_t> moved;
    for (const auto& [v, fan] : fans) {
        Vec3 centre{0, 0, 0};
        for (uint32_t t : fan)
            for (uint32_t w : mesh.triangles[t])
                if (w != v)
                    for (int k = 0; k < 3; ++k) centre[k] += mesh.vertices[w][k] / double(2 * fan.size());
        Vec3 copy;
        for (int k = 0; k < 3; ++k)
            copy[k] = mesh.vertices[v][k] + pinch_parting * (centre[k] - mesh.vertices[v][k]);
        const uint32_t index = uint32_t(mesh.vertices.size());
        mesh.vertices.push_back(copy);
        for (uint32_t t : fan)
            for (uint32_t& w : mesh.triangles[t])
                if (w == v) w = index;
        moved.push_back(index);
    }
    return moved;
}

}  // namespace

size_t max_crossing_pairs(size_t triangle_count) { return std::max<size_t>(1024, triangle_count / 10); }

std::optional<Mesh> resolve_crossings(const Mesh& mesh, const std::vector<std::pair<uint32_t, uint32_t>>& crossings,
                                      Progress& progress) {
    progress.stage("resolve crossings");
    if (crossings.empty() || crossings.size() > max_crossing_pairs(mesh.triangles.size())) return std::nullopt;
    const std::optional<Refined> refined = refine(mesh, crossings);
    if (!refined) return std::nullopt;
    progress.update(0.2);
    const std::optional<Patches> parts = patches(*refined);
    if (!parts) return std::nullopt;
    const std::vector<uint32_t>& patch = parts->of_triangle;
    progress.update(0.3);
    const std::optional<std::vector<int>> front = front_winding_numbers(refined->mesh, patch, parts->count, progress);
    if (!front) return std::nullopt;
    // One ray per patch: the cuts between them must tell the same story.
    for (const auto& [p, q] : parts->across_cuts)
        if (std::abs((*front)[p] - (*front)[q]) != 1) return std::nullopt;
    progress.update(0.8);

    // The kept pieces' cut points, merged with their copies on the other side
    // of the cut (the same rounded point), and with an input vertex there.
    const Mesh& cut = refined->mesh;
    std::vector<uint32_t> kept, at_cut;
    size_t first_kept_piece = 0;
    for (size_t t = 0; t < cut.triangles.size(); ++t) {
        if ((*front)[patch[t]] != 0) continue;
        if (t < refined->first_piece) {
            ++first_kept_piece;
        } else {
            for (uint32_t v : cut.triangles[t]) at_cut.push_back(v);
        }
        kept.push_back(uint32_t(t));
    }
    std::sort(at_cut.begin(), at_cut.end(), [&](uint32_t a, uint32_t b) {
        return cut.vertices[a] < cut.vertices[b] || (cut.vertices[a] == cut.vertices[b] && a < b);
    });
    std::vector<uint32_t> same(cut.vertices.size());
    std::iota(same.begin(), same.end(), 0u);
    for (size_t i = 1; i < at_cut.size(); ++i)
        if (cut.vertices[at_cut[i]] == cut.vertices[at_cut[i - 1]]) same[at_cut[i]] = same[at_cut[i - 1]];
    Mesh merged{cut.vertices, {}};
    for (uint32_t t : kept) {
        const Triangle& original = cut.triangles[t];
        merged.triangles.push_back({same[original[0]], same[original[1]], same[original[2]]});
    }
    const std::optional<std::vector<uint32_t>> moved = part_pinches(merged);
    if (!moved) return std::nullopt;
    // Only the pieces and the triangles at parted pinches may cross after
    // rounding: the others are the input's, which crossed nothing but the
    // crossing triangles.
    std::vector<char> changed(merged.vertices.size(), 0);
    for (uint32_t v : *moved) changed[v] = 1;
    std::vector<char> candidates(merged.triangles.size(), 0);
    for (size_t t = 0; t < merged.triangles.size(); ++t)
        candidates[t] = t >= first_kept_piece || changed[merged.triangles[t][0]] ||
                        changed[merged.triangles[t][1]] || changed[merged.triangles[t][2]];
    std::vector<uint32_t> all(merged.triangles.size());
    std::iota(all.begin(), all.end(), 0u);
    Mesh resolved = sub_mesh(merged, all);
    if (!check_solid(resolved, progress, candidates).clean) return std::nullopt;
    return resolved;
}

}  // namespace fabvdb::volume
