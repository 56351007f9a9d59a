//! Bounding box, areas, signed volume and validation of the plain mesh type.
#include "core/mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"

namespace fabvdb {

double BoundingBox::diagonal() const {
    const double dx = max[0] - min[0], dy = max[1] - min[1], dz = max[2] - min[2];
    return std::sqrt(dx * dx + dy * dy + dz * dz);
}

void BoundingBox::add(const Vec3& p) {
    for (int k = 0; k < 3; ++k) {
        min[k] = std::min(min[k], p[k]);
        max[k] = std::max(max[k], p[k]);
    }
}

BoundingBox bounding_box(const Mesh& mesh, bool referenced_only) {
    BoundingBox box;
    const double inf = std::numeric_limits<double>::infinity();
    box.min = {inf, inf, inf};
    box.max = {-inf, -inf, -inf};
    if (referenced_only) {
        for (const Triangle& t : mesh.triangles)
            for (uint32_t v : t) box.add(mesh.vertices[v]);
    } else {
        for (const Vec3& p : mesh.vertices) box.add(p);
    }
    if (box.min[0] > box.max[0]) return BoundingBox{};
    return box;
}

Vec3 triangle_normal(const Mesh& mesh, const Triangle& t) {
    const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

double triangle_area(const Mesh& mesh, const Triangle& t) {
    const Vec3 n = triangle_normal(mesh, t);
    return 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

std::vector<Vec3> area_weighted_vertex_normals(const Mesh& mesh) {
    std::vector<Vec3> normals(mesh.vertices.size(), Vec3{0, 0, 0});
    for (const Triangle& t : mesh.triangles) {
        const Vec3 n = triangle_normal(mesh, t);
        for (uint32_t v : t)
            for (int k = 0; k < 3; ++k) normals[v][k] += n[k];
    }
    return normals;
}

double squared_distance(const Vec3& a, const Vec3& b) {
    const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
    return dx * dx + dy * dy + dz * dz;
}

double six_signed_tetrahedron_volume(const Vec3& a, const Vec3& b, const Vec3& c) {
    return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
           a[2] * (b[0] * c[1] - b[1] * c[0]);
}

double signed_volume(const Mesh& mesh) {
    double six_volume = 0.0;
    for (const Triangle& t : mesh.triangles)
        six_volume += six_signed_tetrahedron_volume(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
    return six_volume / 6.0;
}

void append(Mesh& to, const Mesh& from) {
    const uint32_t base = uint32_t(to.vertices.size());
    to.vertices.insert(to.vertices.end(), from.vertices.begin(), from.vertices.end());
    to.triangles.reserve(to.triangles.size() + from.triangles.size());
    for (const Triangle& t : from.triangles) to.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
}

void validate_mesh(const Mesh& mesh, const std::string& what) {
    for (size_t i = 0; i < mesh.vertices.size(); ++i)
        for (double c : mesh.vertices[i])
            if (!std::isfinite(c))
                throw Error(FABVDB_ERR_BAD_INPUT,
                            what + ": vertex " + std::to_string(i + 1) + " has a non-finite coordinate");
    const size_t n = mesh.vertices.size();
    for (size_t i = 0; i < mesh.triangles.size(); ++i)
        for (uint32_t v : mesh.triangles[i])
            if (v >= n)
                throw Error(FABVDB_ERR_BAD_INPUT, what + ": triangle " + std::to_string(i + 1) +
                                                      " uses vertex index " + std::to_string(v) + " but there are " +
                                                      std::to_string(n) + " vertices");
}

}  // namespace fabvdb
