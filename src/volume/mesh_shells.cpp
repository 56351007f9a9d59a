//! Shells of a mesh (see mesh_shells.h).
#include "volume/mesh_shells.h"

#include <cmath>

#include "core/disjoint_sets.h"

namespace fabvdb::volume {

std::vector<MeshShell> split_shells(const Mesh& mesh) {
    DisjointSets components(mesh.vertices.size());
    for (const Triangle& t : mesh.triangles) {
        components.unite(t[0], t[1]);
        components.unite(t[1], t[2]);
    }
    std::vector<int> shell_of_root(mesh.vertices.size(), -1);
    std::vector<MeshShell> shells;
    for (uint32_t t = 0; t < mesh.triangles.size(); ++t) {
        const Triangle& tri = mesh.triangles[t];
        const uint32_t root = components.find(tri[0]);
        if (shell_of_root[root] < 0) {
            shell_of_root[root] = int(shells.size());
            shells.emplace_back();
        }
        MeshShell& shell = shells[size_t(shell_of_root[root])];
        shell.triangles.push_back(t);
        shell.volume +=
            six_signed_tetrahedron_volume(mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]]) / 6.0;
    }
    return shells;
}

Mesh sub_mesh(const Mesh& mesh, const std::vector<uint32_t>& triangles) {
    Mesh out;
    std::vector<uint32_t> new_index(mesh.vertices.size(), UINT32_MAX);
    out.triangles.reserve(triangles.size());
    for (uint32_t t : triangles) {
        Triangle copy;
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = mesh.triangles[t][k];
            if (new_index[v] == UINT32_MAX) {
                new_index[v] = uint32_t(out.vertices.size());
                out.vertices.push_back(mesh.vertices[v]);
            }
            copy[k] = new_index[v];
        }
        out.triangles.push_back(copy);
    }
    return out;
}

bool is_flat_shell(const Mesh& mesh, const MeshShell& shell, double diagonal) {
    double area = 0.0;
    const Vec3& first = mesh.vertices[mesh.triangles[shell.triangles[0]][0]];
    BoundingBox box{first, first};
    for (uint32_t t : shell.triangles) {
        area += triangle_area(mesh, mesh.triangles[t]);
        for (uint32_t v : mesh.triangles[t]) box.add(mesh.vertices[v]);
    }
    const double thickness = 2.0 * std::abs(shell.volume) / area;
    return thickness < 1e-4 * diagonal && thickness < 0.01 * box.diagonal();
}

MeshShellCounts drop_small_or_flat_shells(Mesh& mesh, double min_volume) {
    MeshShellCounts counts;
    std::vector<uint32_t> kept;
    const double diagonal = bounding_box(mesh).diagonal();
    for (const MeshShell& shell : split_shells(mesh)) {
        if (std::abs(shell.volume) < min_volume || is_flat_shell(mesh, shell, diagonal)) {
            ++counts.dropped;
            continue;
        }
        ++counts.kept;
        kept.insert(kept.end(), shell.triangles.begin(), shell.triangles.end());
    }
    if (counts.dropped > 0) mesh = sub_mesh(mesh, kept);
    return counts;
}

}  // namespace fabvdb::volume
