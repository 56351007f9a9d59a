// The frame aligned with a direction: right-handed and orthonormal with d the
// direction made unit, e1 perpendicular to the least aligned world axis, the
// two mappings inverse to each other, meshes rotated rigidly; zero or
// non-finite directions are Error(INVALID_ARGUMENT), any other scale works.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "core/error.h"
#include "support/check_vec3.h"
#include "support/shapes.h"
#include "volume/aligned_frame.h"

namespace {

using fabvdb::Mesh;
using fabvdb::Vec3;
using fabvdb::volume::aligned_frame;
using fabvdb::volume::AlignedFrame;

using fabvdb::test::cross;
using fabvdb::test::dot;

void expect_near(const Vec3& actual, const Vec3& expected, double tolerance) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(actual[k], expected[k], tolerance) << "coordinate " << k;
}

// Checks the frame for `direction`, with e1 perpendicular to world axis `least`.
void check_frame(const Vec3& direction, int least) {
    SCOPED_TRACE(testing::Message() << "direction " << direction[0] << " " << direction[1] << " " << direction[2]);
    const AlignedFrame frame = aligned_frame(direction);
    const double length = std::hypot(direction[0], direction[1], direction[2]);
    expect_near(frame.d, {direction[0] / length, direction[1] / length, direction[2] / length}, 1e-15);
    EXPECT_NEAR(dot(frame.e1, frame.e1), 1.0, 1e-15);
    EXPECT_NEAR(dot(frame.e2, frame.e2), 1.0, 1e-15);
    EXPECT_NEAR(dot(frame.d, frame.d), 1.0, 1e-15);
    EXPECT_NEAR(dot(frame.e1, frame.e2), 0.0, 1e-15);
    EXPECT_NEAR(dot(frame.e1, frame.d), 0.0, 1e-15);
    EXPECT_NEAR(dot(frame.e2, frame.d), 0.0, 1e-15);
    // Right-handed: e1 x e2 = d.
    expect_near(cross(frame.e1, frame.e2), frame.d, 1e-15);
    EXPECT_EQ(frame.e1[least], 0.0);
}

TEST(AlignedFrame, OrthonormalRightHandedAroundTheDirection) {
    check_frame({0, 0, 1}, 0);  // x and y tie: the first one
    check_frame({0, 0, -3}, 0);
    check_frame({2, 0, 0}, 1);
    check_frame({0, -1, 0}, 0);
    check_frame({1, 2, 3}, 0);
    check_frame({5, -0.25, 3}, 1);
    check_frame({-4, 6, 0.5}, 2);
    check_frame({1, 1, 1}, 0);
}

TEST(AlignedFrame, TheTieOnZIsResolvedTheSameEveryTime) {
    const AlignedFrame first = aligned_frame({0, 0, 1}), second = aligned_frame({0, 0, 1});
    EXPECT_EQ(first.e1, second.e1);
    EXPECT_EQ(first.e2, second.e2);
    // e1 is perpendicular to x, so ±y; e2 = d x e1 is then ∓x.
    EXPECT_EQ(std::abs(first.e1[1]), 1.0);
    EXPECT_EQ(first.e2[0], -first.e1[1]);
}

TEST(AlignedFrame, MappingsAreInverse) {
    const AlignedFrame frame = aligned_frame({-1, 3, 2});
    const double length = std::sqrt(14.0);
    // The direction itself lands on +Z; e1 and e2 on X and Y.
    expect_near(frame.to_frame({-1, 3, 2}), {0, 0, length}, 1e-14);
    expect_near(frame.to_frame(frame.e1), {1, 0, 0}, 1e-15);
    expect_near(frame.to_frame(frame.e2), {0, 1, 0}, 1e-15);
    expect_near(frame.to_world({0, 0, 2}), {-2 / length, 6 / length, 4 / length}, 1e-15);
    for (const Vec3& p : std::vector<Vec3>{{0, 0, 0}, {10, -20, 30}, {0.125, 7, -3}}) {
        expect_near(frame.to_world(frame.to_frame(p)), p, 1e-13);
        expect_near(frame.to_frame(frame.to_world(p)), p, 1e-13);
    }
}

TEST(AlignedFrame, RotateMeshIsRigid) {
    const Mesh box = fabvdb::test::make_box({1, 2, 3}, {3, 5, 7});  // volume 2 * 3 * 4 = 24
    const AlignedFrame frame = aligned_frame({1, -1, 2});
    const Mesh rotated = fabvdb::volume::rotate_mesh(box, frame, false);
    EXPECT_EQ(rotated.triangles, box.triangles);
    ASSERT_EQ(rotated.vertices.size(), box.vertices.size());
    EXPECT_NEAR(fabvdb::test::mesh_volume(rotated), 24.0, 1e-12);
    for (size_t i = 0; i < box.vertices.size(); ++i)
        for (size_t j = 0; j < i; ++j)
            EXPECT_NEAR(fabvdb::squared_distance(rotated.vertices[i], rotated.vertices[j]),
                        fabvdb::squared_distance(box.vertices[i], box.vertices[j]), 1e-12);
    // The z of a rotated vertex is its height along the direction.
    for (size_t i = 0; i < box.vertices.size(); ++i) {
        const Vec3& p = box.vertices[i];
        EXPECT_NEAR(rotated.vertices[i][2], (p[0] - p[1] + 2 * p[2]) / std::sqrt(6.0), 1e-13);
    }
    const Mesh back = fabvdb::volume::rotate_mesh(rotated, frame, true);
    EXPECT_EQ(back.triangles, box.triangles);
    for (size_t i = 0; i < box.vertices.size(); ++i) expect_near(back.vertices[i], box.vertices[i], 1e-13);
}

TEST(AlignedFrame, ZeroOrNonFiniteDirectionIsInvalid) {
    const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
    for (const Vec3& bad : std::vector<Vec3>{{0, 0, 0}, {-0.0, 0, 0}, {inf, 0, 0}, {1, -inf, 0}, {0, 0, nan}}) {
        try {
            aligned_frame(bad);
            ADD_FAILURE() << "no error for " << bad[0] << " " << bad[1] << " " << bad[2];
        } catch (const fabvdb::Error& error) {
            EXPECT_EQ(error.status(), FABVDB_ERR_INVALID_ARGUMENT);
        }
    }
}

TEST(AlignedFrame, AnyFiniteNonZeroScale) {
    // Finite and non-zero, so a valid frame; the squared length under- or
    // overflows a double, which must not matter.
    check_frame({1e-300, 0, 0}, 1);
    check_frame({0, 1e-160, 0}, 0);
    check_frame({0, 0, 1e160}, 0);
    check_frame({1e300, 2e300, 3e300}, 0);
}

}  // namespace
