// overhang_triangles: a box resting on the plate needs no support (its
// bottom lies on the plate); a second box floating above it needs its bottom
// supported; turned upside down (up −z) the roles swap; a 90-degree process
// never needs support; a face tilted 30 degrees from vertical passes a
// 45-degree limit and fails a 20-degree one.
#include "check/overhang_triangles.h"

#include <gtest/gtest.h>

#include <cmath>

#include "support/shapes.h"

namespace fabvdb::check {
namespace {

// The triangles chosen, by the direction their normal faces (sum of unit normals).
Vec3 chosen_normal(const Mesh& mesh, const std::vector<uint8_t>& chosen, int& count) {
    Vec3 sum{0, 0, 0};
    count = 0;
    for (size_t t = 0; t < chosen.size(); ++t) {
        if (!chosen[t]) continue;
        ++count;
        const Vec3 n = triangle_normal(mesh, mesh.triangles[t]);
        const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (int k = 0; k < 3; ++k) sum[k] += n[k] / length;
    }
    return sum;
}

TEST(OverhangTriangles, BoxOnThePlateAndAFloatingOne) {
    const Mesh resting = test::make_box({0, 0, 0}, {10, 10, 5});
    int count = 0;
    overhang_triangles(resting, {0, 0, 1}, 45.0, 0.1);
    chosen_normal(resting, overhang_triangles(resting, {0, 0, 1}, 45.0, 0.1), count);
    EXPECT_EQ(count, 0);

    const Mesh two = test::merged(resting, test::make_box({20, 0, 8}, {30, 10, 9}));
    const auto chosen = overhang_triangles(two, {0, 0, 1}, 45.0, 0.1);
    const Vec3 n = chosen_normal(two, chosen, count);
    EXPECT_EQ(count, 2);  // the floating box's bottom
    EXPECT_NEAR(n[2], -2.0, 1e-12);
    // Upside down: the resting box's top and the floating box's top (the
    // floating one's bottom, at z = 8, is now above the plate at z = 9).
    const auto flipped = overhang_triangles(two, {0, 0, -1}, 45.0, 0.1);
    chosen_normal(two, flipped, count);
    EXPECT_EQ(count, 2);
    chosen_normal(two, overhang_triangles(two, {0, 0, 1}, 90.0, 0.1), count);
    EXPECT_EQ(count, 0);
}

TEST(OverhangTriangles, TiltAgainstTheLimit) {
    // One triangle above the plate tilted 30 degrees from vertical, facing down.
    const double tilt = 30.0 * M_PI / 180.0;
    Mesh mesh;
    mesh.vertices = {{0, 0, 5}, {0, 1, 5}, {std::sin(tilt), 0, 5 + std::cos(tilt)}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.triangles = {{0, 1, 2}, {3, 5, 4}};
    const Vec3 n = triangle_normal(mesh, mesh.triangles[0]);
    ASSERT_LT(n[2], 0.0);
    int count = 0;
    chosen_normal(mesh, overhang_triangles(mesh, {0, 0, 1}, 45.0, 0.01), count);
    EXPECT_EQ(count, 0);
    const auto strict = overhang_triangles(mesh, {0, 0, 1}, 20.0, 0.01);
    EXPECT_EQ(strict[0], 1);
    EXPECT_EQ(strict[1], 0);  // on the plate
}

}  // namespace
}  // namespace fabvdb::check
