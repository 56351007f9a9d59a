// Coordinates as float-storing files hold them: rounding to the nearest
// float (checked against nextafterf neighbours, not against a cast), the
// float-grid test, a local point's stored position in a far frame, and the
// float step over a box there.
#include <gtest/gtest.h>

#include <cmath>

#include "core/float_coordinates.h"

namespace {

TEST(FloatCoordinates, RoundsToTheNearestFloat) {
    const float a = 170.381f;
    const float above = std::nextafterf(a, 1000.0f);
    const double quarter = 0.25 * (double(above) - double(a));
    EXPECT_EQ(fabvdb::nearest_float(double(a) + quarter), double(a));
    EXPECT_EQ(fabvdb::nearest_float(double(above) - quarter), double(above));
    const fabvdb::Vec3 p = fabvdb::nearest_float(fabvdb::Vec3{double(a) + quarter, -double(a) - quarter, 0.1});
    EXPECT_EQ(p[0], double(a));
    EXPECT_EQ(p[1], -double(a));
    EXPECT_NE(p[2], 0.1);  // 0.1 is no float
    EXPECT_EQ(float(p[2]), 0.1f);
}

TEST(FloatCoordinates, FloatGridAndStoredPositions) {
    fabvdb::Mesh mesh;
    mesh.vertices = {{1.5, 2.25, -3.0}, {170.25, 0.0, 1e-3}};
    EXPECT_FALSE(fabvdb::on_float_grid(mesh));  // 1e-3 is no float
    mesh.vertices[1][2] = double(1e-3f);
    EXPECT_TRUE(fabvdb::on_float_grid(mesh));

    // A point in a frame 4 km off stores to a float step of 2^-12 mm there.
    fabvdb::CentredFrame frame;
    frame.offset = {4000.0, 0.0, 0.0};
    const fabvdb::Vec3 local{0.1, 0.1, 0.0};
    const fabvdb::Vec3 stored = fabvdb::stored_position(local, frame);
    EXPECT_EQ(stored[0] + 4000.0, double(float(4000.1)));
    EXPECT_EQ(stored[1], double(0.1f));
    EXPECT_LE(std::abs(stored[0] - local[0]), std::ldexp(1.0, -13));

    // The step over a box: 2^-12 mm at 4 km, 2 mm at 25 km (2^24 .. 2^25 mm).
    fabvdb::BoundingBox box;
    box.min = {-10, -10, -10};
    box.max = {10, 10, 10};
    EXPECT_EQ(fabvdb::float_step_over(box, frame), std::ldexp(1.0, -12));
    frame.offset = {0.0, -2.5e7, 0.0};
    EXPECT_EQ(fabvdb::float_step_over(box, frame), 2.0);
}

}  // namespace
