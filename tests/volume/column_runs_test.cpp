// Column runs: inside runs (value < 0; 0 is outside) and zero crossings of
// hand-made columns; surface crossings of a run through spheres counted on
// blocks of the same and of a finer voxel size; the kept run is the one with
// the most crossings, then the longer, then the lower.
#include <gtest/gtest.h>

#include <vector>

#include <openvdb/openvdb.h>
#include <openvdb/tools/Composite.h>
#include <openvdb/tools/LevelSetSphere.h>

#include "volume/column_runs.h"

namespace {

using fabvdb::volume::inside_runs;
using fabvdb::volume::kept_run;
using fabvdb::volume::Run;
using fabvdb::volume::SurfaceCrossings;
using fabvdb::volume::zero_crossing;
using openvdb::Coord;

std::vector<std::pair<size_t, size_t>> runs_of(const std::vector<float>& column) {
    std::vector<std::pair<size_t, size_t>> out;
    for (const Run& run : inside_runs(column.data(), column.size())) out.emplace_back(run.start, run.end);
    return out;
}

using Pairs = std::vector<std::pair<size_t, size_t>>;

TEST(InsideRuns, HandMadeColumns) {
    EXPECT_EQ(runs_of({1, -1, -2, 1, 0, -0.5f, 1}), (Pairs{{1, 3}, {5, 6}}));
    EXPECT_EQ(runs_of({1, 0, 0, 2}), Pairs{});  // zero is outside
    EXPECT_EQ(runs_of({3, -0.1f, -0.2f, -0.3f, 0.5f}), (Pairs{{1, 4}}));
    EXPECT_EQ(runs_of({1, -1, 1, -1, 1, -1, 1}), (Pairs{{1, 2}, {3, 4}, {5, 6}}));
    EXPECT_EQ(runs_of({}), Pairs{});
    // Not a caller's column, but well defined: runs at the ends.
    EXPECT_EQ(runs_of({-1, -1, 1, -2}), (Pairs{{0, 2}, {3, 4}}));
}

TEST(ZeroCrossing, LinearBetweenTheTwoSamples) {
    const std::vector<float> column{2, -1, -1, 3, 5, -0.5f, 1.5f};
    EXPECT_NEAR(zero_crossing(column.data(), 0), 2.0 / 3.0, 1e-12);   // 2 → -1
    EXPECT_NEAR(zero_crossing(column.data(), 2), 2.25, 1e-12);        // -1 → 3
    EXPECT_NEAR(zero_crossing(column.data(), 4), 4 + 5.0 / 5.5, 1e-12);  // 5 → -0.5
    EXPECT_NEAR(zero_crossing(column.data(), 5), 5.25, 1e-12);        // -0.5 → 1.5
}

openvdb::FloatGrid::Ptr sphere(double radius, const openvdb::Vec3f& centre) {
    openvdb::initialize();
    return openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(float(radius), centre, 0.5f, 3.0f);
}

TEST(SurfaceCrossings, ARunThroughASphere) {
    // Sphere of radius 2 at the origin; block of 0.5 voxels from index -10:
    // column (10, 10) is the z axis, sample k at z = 0.5 (k - 10).
    const auto surface = sphere(2.0, {0, 0, 0});
    const auto block = openvdb::math::Transform::createLinearTransform(0.5);
    const SurfaceCrossings crossings(*block, Coord(-10, -10, -10), surface.get());
    EXPECT_EQ(crossings.count(10, 10, {4, 17}), 2u);  // samples z -3.5 .. 3.5
    EXPECT_EQ(crossings.count(10, 10, {1, 5}), 0u);   // z -5 .. -2.5, outside
    EXPECT_EQ(crossings.count(10, 10, {9, 12}), 0u);  // z -1 .. 1, inside
    EXPECT_EQ(crossings.count(10, 10, {13, 16}), 1u);  // z 1 .. 3
    EXPECT_EQ(crossings.count(0, 0, {4, 17}), 0u);    // x = y = -5: misses the sphere
    EXPECT_EQ(crossings.count(12, 10, {4, 17}), 2u);  // x = 1: still through it
    EXPECT_EQ(crossings.count(15, 10, {4, 17}), 0u);  // x = 2.5: beside it
}

TEST(SurfaceCrossings, AFinerBlockAndTwoSpheres) {
    // Spheres of radius 1.5 at z = ±3; block of 0.25 voxels from index -20:
    // column (20, 20) is the z axis, sample k at z = 0.25 (k - 20).
    auto surface = sphere(1.5, {0, 0, 3});
    openvdb::tools::csgUnion(*surface, *sphere(1.5, {0, 0, -3}));
    const auto block = openvdb::math::Transform::createLinearTransform(0.25);
    const SurfaceCrossings crossings(*block, Coord(-20, -20, -20), surface.get());
    EXPECT_EQ(crossings.count(20, 20, {1, 40}), 4u);   // z -5 .. 5
    EXPECT_EQ(crossings.count(20, 20, {1, 20}), 2u);   // z -5 .. 0: the lower sphere
    EXPECT_EQ(crossings.count(20, 20, {19, 22}), 0u);  // z -0.5 .. 0.5, between them
    EXPECT_EQ(crossings.count(27, 20, {1, 40}), 0u);   // x = 1.75: beside both
}

TEST(SurfaceCrossings, NoSurfaceCountsNothing) {
    const auto block = openvdb::math::Transform::createLinearTransform(1.0);
    const SurfaceCrossings crossings(*block, Coord(0, 0, 0), nullptr);
    EXPECT_EQ(crossings.count(0, 0, {1, 50}), 0u);
}

TEST(KeptRun, MostCrossingsThenLongerThenLower) {
    const auto surface = sphere(2.0, {0, 0, 0});
    const auto block = openvdb::math::Transform::createLinearTransform(0.5);
    const SurfaceCrossings crossings(*block, Coord(-10, -10, -10), surface.get());
    // 0 crossings and 4 long, 0 and 3 long, 1 and 3 long: the crossing wins.
    EXPECT_EQ(kept_run({{1, 5}, {9, 12}, {13, 16}}, crossings, 10, 10), 2u);
    // 1 crossing each (z -4.5 .. -1 and z 1 .. 3): the longer, wherever it is.
    EXPECT_EQ(kept_run({{2, 8}, {13, 16}}, crossings, 10, 10), 0u);
    EXPECT_EQ(kept_run({{13, 16}, {2, 8}}, crossings, 10, 10), 1u);
    // The same runs off the sphere (no crossings): the longest.
    EXPECT_EQ(kept_run({{1, 5}, {9, 12}, {13, 16}}, crossings, 0, 0), 0u);
    // Without a surface: the longest; on a full tie the lower.
    const SurfaceCrossings none(*block, Coord(-10, -10, -10), nullptr);
    EXPECT_EQ(kept_run({{1, 3}, {5, 9}, {11, 13}}, none, 10, 10), 1u);
    EXPECT_EQ(kept_run({{1, 3}, {5, 7}, {9, 11}}, none, 10, 10), 0u);
    EXPECT_EQ(kept_run({{4, 9}}, crossings, 10, 10), 0u);
}

}  // namespace
