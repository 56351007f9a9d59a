// Moving a model far from the origin near it and back: the offset is the
// box centre along far axes only, and the round trip gives the input back
// bit for bit.
#include <gtest/gtest.h>

#include <cmath>

#include "core/centred_frame.h"

namespace {

using fabvdb::Mesh;

Mesh triangle_at(const fabvdb::Vec3& a, const fabvdb::Vec3& b, const fabvdb::Vec3& c) {
    Mesh mesh;
    mesh.vertices = {a, b, c};
    mesh.triangles = {{0, 1, 2}};
    return mesh;
}

TEST(CentredFrame, FarAxesAreCentredAndComeBackExactly) {
    const Mesh far = triangle_at({631234.123456789, 3980578.987654321, 0.1}, {635311.0000001, 3984982.33, -0.2},
                                 {632000.5, 3981000.25, 8708.75});
    const fabvdb::CentredFrame frame = fabvdb::centred_frame(far);
    EXPECT_DOUBLE_EQ(frame.offset[0], 0.5 * (631234.123456789 + 635311.0000001));
    EXPECT_DOUBLE_EQ(frame.offset[1], 0.5 * (3980578.987654321 + 3984982.33));
    EXPECT_EQ(frame.offset[2], 0.0);  // from -0.2 to 8708.75: not far along z
    Mesh local = fabvdb::to_local(far, frame);
    for (const fabvdb::Vec3& p : local.vertices) {
        EXPECT_LE(std::abs(p[0]), 2100.0);
        EXPECT_LE(std::abs(p[1]), 2300.0);
    }
    fabvdb::to_world(local, frame);
    EXPECT_EQ(local.vertices, far.vertices);
}

TEST(CentredFrame, ModelsAroundTheOriginStayPut) {
    const Mesh near = triangle_at({-5, 1, 2}, {10, 3, 4}, {1, 20, 9});
    EXPECT_TRUE(fabvdb::centred_frame(near).identity());
    EXPECT_TRUE(fabvdb::centred_frame(Mesh{}).identity());
}

}  // namespace
