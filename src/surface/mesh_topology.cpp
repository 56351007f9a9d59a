//! Components and the topology summary from the edge table, by union-find on
//! indices (linear-logarithmic in the triangle count).
#include "surface/mesh_topology.h"

#include <algorithm>
#include <limits>

#include "core/disjoint_sets.h"

namespace fabvdb::surface {
namespace {

constexpr uint32_t none = std::numeric_limits<uint32_t>::max();

//! Corners are numbered 3·triangle + k. Two corners at the same vertex are in
//! the same fan when their triangles share an edge from that vertex (or are
//! the same triangle); the vertex is non-manifold when it has several fans.
size_t count_non_manifold_vertices(const Mesh& mesh, const EdgeTable& edges) {
    DisjointSets fans(mesh.triangles.size() * 3);
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const Triangle& tri = mesh.triangles[t];
        for (int i = 0; i < 3; ++i)
            for (int j = i + 1; j < 3; ++j)
                if (tri[i] == tri[j]) fans.unite(uint32_t(3 * t + i), uint32_t(3 * t + j));
    }
    auto corner_at = [&](uint32_t triangle, uint32_t vertex) {
        const Triangle& tri = mesh.triangles[triangle];
        return uint32_t(3 * triangle + (tri[0] == vertex ? 0 : tri[1] == vertex ? 1 : 2));
    };
    for (size_t e = 0; e < edges.edge_count(); ++e) {
        const EdgeUse& first = edges.uses[edges.begin[e]];
        for (size_t u = edges.begin[e] + 1; u < edges.begin[e + 1]; ++u) {
            const uint32_t other = edges.uses[u].triangle;
            fans.unite(corner_at(first.triangle, first.lo), corner_at(other, first.lo));
            fans.unite(corner_at(first.triangle, first.hi), corner_at(other, first.hi));
        }
    }
    std::vector<uint32_t> fan_of_vertex(mesh.vertices.size(), none);
    std::vector<bool> several_fans(mesh.vertices.size(), false);
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = mesh.triangles[t][k];
            const uint32_t fan = fans.find(uint32_t(3 * t + k));
            if (fan_of_vertex[v] == none)
                fan_of_vertex[v] = fan;
            else if (fan_of_vertex[v] != fan)
                several_fans[v] = true;
        }
    return size_t(std::count(several_fans.begin(), several_fans.end(), true));
}

}  // namespace

std::vector<std::vector<uint32_t>> boundary_loops(const Mesh& mesh, const EdgeTable& edges) {
    DisjointSets sets(mesh.vertices.size());
    std::vector<bool> on_boundary(mesh.vertices.size(), false);
    for (size_t e = 0; e < edges.edge_count(); ++e) {
        if (edges.use_count(e) != 1) continue;
        const EdgeUse& use = edges.uses[edges.begin[e]];
        sets.unite(use.lo, use.hi);
        on_boundary[use.lo] = on_boundary[use.hi] = true;
    }
    std::vector<uint32_t> loop_of(mesh.vertices.size(), none);
    std::vector<std::vector<uint32_t>> loops;
    for (uint32_t v = 0; v < mesh.vertices.size(); ++v) {
        if (!on_boundary[v]) continue;
        const uint32_t root = sets.find(v);
        if (loop_of[root] == none) {
            loop_of[root] = uint32_t(loops.size());
            loops.emplace_back();
        }
        loops[loop_of[root]].push_back(v);
    }
    return loops;
}

std::vector<uint32_t> triangle_components(const Mesh& mesh, size_t& component_count) {
    DisjointSets sets(mesh.vertices.size());
    for (const Triangle& t : mesh.triangles) {
        sets.unite(t[0], t[1]);
        sets.unite(t[0], t[2]);
    }
    std::vector<uint32_t> label_of_root(mesh.vertices.size(), none);
    std::vector<uint32_t> component(mesh.triangles.size());
    component_count = 0;
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        uint32_t& label = label_of_root[sets.find(mesh.triangles[t][0])];
        if (label == none) label = uint32_t(component_count++);
        component[t] = label;
    }
    return component;
}

TopologySummary summarize_topology(const Mesh& mesh) {
    TopologySummary s;
    std::vector<bool> referenced(mesh.vertices.size(), false);
    for (const Triangle& t : mesh.triangles)
        for (uint32_t v : t) referenced[v] = true;
    s.referenced_vertices = size_t(std::count(referenced.begin(), referenced.end(), true));
    s.unreferenced_vertices = mesh.vertices.size() - s.referenced_vertices;

    s.triangle_component = triangle_components(mesh, s.components);
    s.component_closed.assign(s.components, true);

    const EdgeTable edges = build_edge_table(mesh);
    s.edges = edges.edge_count();
    for (size_t e = 0; e < edges.edge_count(); ++e) {
        const size_t uses = edges.use_count(e);
        const EdgeUse& first = edges.uses[edges.begin[e]];
        if (uses == 1) ++s.boundary_edges;
        if (uses >= 3) ++s.non_manifold_edges;
        if (uses != 2) s.component_closed[s.triangle_component[first.triangle]] = false;
        if (uses == 2 && first.forward == edges.uses[edges.begin[e] + 1].forward) ++s.inconsistent_edges;
    }
    s.boundary_loops = boundary_loops(mesh, edges).size();
    s.non_manifold_vertices = count_non_manifold_vertices(mesh, edges);
    s.closed = !mesh.triangles.empty() && s.boundary_edges == 0 && s.non_manifold_edges == 0;

    if (s.closed && s.non_manifold_vertices == 0) {
        const long long euler = (long long)s.referenced_vertices - (long long)s.edges + (long long)mesh.triangles.size();
        const long long twice_genus = 2 * (long long)s.components - euler;
        if (twice_genus % 2 == 0) s.genus = twice_genus / 2;
    }
    return s;
}

}  // namespace fabvdb::surface
