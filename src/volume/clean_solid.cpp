//! The clean-solid test (see clean_solid.h).
#include "volume/clean_solid.h"

#include <algorithm>
#include <atomic>
#include <unordered_map>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <tbb/parallel_for.h>

namespace fabvdb::volume {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;

//! Each directed edge once, and its reverse once.
bool edges_pair_up(const Mesh& mesh) {
    std::unordered_map<uint64_t, int> directed;
    directed.reserve(mesh.triangles.size() * 3);
    for (const Triangle& t : mesh.triangles) {
        if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) return false;
        for (int k = 0; k < 3; ++k) {
            const uint64_t key = (uint64_t(t[k]) << 32) | t[(k + 1) % 3];
            if (++directed[key] > 1) return false;
        }
    }
    for (const auto& [key, count] : directed) {
        const uint64_t reverse = (key << 32) | (key >> 32);
        if (directed.find(reverse) == directed.end()) return false;
    }
    return true;
}

//! Whether any two faces cross, tested in slabs across the longest axis in
//! parallel (CGAL is built without TBB, so each test runs on one core). A
//! face belongs to every slab its bounding box reaches, boundaries included,
//! so two faces that share a point share the slab holding that point: the
//! answer is the whole mesh's.
bool self_intersects(const SurfaceMesh& surface, Progress& progress) {
    const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(surface);
    int axis = 0;
    for (int k = 1; k < 3; ++k)
        if (box.max(k) - box.min(k) > box.max(axis) - box.min(axis)) axis = k;
    constexpr int kSlabs = 8;
    const double width = (box.max(axis) - box.min(axis)) / kSlabs;
    std::vector<std::vector<SurfaceMesh::Face_index>> slabs(kSlabs);
    for (auto f : surface.faces()) {
        if (!(width > 0.0)) {  // flat: one slab
            slabs[0].push_back(f);
            continue;
        }
        const CGAL::Bbox_3 face_box = CGAL::Polygon_mesh_processing::face_bbox(f, surface);
        const int first = std::clamp(int((face_box.min(axis) - box.min(axis)) / width), 0, kSlabs - 1);
        const int last = std::clamp(int((face_box.max(axis) - box.min(axis)) / width), 0, kSlabs - 1);
        for (int slab = std::max(0, first - 1); slab <= std::min(kSlabs - 1, last + 1); ++slab) {
            const double lo = box.min(axis) + slab * width, hi = slab + 1 == kSlabs ? box.max(axis) : lo + width;
            if (face_box.max(axis) >= lo && face_box.min(axis) <= hi) slabs[slab].push_back(f);
        }
    }
    std::atomic<bool> crossing{false};
    tbb::parallel_for(0, kSlabs, [&](int slab) {
        if (crossing || progress.cancelled()) return;
        if (CGAL::Polygon_mesh_processing::does_self_intersect(slabs[slab], surface)) crossing = true;
    });
    progress.check();
    return crossing;
}

}  // namespace

bool is_clean_solid(const Mesh& mesh, Progress& progress) {
    progress.stage("check input surface");
    if (mesh.triangles.empty() || !edges_pair_up(mesh)) return false;
    progress.update(0.2);
    // Only the vertices triangles use: CGAL's volume test fails on isolated ones.
    SurfaceMesh surface;
    std::vector<SurfaceMesh::Vertex_index> vertex(mesh.vertices.size(), SurfaceMesh::null_vertex());
    for (const Triangle& t : mesh.triangles)
        for (uint32_t v : t)
            if (vertex[v] == SurfaceMesh::null_vertex())
                vertex[v] = surface.add_vertex(
                    Kernel::Point_3(mesh.vertices[v][0], mesh.vertices[v][1], mesh.vertices[v][2]));
    for (const Triangle& t : mesh.triangles)
        if (surface.add_face(vertex[t[0]], vertex[t[1]], vertex[t[2]]) == SurfaceMesh::null_face()) return false;
    for (auto f : surface.faces())
        if (CGAL::Polygon_mesh_processing::is_degenerate_triangle_face(f, surface)) return false;
    progress.update(0.4);
    if (self_intersects(surface, progress)) return false;
    progress.update(0.9);
    // CGAL also accepts a mesh turned wholly inside out (it bounds the
    // unbounded complement); its volume is negative.
    const bool bounds_volume =
        CGAL::Polygon_mesh_processing::does_bound_a_volume(surface) && signed_volume(mesh) > 0.0;
    progress.update(1.0);
    return bounds_volume;
}

}  // namespace fabvdb::volume
