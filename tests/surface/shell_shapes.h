//! Shells (surface/shell.h) of synthetic meshes with known answers, shared by
//! the surface tests: the mesh as S_low, each inner vertex `thickness` inside
//! along the vertex normal, no thin features.
#pragma once

#include <cmath>
#include <queue>
#include <string>
#include <utility>
#include <vector>

#include "core/mesh.h"
#include "support/shapes.h"
#include "surface/shell.h"

namespace fabvdb::test {

inline surface::Shell shell_of(Mesh mesh, double thickness) {
    const std::vector<Vec3> normals = area_weighted_vertex_normals(mesh);
    std::vector<Vec3> inner(mesh.vertices.size());
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
        const Vec3& n = normals[v];
        const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (int k = 0; k < 3; ++k) inner[v][k] = mesh.vertices[v][k] - thickness * n[k] / length;
    }
    const size_t n = mesh.triangles.size();
    return surface::make_shell(std::move(mesh), std::move(inner), std::vector<int>(n, -1), thickness, "test shell");
}

//! Index of the candidate direction nearest `d`.
inline int nearest_direction(const std::vector<Vec3>& directions, const Vec3& d) {
    int best = 0;
    double best_dot = -2;
    for (size_t i = 0; i < directions.size(); ++i) {
        const double dot = directions[i][0] * d[0] + directions[i][1] * d[1] + directions[i][2] * d[2];
        if (dot > best_dot) {
            best_dot = dot;
            best = int(i);
        }
    }
    return best;
}

//! Edge-connected pieces of the triangles labelled `label`.
inline int connected_pieces(const surface::Shell& shell, const std::vector<int>& label_of_triangle, int label) {
    std::vector<char> seen(shell.triangle_count(), 0);
    int count = 0;
    for (size_t start = 0; start < shell.triangle_count(); ++start) {
        if (seen[start] || label_of_triangle[start] != label) continue;
        ++count;
        std::queue<int> queue;
        queue.push(int(start));
        seen[start] = 1;
        while (!queue.empty()) {
            const int t = queue.front();
            queue.pop();
            for (int u : shell.neighbor[t])
                if (u >= 0 && !seen[u] && label_of_triangle[u] == label) {
                    seen[u] = 1;
                    queue.push(u);
                }
        }
    }
    return count;
}

}  // namespace fabvdb::test
