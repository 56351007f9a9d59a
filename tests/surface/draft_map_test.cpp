// The draft/undercut map on synthetic shapes with known answers: on a sphere
// along z, caps are positive or negative, a belt around the equator needs
// draft (|n·z| < sin φ) and nothing is an undercut; on a torus around z seen
// along x, the inner wall facing the hole is an undercut (its ray crosses the
// hole into the other side) while the outer wall is not; along the torus'
// axis nothing is. Classes are checked against the normals and positions
// computed here from the triangles.
#include <gtest/gtest.h>

#include <cmath>

#include "support/shapes.h"
#include "surface/draft_map.h"
#include "core/vec3_ops.h"

namespace {

using namespace fabvdb;
using namespace fabvdb::surface;

Shell shell_of(const Mesh& mesh) {
    return make_shell(mesh, mesh.vertices, std::vector<int>(mesh.triangles.size(), -1), 0.1, "test");
}

Vec3 centre_of(const Shell& s, size_t t) {
    const Triangle& f = s.outer.triangles[t];
    return (1.0 / 3.0) * (s.outer.vertices[f[0]] + s.outer.vertices[f[1]] + s.outer.vertices[f[2]]);
}

TEST(DraftMap, SphereAlongZ) {
    const Shell s = shell_of(test::make_sphere({0, 0, 0}, 10, 4));
    const double draft = 5 * M_PI / 180;
    const std::vector<uint8_t> classes = draft_map(s, {0, 0, 3}, draft);
    ASSERT_EQ(classes.size(), s.triangle_count());
    size_t needs = 0;
    for (size_t t = 0; t < classes.size(); ++t) {
        const double c = dot(s.normal[t], Vec3{0, 0, 1});
        const uint8_t expected = std::abs(c) < std::sin(draft) ? needs_draft : c > 0 ? draft_positive : draft_negative;
        EXPECT_EQ(classes[t], expected) << "triangle " << t;
        needs += classes[t] == needs_draft;
    }
    EXPECT_GT(needs, 0u);
}

TEST(DraftMap, TorusInnerWallIsAnUndercutAcross) {
    const Shell s = shell_of(test::make_torus({0, 0, 0}, 10, 3, 48, 24));
    const std::vector<uint8_t> across = draft_map(s, {1, 0, 0}, M_PI / 180);
    size_t inner_facing = 0, outer_facing = 0;
    for (size_t t = 0; t < across.size(); ++t) {
        const Vec3 c = centre_of(s, t);
        const double ring = std::hypot(c[0], c[1]);
        const double nx = s.normal[t][0];
        if (std::abs(c[1]) > 3 || std::abs(nx) < 0.3) continue;  // near the x axis, clearly facing ±x
        if (ring < 9 && c[0] < 0 && nx > 0) {  // inner wall at x < 0, facing the hole (+x)
            EXPECT_EQ(across[t], undercut) << "triangle " << t;
            ++inner_facing;
        }
        if (ring > 11 && c[0] > 0 && nx > 0) {  // outer wall at x > 0, facing out (+x)
            EXPECT_EQ(across[t], draft_positive) << "triangle " << t;
            ++outer_facing;
        }
    }
    EXPECT_GT(inner_facing, 0u);
    EXPECT_GT(outer_facing, 0u);
    for (uint8_t c : draft_map(s, {0, 0, 1}, M_PI / 180)) EXPECT_NE(c, undercut);
}

}  // namespace
