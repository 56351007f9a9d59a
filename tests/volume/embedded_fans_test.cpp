// embedded_fans on fans whose answer is known by construction: a flat
// disc's centre is embedded wherever it lies inside its ring and not outside
// it; a convex cone's apex and every corner of a convex solid are; a fan
// that winds twice (a pentagram), a pinch of two cones, an open fan, fans of
// fewer than 3 or more than 64 triangles are not; only the candidates'
// vertices are computed.
#include "volume/embedded_fans.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "support/shapes.h"

namespace fabvdb::volume {
namespace {

// Vertex 0 at `centre`, vertices 1..n on the unit circle around the z axis at
// height `height`, the k-th at angle k × `step` (radians), and the triangles
// (0, k, k + 1), the last closing back to 1.
Mesh fan(const Vec3& centre, int n, double step, double height = 0.0) {
    Mesh mesh;
    mesh.vertices.push_back(centre);
    for (int k = 0; k < n; ++k) mesh.vertices.push_back({std::cos(k * step), std::sin(k * step), height});
    for (uint32_t k = 1; k <= uint32_t(n); ++k) mesh.triangles.push_back({0, k, k % uint32_t(n) + 1});
    return mesh;
}

TEST(EmbeddedFans, FlatDiscCentreInsideItsRing) {
    const Mesh disc = fan({0, 0, 0}, 6, M_PI / 3);
    const std::vector<char> embedded = embedded_fans(disc);
    ASSERT_EQ(embedded.size(), 7u);
    EXPECT_TRUE(embedded[0]);
    // The ring's vertices have open fans of two triangles.
    for (size_t v = 1; v < 7; ++v) EXPECT_FALSE(embedded[v]) << v;
    // Off centre but inside the hexagon (its edges are 0.866 from the
    // centre): still one to one.
    EXPECT_TRUE(embedded_fans(fan({0.8, 0, 0}, 6, M_PI / 3))[0]);
    // Outside the ring: some triangles turn the other way.
    EXPECT_FALSE(embedded_fans(fan({1.5, 0, 0}, 6, M_PI / 3))[0]);
}

TEST(EmbeddedFans, ConesAndConvexSolids) {
    // A cone's apex, above or below its ring, and a saddle (the ring up and
    // down): each projects one to one along its summed normal.
    EXPECT_TRUE(embedded_fans(fan({0, 0, 1}, 5, 2 * M_PI / 5))[0]);
    EXPECT_TRUE(embedded_fans(fan({0, 0, -1}, 5, 2 * M_PI / 5))[0]);
    Mesh saddle = fan({0, 0, 0}, 6, M_PI / 3);
    for (size_t v = 1; v < 7; ++v) saddle.vertices[v][2] = v % 2 ? 0.5 : -0.5;
    EXPECT_TRUE(embedded_fans(saddle)[0]);
    for (const Mesh& solid : {test::make_box({0, 0, 0}, {1, 2, 3}), test::make_sphere({0, 0, 0}, 1.0, 2)}) {
        const std::vector<char> embedded = embedded_fans(solid);
        EXPECT_EQ(std::count(embedded.begin(), embedded.end(), 1), std::ptrdiff_t(solid.vertices.size()));
    }
}

TEST(EmbeddedFans, AFanThatWindsTwiceIsNot) {
    // Five triangles each turning 144°: a closed cycle of positive turns
    // that covers every direction twice.
    const Mesh pentagram = fan({0, 0, 0}, 5, 4 * M_PI / 5);
    EXPECT_FALSE(embedded_fans(pentagram)[0]);
    // The same ring in order (72° turns) is a pentagon: embedded.
    EXPECT_TRUE(embedded_fans(fan({0, 0, 0}, 5, 2 * M_PI / 5))[0]);
}

TEST(EmbeddedFans, TwoConesTipToTipAreNot) {
    // One apex with two closed fans, one above and one below it.
    Mesh pinch = fan({0, 0, 0}, 4, M_PI / 2, 1.0);
    Mesh lower = fan({0, 0, 0}, 4, -M_PI / 2, -1.0);
    const uint32_t shift = uint32_t(pinch.vertices.size()) - 1;
    for (size_t v = 1; v < lower.vertices.size(); ++v) pinch.vertices.push_back(lower.vertices[v]);
    for (Triangle t : lower.triangles) {
        for (uint32_t& v : t) v = v == 0 ? 0 : v + shift;
        pinch.triangles.push_back(t);
    }
    EXPECT_FALSE(embedded_fans(pinch)[0]);
    // Each cone alone is.
    EXPECT_TRUE(embedded_fans(fan({0, 0, 0}, 4, M_PI / 2, 1.0))[0]);
}

TEST(EmbeddedFans, FanSizesFromThreeToSixtyFour) {
    // Two triangles back to back close a cycle but are too few.
    EXPECT_FALSE(embedded_fans(fan({0, 0, 1}, 2, M_PI))[0]);
    EXPECT_TRUE(embedded_fans(fan({0, 0, 1}, 3, 2 * M_PI / 3))[0]);
    EXPECT_TRUE(embedded_fans(fan({0, 0, 1}, 64, 2 * M_PI / 64))[0]);
    EXPECT_FALSE(embedded_fans(fan({0, 0, 1}, 65, 2 * M_PI / 65))[0]);
}

TEST(EmbeddedFans, OnlyTheCandidatesVerticesAreComputed) {
    const Mesh box = test::make_box({0, 0, 0}, {1, 1, 1});
    std::vector<char> candidates(box.triangles.size(), 0);
    EXPECT_EQ(embedded_fans(box, candidates), std::vector<char>(8, 0));
    candidates[0] = 1;  // the triangle (0, 2, 3)
    EXPECT_EQ(embedded_fans(box, candidates), (std::vector<char>{1, 0, 1, 1, 0, 0, 0, 0}));
}

}  // namespace
}  // namespace fabvdb::volume
