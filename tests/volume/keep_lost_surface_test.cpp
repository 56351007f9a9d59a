// Lost input surface kept as tubes: a fin thinner than a voxel on a block,
// which the block's level set drops, comes back inside the result within
// about the radius of the fin's surface while the block's far faces stay;
// the same fin split between two parts comes back and the parts stay
// disjoint; a sphere loses
// nothing and comes back as given; bad options throw INVALID_ARGUMENT; a
// cancelled call throws CANCELLED.
#include <gtest/gtest.h>

#include <atomic>
#include <vector>

#include <openvdb/openvdb.h>
#include <openvdb/tools/Interpolation.h>

#include "core/error.h"
#include "core/progress.h"
#include "support/shapes.h"
#include "volume/keep_lost_surface.h"
#include "volume/rebuild_band.h"
#include "volume/signed_distance.h"

namespace {

using fabvdb::Mesh;
using fabvdb::Vec3;
using openvdb::FloatGrid;
using namespace fabvdb::volume;

constexpr double voxel = 0.5;

FloatGrid::Ptr level_set(const Mesh& mesh) {
    SignedDistanceOptions options;
    options.voxel_size = voxel;
    options.half_band_voxels = 4;
    fabvdb::Progress progress;
    return signed_distance_from_mesh(mesh, options, progress);
}

double value_at(const FloatGrid& grid, const Vec3& p) {
    return openvdb::tools::BoxSampler::sample(grid.tree(), grid.transform().worldToIndex(openvdb::Vec3d(p[0], p[1], p[2])));
}

KeepLostSurfaceOptions options() {
    KeepLostSurfaceOptions o;
    o.tolerance = voxel;
    o.radius = voxel;
    o.reach = 6.0;
    o.half_band_voxels = 14;
    return o;
}

// A 10 mm block with a fin 0.4 mm thick (0.8 voxel, between two planes of
// voxel centres) standing 4 mm off its top.
Mesh block_with_fin() {
    return fabvdb::test::merged(fabvdb::test::make_box({0, 0, 0}, {10, 10, 10}),
                                fabvdb::test::make_box({2, 5.05, 9}, {8, 5.45, 14}));
}

TEST(KeepLostSurface, FinThinnerThanAVoxelComesBack) {
    const Mesh input = block_with_fin();
    const FloatGrid::Ptr grid = level_set(input);
    const Vec3 fin_top{5, 5.25, 14}, fin_side{3, 5.05, 12}, far_face{5, 5, 0};
    fabvdb::Progress progress;
    // The level set has no voxel inside the fin: its zero surface lost it.
    ASSERT_GT(value_at(*rebuild_band(*grid, 0.0, 4, progress), fin_top), voxel);
    LostSurface lost;
    const std::vector<FloatGrid::Ptr> kept = keep_lost_surface({grid}, input, options(), progress, &lost);
    ASSERT_EQ(kept.size(), 1u);
    EXPECT_NE(kept[0], grid);
    EXPECT_GT(lost.lost_samples, 0u);
    EXPECT_GT(lost.lost_triangles, 0u);
    EXPECT_LT(lost.lost_samples, lost.samples);
    // The fin lies inside, about a radius below the surface.
    for (const Vec3& p : {fin_top, fin_side}) {
        EXPECT_LT(value_at(*kept[0], p), 0.0) << p[0] << " " << p[1] << " " << p[2];
        EXPECT_GT(value_at(*kept[0], p), -1.5 * voxel);
    }
    // Far from the fin nothing moved.
    EXPECT_NEAR(value_at(*kept[0], far_face), value_at(*grid, far_face), 0.1 * voxel);
    EXPECT_EQ(kept[0]->transform(), grid->transform());
    EXPECT_EQ(kept[0]->getGridClass(), openvdb::GRID_LEVEL_SET);
}

TEST(KeepLostSurface, FinSplitBetweenTwoPartsGoesToOne) {
    // The block and its fin split at y = 5.25, between voxel centres: each
    // part holds half of the block and half of the fin (0.2 mm).
    const Mesh input = block_with_fin();
    const FloatGrid::Ptr near = level_set(fabvdb::test::merged(fabvdb::test::make_box({0, 0, 0}, {10, 5.25, 10}),
                                                               fabvdb::test::make_box({2, 5.05, 9}, {8, 5.25, 14})));
    const FloatGrid::Ptr far = level_set(fabvdb::test::merged(fabvdb::test::make_box({0, 5.25, 0}, {10, 10, 10}),
                                                              fabvdb::test::make_box({2, 5.25, 9}, {8, 5.45, 14})));
    const Vec3 near_side{5, 5.05, 13}, far_side{5, 5.45, 13}, top{4, 5.25, 14};
    fabvdb::Progress progress;
    // Neither part's zero surface has its half of the fin.
    ASSERT_GT(std::min(value_at(*rebuild_band(*near, 0.0, 4, progress), top),
                       value_at(*rebuild_band(*far, 0.0, 4, progress), top)),
              voxel);
    LostSurface lost;
    const std::vector<FloatGrid::Ptr> kept = keep_lost_surface({near, far}, input, options(), progress, &lost);
    ASSERT_EQ(kept.size(), 2u);
    EXPECT_GT(lost.lost_triangles, 0u);
    for (const Vec3& p : {near_side, far_side, top}) {
        const double inside = std::min(value_at(*kept[0], p), value_at(*kept[1], p));
        EXPECT_LT(inside, 0.0) << p[0] << " " << p[1] << " " << p[2];
        EXPECT_GT(inside, -1.5 * voxel);
    }
    // Disjoint: no voxel inside both.
    const auto other = kept[1]->getConstAccessor();
    size_t both = 0;
    for (auto v = kept[0]->cbeginValueOn(); v; ++v)
        if (*v < 0 && other.getValue(v.getCoord()) < 0) ++both;
    EXPECT_EQ(both, 0u);
}

TEST(KeepLostSurface, NothingLostComesBackAsGiven) {
    const Mesh input = fabvdb::test::make_sphere({0, 0, 0}, 4.0, 4);
    const FloatGrid::Ptr grid = level_set(input);
    fabvdb::Progress progress;
    LostSurface lost;
    const std::vector<FloatGrid::Ptr> kept = keep_lost_surface({grid}, input, options(), progress, &lost);
    ASSERT_EQ(kept.size(), 1u);
    EXPECT_EQ(kept[0], grid);
    EXPECT_GT(lost.samples, 1000u);
    EXPECT_EQ(lost.lost_samples, 0u);
}

TEST(KeepLostSurface, BadOptionsThrowInvalidArgument) {
    const Mesh input = fabvdb::test::make_box({0, 0, 0}, {4, 4, 4});
    const FloatGrid::Ptr grid = level_set(input);
    fabvdb::Progress progress;
    KeepLostSurfaceOptions bad = options();
    bad.radius = 0;
    for (const KeepLostSurfaceOptions& o : {bad, options()}) {
        try {
            keep_lost_surface(o.radius > 0 ? std::vector<FloatGrid::Ptr>{} : std::vector<FloatGrid::Ptr>{grid},
                              input, o, progress);
            FAIL() << "accepted";
        } catch (const fabvdb::Error& error) {
            EXPECT_EQ(error.status(), FABVDB_ERR_INVALID_ARGUMENT);
        }
    }
}

TEST(KeepLostSurface, CancelledCallThrowsCancelled) {
    const Mesh input = block_with_fin();
    const FloatGrid::Ptr grid = level_set(input);
    std::atomic<bool> cancel{true};
    fabvdb::Progress progress(nullptr, nullptr, &cancel);
    try {
        keep_lost_surface({grid}, input, options(), progress);
        FAIL() << "not cancelled";
    } catch (const fabvdb::Error& error) {
        EXPECT_EQ(error.status(), FABVDB_ERR_CANCELLED);
    }
}

}  // namespace
