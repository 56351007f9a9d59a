//! Synthetic test shapes: boxes, icospheres, tori.
#include "support/shapes.h"

#include "core/icosphere.h"
#include "support/check_vec3.h"

#include <cmath>

namespace fabvdb::test {

Mesh make_box(const Vec3& lo, const Vec3& hi) {
    Mesh mesh;
    for (int i = 0; i < 8; ++i)
        mesh.vertices.push_back({(i & 1) ? hi[0] : lo[0], (i & 2) ? hi[1] : lo[1], (i & 4) ? hi[2] : lo[2]});
    // Faces as quads (outward), each split in two triangles.
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads) {
        mesh.triangles.push_back({uint32_t(q[0]), uint32_t(q[1]), uint32_t(q[2])});
        mesh.triangles.push_back({uint32_t(q[0]), uint32_t(q[2]), uint32_t(q[3])});
    }
    return mesh;
}

Mesh make_open_box(const Vec3& lo, const Vec3& hi) {
    Mesh box = make_box(lo, hi);
    box.triangles.erase(box.triangles.begin() + 2, box.triangles.begin() + 4);  // the quad {4, 5, 7, 6}
    return box;
}

Mesh make_sphere(const Vec3& center, double radius, int levels) {
    Mesh mesh = unit_icosphere(levels);
    for (Vec3& p : mesh.vertices)
        p = {center[0] + radius * p[0], center[1] + radius * p[1], center[2] + radius * p[2]};
    return mesh;
}

Mesh make_torus(const Vec3& center, double major, double minor, int segments_major, int segments_minor) {
    Mesh mesh;
    for (int i = 0; i < segments_major; ++i) {
        const double u = 2 * M_PI * i / segments_major;
        for (int j = 0; j < segments_minor; ++j) {
            const double v = 2 * M_PI * j / segments_minor;
            const double r = major + minor * std::cos(v);
            mesh.vertices.push_back(
                {center[0] + r * std::cos(u), center[1] + r * std::sin(u), center[2] + minor * std::sin(v)});
        }
    }
    auto index = [&](int i, int j) {
        return uint32_t((i % segments_major) * segments_minor + (j % segments_minor));
    };
    for (int i = 0; i < segments_major; ++i)
        for (int j = 0; j < segments_minor; ++j) {
            const uint32_t a = index(i, j), b = index(i + 1, j), c = index(i + 1, j + 1), d = index(i, j + 1);
            mesh.triangles.push_back({a, b, c});
            mesh.triangles.push_back({a, c, d});
        }
    return mesh;
}

Mesh make_standing_torus(double major, double minor, int segments_major, int segments_minor) {
    Mesh ring = make_torus({0, 0, 0}, major, minor, segments_major, segments_minor);
    for (Vec3& p : ring.vertices) p = {p[0], -p[2], p[1]};
    return ring;
}

Mesh flipped(Mesh mesh) {
    for (Triangle& t : mesh.triangles) std::swap(t[1], t[2]);
    return mesh;
}

Mesh merged(const Mesh& a, const Mesh& b) {
    Mesh out = a;
    const uint32_t offset = uint32_t(a.vertices.size());
    out.vertices.insert(out.vertices.end(), b.vertices.begin(), b.vertices.end());
    for (Triangle t : b.triangles) out.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    return out;
}

Mesh loose_triangles(const std::vector<std::array<Vec3, 3>>& corners) {
    Mesh mesh;
    for (const auto& t : corners) {
        const uint32_t first = uint32_t(mesh.vertices.size());
        mesh.vertices.insert(mesh.vertices.end(), t.begin(), t.end());
        mesh.triangles.push_back({first, first + 1, first + 2});
    }
    return mesh;
}

Mesh unwelded(const Mesh& mesh) {
    std::vector<std::array<Vec3, 3>> corners;
    for (const auto& t : mesh.triangles) corners.push_back({mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]});
    return loose_triangles(corners);
}

double mesh_volume(const Mesh& mesh) {
    double six_volume = 0;
    for (const Triangle& t : mesh.triangles) {
        const Vec3& a = mesh.vertices[t[0]];
        const Vec3& b = mesh.vertices[t[1]];
        const Vec3& c = mesh.vertices[t[2]];
        six_volume += dot(a, cross(b, c));
    }
    return six_volume / 6.0;
}

double box_signed_distance(const Vec3& p, const Vec3& lo, const Vec3& hi) {
    double outside = 0.0, inside = -1e300;
    for (int k = 0; k < 3; ++k) {
        const double d = std::max(lo[k] - p[k], p[k] - hi[k]);
        outside += std::max(d, 0.0) * std::max(d, 0.0);
        inside = std::max(inside, d);
    }
    return outside > 0.0 ? std::sqrt(outside) : inside;
}

}  // namespace fabvdb::test
