// unsigned_band on an open square of two triangles in the plane z = 0
// (voxel 0.5 mm, half band 3 voxels), read back with OpenVDB's accessor:
// - at voxel centres above the square its value is the height (in world
//   units), on both sides alike (unsigned), within a tenth of a voxel;
// - no voxel farther than the band from the square is active;
// - the closest triangle of a voxel over each half is that half's.
#include <gtest/gtest.h>

#include <cmath>

#include "volume/unsigned_band.h"

namespace {

using fabvdb::Mesh;

constexpr double kVoxel = 0.5;

Mesh square() {
    Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}};
    mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
    return mesh;
}

openvdb::math::Transform::Ptr transform() { return openvdb::math::Transform::createLinearTransform(kVoxel); }

}  // namespace

TEST(UnsignedBand, ValueIsTheDistanceOnBothSides) {
    openvdb::initialize();
    fabvdb::Progress progress;
    const openvdb::FloatGrid::Ptr band = fabvdb::volume::unsigned_band(square(), *transform(), 3.0f, progress);
    const auto accessor = band->getConstAccessor();
    for (int k : {-2, -1, 1, 2}) {
        const openvdb::Coord ijk(4, 4, k);  // world (2, 2, k/2): over the middle of the square
        ASSERT_TRUE(accessor.isValueOn(ijk)) << k;
        EXPECT_NEAR(accessor.getValue(ijk), std::abs(k) * kVoxel, 0.1 * kVoxel) << k;
    }
    for (auto v = band->cbeginValueOn(); v; ++v) EXPECT_LE(std::abs(v.getCoord().z()), 4) << v.getCoord();
}

TEST(UnsignedBand, ClosestTriangleIsThatOfEachHalf) {
    openvdb::initialize();
    fabvdb::Progress progress;
    openvdb::Int32Grid closest(-1);
    fabvdb::volume::unsigned_band(square(), *transform(), 3.0f, progress, &closest);
    const auto accessor = closest.getConstAccessor();
    // World (3, 1, 0.5) lies over triangle 0 (below the diagonal x = y), (1, 3, 0.5) over triangle 1.
    EXPECT_EQ(accessor.getValue(openvdb::Coord(6, 2, 1)), 0);
    EXPECT_EQ(accessor.getValue(openvdb::Coord(2, 6, 1)), 1);
}
