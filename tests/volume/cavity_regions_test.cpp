// split_cavity_regions on boxes whose voids are known: one void (volume 1),
// a void with a floating island (64 − 1, the island apart), two voids in
// their outer shells' order with each island in its own, nested voids where
// an island joins the smallest outer shell around it and the inner void is
// marked as lying in an island (in either listing order), an island in no
// void (dropped) and an empty surface.
#include "volume/cavity_regions.h"

#include <gtest/gtest.h>

#include "support/ray_cast.h"
#include "support/shapes.h"

namespace fabvdb::volume {
namespace {

using test::flipped;
using test::make_box;
using test::merged;

Mesh cube(double lo, double hi) { return make_box({lo, lo, lo}, {hi, hi, hi}); }

TEST(CavityRegions, OneVoid) {
    const std::vector<CavityRegion> regions = split_cavity_regions(make_box({1, 2, 3}, {2, 4, 6}));
    ASSERT_EQ(regions.size(), 1u);
    EXPECT_NEAR(regions[0].volume, 6.0, 1e-12);
    EXPECT_EQ(regions[0].surface.vertices.size(), 8u);
    EXPECT_EQ(regions[0].surface.triangles.size(), 12u);
    EXPECT_TRUE(test::closed_two_manifold(regions[0].surface));
    EXPECT_NEAR(test::mesh_volume(regions[0].surface), 6.0, 1e-12);
}

TEST(CavityRegions, IslandBelongsToTheVoidAroundIt) {
    // A 4 mm void with a 1 mm solid island floating in it (facing into the island).
    const std::vector<CavityRegion> regions = split_cavity_regions(merged(cube(0, 4), flipped(cube(1, 2))));
    ASSERT_EQ(regions.size(), 1u);
    EXPECT_NEAR(regions[0].volume, 64.0 - 1.0, 1e-12);
    EXPECT_NEAR(regions[0].island_volume, 1.0, 1e-12);
    EXPECT_FALSE(regions[0].in_island);
    EXPECT_EQ(regions[0].surface.vertices.size(), 8u);
    EXPECT_EQ(regions[0].surface.triangles.size(), 12u);
    EXPECT_TRUE(test::closed_two_manifold(regions[0].surface));
    EXPECT_NEAR(test::mesh_volume(regions[0].surface), 64.0, 1e-12);
    EXPECT_EQ(regions[0].islands.triangles.size(), 12u);
    EXPECT_NEAR(test::mesh_volume(regions[0].islands), -1.0, 1e-12);
}

TEST(CavityRegions, SeparateVoidsInTheOrderOfTheirOuterShells) {
    // The island of the first void listed last, after the second void.
    const Mesh surface =
        merged(merged(make_box({10, 0, 0}, {12, 2, 2}), cube(0, 4)), flipped(make_box({1, 1, 1}, {3, 2, 2})));
    const std::vector<CavityRegion> regions = split_cavity_regions(surface);
    ASSERT_EQ(regions.size(), 2u);
    EXPECT_NEAR(regions[0].volume, 8.0, 1e-12);
    EXPECT_EQ(regions[0].surface.triangles.size(), 12u);
    EXPECT_NEAR(regions[1].volume, 64.0 - 2.0, 1e-12);
    EXPECT_EQ(regions[1].surface.triangles.size(), 12u);
    EXPECT_EQ(regions[1].islands.triangles.size(), 12u);
    EXPECT_TRUE(regions[0].islands.triangles.empty());
    // Each region's surface holds its own vertices only.
    for (const Vec3& p : regions[0].surface.vertices) EXPECT_GE(p[0], 10.0);
    for (const Vec3& p : regions[1].surface.vertices) EXPECT_LE(p[0], 4.0);
}

TEST(CavityRegions, NestedVoidsTakeTheSmallestOuterShell) {
    // A void [0, 10]³ around a solid [1, 9]³, inside which is a void [2, 8]³
    // around a solid [4, 5]³. The inner island lies inside both outer
    // shells and belongs to the smaller.
    const Mesh big = cube(0, 10), big_island = flipped(cube(1, 9)), small = cube(2, 8), small_island = flipped(cube(4, 5));
    for (bool small_first : {false, true}) {
        SCOPED_TRACE(testing::Message() << "small first " << small_first);
        const Mesh surface = small_first ? merged(merged(small, small_island), merged(big, big_island))
                                         : merged(merged(big, big_island), merged(small, small_island));
        const std::vector<CavityRegion> regions = split_cavity_regions(surface);
        ASSERT_EQ(regions.size(), 2u);
        const CavityRegion& outer = regions[small_first ? 1 : 0];
        const CavityRegion& inner = regions[small_first ? 0 : 1];
        EXPECT_NEAR(outer.volume, 1000.0 - 512.0, 1e-9);
        EXPECT_NEAR(inner.volume, 216.0 - 1.0, 1e-9);
        EXPECT_EQ(outer.surface.triangles.size(), 12u);
        EXPECT_EQ(outer.islands.triangles.size(), 12u);
        EXPECT_EQ(inner.surface.triangles.size(), 12u);
        EXPECT_EQ(inner.islands.triangles.size(), 12u);
        EXPECT_NEAR(outer.island_volume, 512.0, 1e-9);
        // The inner void lies in the outer void's island.
        EXPECT_FALSE(outer.in_island);
        EXPECT_TRUE(inner.in_island);
    }
}

TEST(CavityRegions, IslandOutsideEveryVoidBoundsNone) {
    const std::vector<CavityRegion> regions = split_cavity_regions(merged(cube(0, 1), flipped(cube(5, 6))));
    ASSERT_EQ(regions.size(), 1u);
    EXPECT_NEAR(regions[0].volume, 1.0, 1e-12);
    EXPECT_EQ(regions[0].surface.triangles.size(), 12u);
    // Islands alone: no void at all.
    EXPECT_TRUE(split_cavity_regions(flipped(cube(5, 6))).empty());
    EXPECT_TRUE(split_cavity_regions(Mesh{}).empty());
}

}  // namespace
}  // namespace fabvdb::volume
