//! An octahedron for tests that need a closed solid with no vertical and no
//! axis-parallel face: corners center ± (a, 0, 0), ± (0, a, 0), ± (0, 0, h),
//! outward-oriented, 6 vertices and 8 triangles; volume (4/3)·a²·h, shadow
//! along z a square of area 2a².
#pragma once

#include "core/mesh.h"

namespace fabvdb::test {

inline Mesh make_octahedron(const Vec3& center, double a, double h) {
    Mesh mesh;
    const Vec3 offsets[6] = {{a, 0, 0}, {0, a, 0}, {-a, 0, 0}, {0, -a, 0}, {0, 0, h}, {0, 0, -h}};
    for (const Vec3& o : offsets) mesh.vertices.push_back({center[0] + o[0], center[1] + o[1], center[2] + o[2]});
    for (uint32_t k = 0; k < 4; ++k) {
        const uint32_t next = (k + 1) % 4;
        mesh.triangles.push_back({k, next, 4});
        mesh.triangles.push_back({next, k, 5});
    }
    return mesh;
}

}  // namespace fabvdb::test
