// Fan triangulation of polygon faces: n corners give the n-2 triangles
// (c0, ci, ci+1) in order, appended after earlier triangles; a convex polygon
// keeps its orientation and area; corner indices are not range-checked here.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "core/mesh.h"
#include "io/polygon_fan.h"

namespace {

using fabvdb::Mesh;
using fabvdb::Triangle;
using fabvdb::Vec3;

TEST(PolygonFan, TriangleStaysOneTriangle) {
    Mesh mesh;
    const uint32_t corners[] = {4, 7, 2};
    fabvdb::io::add_polygon_fan(mesh, corners, 3);
    EXPECT_EQ(mesh.triangles, (std::vector<Triangle>{{4, 7, 2}}));
}

TEST(PolygonFan, HexagonGivesFourTrianglesInOrderAfterEarlierOnes) {
    Mesh mesh;
    mesh.triangles = {{9, 8, 7}};
    const uint32_t corners[] = {10, 11, 12, 13, 14, 15};
    fabvdb::io::add_polygon_fan(mesh, corners, 6);
    EXPECT_EQ(mesh.triangles,
              (std::vector<Triangle>{{9, 8, 7}, {10, 11, 12}, {10, 12, 13}, {10, 13, 14}, {10, 14, 15}}));
}

TEST(PolygonFan, IndicesAreTakenAsGiven) {
    Mesh mesh;  // no vertices at all: range checks come later, not here
    const uint32_t corners[] = {1000000, 5, 4294967295u, 3};
    EXPECT_NO_THROW(fabvdb::io::add_polygon_fan(mesh, corners, 4));
    EXPECT_EQ(mesh.triangles, (std::vector<Triangle>{{1000000, 5, 4294967295u}, {1000000, 4294967295u, 3}}));
    EXPECT_TRUE(mesh.vertices.empty());
}

TEST(PolygonFan, ConvexPolygonKeepsOrientationAndArea) {
    // A regular pentagon of circumradius 2 in the plane z = 1, counter-clockwise
    // seen from +z: area 5/2 · r² · sin(72°).
    Mesh mesh;
    std::vector<uint32_t> corners;
    for (int i = 0; i < 5; ++i) {
        const double angle = 2.0 * M_PI * i / 5.0;
        mesh.vertices.push_back({2.0 * std::cos(angle), 2.0 * std::sin(angle), 1.0});
        corners.push_back(uint32_t(i));
    }
    fabvdb::io::add_polygon_fan(mesh, corners.data(), corners.size());
    ASSERT_EQ(mesh.triangles.size(), 3u);
    double area = 0.0;
    for (const Triangle& t : mesh.triangles) {
        const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
        // z component of (b - a) x (c - a): twice the signed area seen from +z.
        const double twice = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        EXPECT_GT(twice, 0.0);
        area += 0.5 * twice;
    }
    EXPECT_NEAR(area, 2.5 * 4.0 * std::sin(72.0 * M_PI / 180.0), 1e-12);
}

}  // namespace
