// vec3_ops on exact values: each operation is the plain expression, so
// small integers and halves give exact results; normalized leaves the zero
// vector at zero.
#include "core/vec3_ops.h"

#include <gtest/gtest.h>

namespace fabvdb {
namespace {

TEST(Vec3Ops, SumsDifferencesAndScaling) {
    const Vec3 a = {1, 2, 3}, b = {0.5, -4, 8};
    EXPECT_EQ(a + b, (Vec3{1.5, -2, 11}));
    EXPECT_EQ(a - b, (Vec3{0.5, 6, -5}));
    EXPECT_EQ(2.0 * b, (Vec3{1, -8, 16}));
}

TEST(Vec3Ops, DotAndCrossProducts) {
    const Vec3 x = {1, 0, 0}, y = {0, 1, 0}, z = {0, 0, 1};
    EXPECT_EQ(cross(x, y), z);
    EXPECT_EQ(cross(y, z), x);
    EXPECT_EQ(cross(y, x), (Vec3{0, 0, -1}));
    const Vec3 a = {1, 2, 3}, b = {4, -5, 6};
    EXPECT_EQ(dot(a, b), 12.0);
    EXPECT_EQ(cross(a, b), (Vec3{27, 6, -13}));
    EXPECT_EQ(dot(cross(a, b), a), 0.0);
    EXPECT_EQ(dot(cross(a, b), b), 0.0);
}

TEST(Vec3Ops, LengthsAndDirections) {
    EXPECT_EQ(norm(Vec3{3, 4, 12}), 13.0);
    EXPECT_EQ(normalized(Vec3{0, 0, -2}), (Vec3{0, 0, -1}));
    EXPECT_EQ(normalized(Vec3{0, 0, 0}), (Vec3{0, 0, 0}));
    const Vec3 unit = normalized(Vec3{1, 2, 2});
    EXPECT_NEAR(unit[0], 1.0 / 3.0, 1e-16);
    EXPECT_NEAR(unit[1], 2.0 / 3.0, 1e-16);
    EXPECT_NEAR(norm(unit), 1.0, 1e-15);
}

}  // namespace
}  // namespace fabvdb
