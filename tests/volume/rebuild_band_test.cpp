// A fresh band around an iso-surface: a sphere level set with its values
// scaled (no longer distances) comes back as distances to the extracted
// surface (brute force over its triangles) and to the sphere; an isovalue > 0
// grows it by that much; an enclosed cavity stays outside (OpenVDB's
// levelSetRebuild would fill it); name, transform and class are kept; a
// cancelled call throws CANCELLED.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <vector>

#include <openvdb/openvdb.h>
#include <openvdb/tools/Composite.h>
#include <openvdb/tools/LevelSetSphere.h>
#include <openvdb/tools/VolumeToMesh.h>

#include "core/error.h"
#include "core/progress.h"
#include "volume/closest_point_on_triangle.h"
#include "volume/rebuild_band.h"

namespace {

using openvdb::FloatGrid;
using openvdb::Vec3d;

constexpr double voxel = 0.25;
const Vec3d centre(0.3, -0.2, 0.1);

FloatGrid::Ptr sphere(float radius, float half_width = 3.0f) {
    openvdb::initialize();
    return openvdb::tools::createLevelSetSphere<FloatGrid>(radius, openvdb::Vec3f(centre), float(voxel), half_width);
}

//! Band voxels within `check` of the surface by `distance` of their world position agree to `tolerance`.
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

double sphere_distance(const Vec3d& p, double radius) { return (p - centre).length() - radius; }

TEST(RebuildBand, ScaledValuesBecomeDistancesAgain) {
    const auto grid = sphere(3.0f);
    grid->setName("part");
    // Twice the distance: the same zero crossings, wrong values.
    for (auto value = grid->beginValueOn(); value; ++value) value.setValue(2.0f * *value);
    fabvdb::Progress progress;
    const auto rebuilt = fabvdb::volume::rebuild_band(*grid, 0.0, 3, progress);
    ASSERT_TRUE(rebuilt);
    EXPECT_EQ(rebuilt->getGridClass(), openvdb::GRID_LEVEL_SET);
    EXPECT_EQ(rebuilt->getName(), "part");
    EXPECT_EQ(rebuilt->transform(), grid->transform());
    EXPECT_NEAR(rebuilt->background(), 3 * voxel, 1e-6);  // 3 voxels on each side
    for (auto value = rebuilt->cbeginValueOn(); value; ++value) ASSERT_LE(std::abs(*value), 3 * voxel + 1e-5);
    // The sphere's distance, less the chords' sag (~0.01 at 0.25 mm on radius 3),
    // closely within a voxel, a little less closely within two.
    expect_distances(*rebuilt, [](const Vec3d& p) { return sphere_distance(p, 3.0); }, voxel, 0.015);
    expect_distances(*rebuilt, [](const Vec3d& p) { return sphere_distance(p, 3.0); }, 2 * voxel, 0.03);
    // Off the band: signs from the flood fill.
    const auto at = [&](const Vec3d& p) {
        return rebuilt->tree().getValue(rebuilt->transform().worldToIndexNodeCentered(p));
    };
    EXPECT_EQ(at(centre), -rebuilt->background());
    EXPECT_EQ(at(centre + Vec3d(5, 5, 0)), rebuilt->background());
}

TEST(RebuildBand, WithinAVoxelTheDistanceToTheExtractedSurfaceIsExact) {
    const auto grid = sphere(2.0f);
    fabvdb::Progress progress;
    const auto rebuilt = fabvdb::volume::rebuild_band(*grid, 0.0, 3, progress);
    // The zero surface by OpenVDB, with quads split; distances by brute force.
    std::vector<openvdb::Vec3s> points;
    std::vector<openvdb::Vec3I> triangles;
    std::vector<openvdb::Vec4I> quads;
    openvdb::tools::volumeToMesh(*grid, points, triangles, quads, 0.0, 0.0);
    for (const auto& q : quads) {
        triangles.emplace_back(q[0], q[1], q[2]);
        triangles.emplace_back(q[0], q[2], q[3]);
    }
    ASSERT_GT(triangles.size(), 100u);
    int checked = 0, index = 0;
    for (auto value = rebuilt->cbeginValueOn(); value; ++value) {
        if (++index % 3) continue;  // a third of them keeps it fast
        const Vec3d p = rebuilt->indexToWorld(value.getCoord());
        double nearest = 1e9;
        for (const auto& t : triangles) {
            const auto on = fabvdb::volume::closest_point_on_triangle(p, Vec3d(points[t[0]]), Vec3d(points[t[1]]),
                                                                      Vec3d(points[t[2]]));
            nearest = std::min(nearest, (on.point - p).length());
        }
        if (nearest > voxel) continue;
        ++checked;
        const double sign = sphere_distance(p, 2.0) < 0 ? -1.0 : 1.0;
        ASSERT_NEAR(*value, sign * nearest, 2e-3) << "at " << p;
    }
    EXPECT_GT(checked, 200);
}

TEST(RebuildBand, APositiveIsovalueGrowsTheSurface) {
    // A wider input band, so the values around 0.5 are distances.
    const auto grid = sphere(2.5f, 6.0f);
    fabvdb::Progress progress;
    const auto rebuilt = fabvdb::volume::rebuild_band(*grid, 0.5, 3, progress);
    expect_distances(*rebuilt, [](const Vec3d& p) { return sphere_distance(p, 3.0); }, voxel, 0.015);
    expect_distances(*rebuilt, [](const Vec3d& p) { return sphere_distance(p, 3.0); }, 2 * voxel, 0.03);
    // A wider band when asked.
    const auto wide = fabvdb::volume::rebuild_band(*grid, 0.0, 5, progress);
    EXPECT_NEAR(wide->background(), 5 * voxel, 1e-6);
    double widest = 0.0;
    for (auto value = wide->cbeginValueOn(); value; ++value) widest = std::max(widest, double(std::abs(*value)));
    EXPECT_GT(widest, 4 * voxel);
    EXPECT_LE(widest, 5 * voxel + 1e-5);
}

TEST(RebuildBand, AnEnclosedCavityStaysOutside) {
    // A ball of radius 3 with a spherical cavity of radius 1.5.
    auto shell = sphere(3.0f);
    openvdb::tools::csgDifference(*shell, *sphere(1.5f));
    fabvdb::Progress progress;
    const auto rebuilt = fabvdb::volume::rebuild_band(*shell, 0.0, 3, progress);
    const auto at = [&](const Vec3d& p) {
        return rebuilt->tree().getValue(rebuilt->transform().worldToIndexNodeCentered(p));
    };
    EXPECT_GT(at(centre), 0.0f);                      // the cavity's centre, 1.5 from its wall
    EXPECT_GT(at(centre + Vec3d(0, 0, 1.0)), 0.0f);   // in the cavity, 0.5 from the wall
    EXPECT_LT(at(centre + Vec3d(2.25, 0, 0)), 0.0f);  // mid-wall
    EXPECT_GT(at(centre + Vec3d(0, 4.5, 0)), 0.0f);   // outside
    const auto wall = [](const Vec3d& p) { return std::max(sphere_distance(p, 3.0), -sphere_distance(p, 1.5)); };
    // The cavity's chords sag more (radius 1.5, up to ~0.03).
    expect_distances(*rebuilt, wall, voxel, 0.04);
    expect_distances(*rebuilt, wall, 2 * voxel, 0.05);
}

TEST(RebuildBand, CancelledCallThrowsCancelled) {
    const auto grid = sphere(2.0f);
    std::atomic<bool> cancel{true};
    fabvdb::Progress progress(nullptr, nullptr, &cancel);
    try {
        fabvdb::volume::rebuild_band(*grid, 0.0, 3, progress);
        FAIL() << "not cancelled";
    } catch (const fabvdb::Error& error) {
        EXPECT_EQ(error.status(), FABVDB_ERR_CANCELLED);
    }
}

}  // namespace
