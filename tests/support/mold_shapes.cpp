//! Test parts for mold generation (see mold_shapes.h).
#include "support/mold_shapes.h"

#include <cmath>

namespace fabvdb::test {

Mesh make_dome_shell(double outer, double inner, int rings, int segments) {
    Mesh mesh;
    auto ring_vertex = [&](double radius, int ring, int segment) {
        const double elevation = 0.5 * M_PI * double(ring) / rings;  // ring 0: the equator
        const double azimuth = 2 * M_PI * segment / segments;
        return Vec3{radius * std::cos(elevation) * std::cos(azimuth), radius * std::cos(elevation) * std::sin(azimuth),
                    radius * std::sin(elevation)};
    };
    for (double radius : {outer, inner}) {
        for (int ring = 0; ring < rings; ++ring)
            for (int s = 0; s < segments; ++s) mesh.vertices.push_back(ring_vertex(radius, ring, s));
        mesh.vertices.push_back({0, 0, radius});
    }
    const uint32_t inner_base = uint32_t(rings * segments + 1);
    auto index = [&](uint32_t base, int ring, int s) { return base + uint32_t(ring * segments + (s % segments)); };
    for (uint32_t base : {0u, inner_base}) {
        const bool outward = base == 0;
        auto add = [&](uint32_t a, uint32_t b, uint32_t c) {
            mesh.triangles.push_back(outward ? Triangle{a, b, c} : Triangle{a, c, b});
        };
        for (int ring = 0; ring + 1 < rings; ++ring)
            for (int s = 0; s < segments; ++s) {
                add(index(base, ring, s), index(base, ring, s + 1), index(base, ring + 1, s + 1));
                add(index(base, ring, s), index(base, ring + 1, s + 1), index(base, ring + 1, s));
            }
        const uint32_t pole = base + uint32_t(rings * segments);
        for (int s = 0; s < segments; ++s) add(index(base, rings - 1, s), index(base, rings - 1, s + 1), pole);
    }
    for (int s = 0; s < segments; ++s) {  // the flat ring, facing down
        mesh.triangles.push_back({index(0, 0, s), index(inner_base, 0, s + 1), index(0, 0, s + 1)});
        mesh.triangles.push_back({index(0, 0, s), index(inner_base, 0, s), index(inner_base, 0, s + 1)});
    }
    return mesh;
}

}  // namespace fabvdb::test
