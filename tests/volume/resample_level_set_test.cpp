// A level set carried onto a turned transform by sampling: a sphere's band
// holds the sphere's exact distance (analytic) within a voxel, its inside and
// outside keep their signs, an enclosed cavity stays outside, a coarser grid
// works too; smaller voxels are refused and a cancelled call throws.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>

#include <openvdb/openvdb.h>
#include <openvdb/tools/Composite.h>
#include <openvdb/tools/LevelSetSphere.h>

#include "core/error.h"
#include "core/progress.h"
#include "volume/resample_level_set.h"
#include "volume/sweep.h"

namespace {

using openvdb::FloatGrid;
using openvdb::Vec3d;

constexpr double voxel = 0.25;
const Vec3d centre(0.3, -0.2, 0.1);

FloatGrid::Ptr sphere(float radius) {
    openvdb::initialize();
    return openvdb::tools::createLevelSetSphere<FloatGrid>(radius, openvdb::Vec3f(centre), float(voxel), 3.0f);
}

double sphere_distance(const Vec3d& p, double radius) { return (p - centre).length() - radius; }

float value_at(const FloatGrid& grid, const Vec3d& p) {
    return grid.tree().getValue(grid.transform().worldToIndexNodeCentered(p));
}

//! Band voxels within `check` of the surface by `distance` agree to `tolerance`.
template <typename Distance>
void expect_distances(const FloatGrid& grid, Distance distance, double check, double tolerance) {
    int checked = 0;
    for (auto value = grid.cbeginValueOn(); value; ++value) {
        const Vec3d p = grid.indexToWorld(value.getCoord());
        const double expected = distance(p);
        if (std::abs(expected) > check) continue;
        ++checked;
        ASSERT_NEAR(*value, expected, tolerance) << "at " << p;
    }
    EXPECT_GT(checked, 500);
}

const openvdb::math::Transform::Ptr turned = fabvdb::volume::aligned_transform(voxel, {1.0, 0.5, 0.2});

TEST(ResampleLevelSet, ATurnedSphereKeepsItsDistances) {
    const auto grid = sphere(3.0f);
    grid->setName("part");
    fabvdb::Progress progress;
    const auto out = fabvdb::volume::resample_level_set(*grid, *turned, progress);
    EXPECT_EQ(out->getGridClass(), openvdb::GRID_LEVEL_SET);
    EXPECT_EQ(out->getName(), "part");
    EXPECT_EQ(out->transform(), *turned);
    EXPECT_EQ(out->background(), grid->background());
    // Trilinear interpolation of the exact distance sags by h²/(8ρ) along
    // each of the three axes, ρ >= 2.5 within two voxels: 0.0094 at most.
    const auto distance = [](const Vec3d& p) { return sphere_distance(p, 3.0); };
    expect_distances(*out, distance, 2 * voxel, 0.0094);
    // Every voxel of the new grid within two voxels of the surface is in its band.
    int missed = 0;
    for (double x = -4; x <= 4; x += 0.1)
        for (double y = -4; y <= 4; y += 0.1) {
            const Vec3d p = centre + Vec3d(x, y, 0.7);
            const double d = sphere_distance(p, 3.0);
            if (std::abs(d) < 2 * voxel && std::abs(value_at(*out, p)) >= out->background()) ++missed;
        }
    EXPECT_EQ(missed, 0);
    EXPECT_EQ(value_at(*out, centre), -out->background());
    EXPECT_EQ(value_at(*out, centre + Vec3d(4, 4, 0)), out->background());
}

TEST(ResampleLevelSet, AnEnclosedCavityStaysOutside) {
    auto shell = sphere(3.0f);
    openvdb::tools::csgDifference(*shell, *sphere(1.5f));
    fabvdb::Progress progress;
    const auto out = fabvdb::volume::resample_level_set(*shell, *turned, progress);
    EXPECT_GT(value_at(*out, centre), 0.0f);
    EXPECT_GT(value_at(*out, centre + Vec3d(0, 0, 1.0)), 0.0f);
    EXPECT_LT(value_at(*out, centre + Vec3d(2.25, 0, 0)), 0.0f);
    EXPECT_GT(value_at(*out, centre + Vec3d(0, 4.5, 0)), 0.0f);
    const auto wall = [](const Vec3d& p) { return std::max(sphere_distance(p, 3.0), -sphere_distance(p, 1.5)); };
    expect_distances(*out, wall, voxel, 0.02);
}

TEST(ResampleLevelSet, CoarserVoxelsWorkSmallerAreRefused) {
    const auto grid = sphere(3.0f);
    fabvdb::Progress progress;
    const auto coarse = fabvdb::volume::resample_level_set(*grid, *fabvdb::volume::aligned_transform(0.4, {0, 1, 1}),
                                                           progress);
    expect_distances(*coarse, [](const Vec3d& p) { return sphere_distance(p, 3.0); }, 0.4, 0.01);
    try {
        fabvdb::volume::resample_level_set(*grid, *fabvdb::volume::aligned_transform(0.2, {0, 0, 1}), progress);
        FAIL() << "smaller voxels accepted";
    } catch (const fabvdb::Error& error) {
        EXPECT_EQ(error.status(), FABVDB_ERR_INVALID_ARGUMENT);
    }
}

TEST(ResampleLevelSet, CancelledCallThrowsCancelled) {
    const auto grid = sphere(2.0f);
    std::atomic<bool> cancel{true};
    fabvdb::Progress progress(nullptr, nullptr, &cancel);
    try {
        fabvdb::volume::resample_level_set(*grid, *turned, progress);
        FAIL() << "not cancelled";
    } catch (const fabvdb::Error& error) {
        EXPECT_EQ(error.status(), FABVDB_ERR_CANCELLED);
    }
}

}  // namespace
