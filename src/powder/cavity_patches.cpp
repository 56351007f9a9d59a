//! Cavity surface → patches (see cavity_patches.h).
#include "powder/cavity_patches.h"

#include <cmath>
#include <limits>
#include <map>
#include <unordered_map>

#include <Eigen/Geometry>

#include "core/error.h"

namespace fabvdb::powder {

namespace {

Eigen::Vector3d point(const Vec3& p) { return {p[0], p[1], p[2]}; }
Vec3 vec(const Eigen::Vector3d& p) { return {p.x(), p.y(), p.z()}; }

uint64_t edge_key(uint32_t a, uint32_t b) {
    if (a > b) std::swap(a, b);
    return (uint64_t(a) << 32) | b;
}

//! The triangles sharing each edge, from which triangle adjacency follows.
struct EdgeTriangles {
    std::unordered_map<uint64_t, std::vector<uint32_t>> of_edge;
};

EdgeTriangles edge_triangles(const Mesh& mesh) {
    EdgeTriangles edges;
    edges.of_edge.reserve(mesh.triangles.size() * 2);
    for (uint32_t t = 0; t < mesh.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k)
            edges.of_edge[edge_key(mesh.triangles[t][k], mesh.triangles[t][(k + 1) % 3])].push_back(t);
    return edges;
}

//! Labels the edge-connected components of the triangles for which
//! `same_group(a, b)` holds across every crossed edge.
template <class SameGroup>
std::vector<uint32_t> connected_labels(const Mesh& mesh, const EdgeTriangles& edges, SameGroup same_group,
                                       uint32_t& count) {
    const uint32_t none = std::numeric_limits<uint32_t>::max();
    std::vector<uint32_t> label(mesh.triangles.size(), none);
    std::vector<uint32_t> stack;
    count = 0;
    for (uint32_t seed = 0; seed < mesh.triangles.size(); ++seed) {
        if (label[seed] != none) continue;
        label[seed] = count;
        stack.push_back(seed);
        while (!stack.empty()) {
            const uint32_t t = stack.back();
            stack.pop_back();
            for (int k = 0; k < 3; ++k) {
                const auto& around = edges.of_edge.at(edge_key(mesh.triangles[t][k], mesh.triangles[t][(k + 1) % 3]));
                for (uint32_t other : around)
                    if (label[other] == none && same_group(t, other)) {
                        label[other] = count;
                        stack.push_back(other);
                    }
            }
        }
        ++count;
    }
    return label;
}

}  // namespace

CavityPatches cluster_cavity_patches(const Mesh& mesh, size_t target_count) {
    if (mesh.triangles.empty()) throw Error(FABVDB_ERR_BAD_INPUT, "the part has no cavity surface");
    if (target_count == 0) throw Error(FABVDB_ERR_INVALID_ARGUMENT, "the patch count must be positive");
    const size_t n_triangles = mesh.triangles.size();
    std::vector<Eigen::Vector3d> area_normal(n_triangles), center(n_triangles);
    double total_area = 0.0;
    for (size_t t = 0; t < n_triangles; ++t) {
        const Eigen::Vector3d a = point(mesh.vertices[mesh.triangles[t][0]]);
        const Eigen::Vector3d b = point(mesh.vertices[mesh.triangles[t][1]]);
        const Eigen::Vector3d c = point(mesh.vertices[mesh.triangles[t][2]]);
        area_normal[t] = 0.5 * (b - a).cross(c - a);
        center[t] = (a + b + c) / 3.0;
        total_area += area_normal[t].norm();
    }
    const EdgeTriangles edges = edge_triangles(mesh);

    CavityPatches patches;
    std::vector<uint32_t> component = connected_labels(
        mesh, edges, [](uint32_t, uint32_t) { return true; }, patches.cavity_count);

    const double cell = std::sqrt(total_area / double(target_count));
    std::vector<std::array<int64_t, 3>> bin(n_triangles);
    for (size_t t = 0; t < n_triangles; ++t)
        for (int k = 0; k < 3; ++k) bin[t][k] = int64_t(std::floor(center[t][k] / cell));
    uint32_t patch_count = 0;
    patches.patch_of_triangle = connected_labels(
        mesh, edges, [&](uint32_t a, uint32_t b) { return bin[a] == bin[b] && component[a] == component[b]; },
        patch_count);

    std::vector<Eigen::Vector3d> centroid(patch_count, Eigen::Vector3d::Zero());
    std::vector<Eigen::Vector3d> normal(patch_count, Eigen::Vector3d::Zero());
    patches.area.assign(patch_count, 0.0);
    patches.cavity.assign(patch_count, 0);
    for (size_t t = 0; t < n_triangles; ++t) {
        const uint32_t p = patches.patch_of_triangle[t];
        const double area = area_normal[t].norm();
        patches.area[p] += area;
        centroid[p] += area * center[t];
        normal[p] += area_normal[t];
        patches.cavity[p] = component[t];
    }
    patches.centroid.resize(patch_count);
    patches.normal.resize(patch_count);
    for (uint32_t p = 0; p < patch_count; ++p) {
        if (patches.area[p] > 0) centroid[p] /= patches.area[p];
        patches.centroid[p] = vec(centroid[p]);
        // The mesh faces out of the cavity region; powder rests on the other side.
        const double length = normal[p].norm();
        patches.normal[p] = length > 0 ? vec(-normal[p] / length) : Vec3{0, 0, 1};
    }
    std::vector<double> nearest(patch_count, std::numeric_limits<double>::max());
    patches.site.resize(patch_count);
    for (size_t t = 0; t < n_triangles; ++t) {
        const uint32_t p = patches.patch_of_triangle[t];
        const double distance = (center[t] - centroid[p]).squaredNorm();
        if (distance < nearest[p]) {
            nearest[p] = distance;
            patches.site[p] = vec(center[t]);
        }
    }

    std::vector<std::map<uint32_t, double>> border(patch_count);
    for (const auto& [key, around] : edges.of_edge) {
        if (around.size() != 2) continue;
        const uint32_t a = patches.patch_of_triangle[around[0]], b = patches.patch_of_triangle[around[1]];
        if (a == b) continue;
        const double length = (point(mesh.vertices[key >> 32]) - point(mesh.vertices[key & 0xffffffffu])).norm();
        border[a][b] += length;
        border[b][a] += length;
    }
    patches.neighbours.resize(patch_count);
    for (uint32_t p = 0; p < patch_count; ++p)
        for (const auto& [other, length] : border[p]) patches.neighbours[p].push_back({other, length});
    return patches;
}

}  // namespace fabvdb::powder
