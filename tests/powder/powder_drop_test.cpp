//! drop_cavity_powder on box cavities (0.5 mm voxels): the samples' volume is
//! the box's to within the sampling (half a cell over the box's surface);
//! every sample sits at origin + cell·spacing, within half a cell of the box,
//! and comes to rest, by the flow's main destination, on the patch of the
//! floor triangle straight below it (the floor of make_box is split along its
//! diagonal, so the side of the diagonal decides). A slab one voxel thin
//! (walls half-way between voxel centres, so its voxels make it up exactly)
//! that the coarse grid misses is sampled at its own voxels, with the slab's
//! volume. An empty cavity, a cavity whose drops meet no surface, and a
//! cancelled run are refused.
#include <gtest/gtest.h>

#include <atomic>
#include <functional>
#include <string>

#include "cavity_shapes.h"
#include "core/error.h"
#include "powder/powder_drop.h"
#include "support/hand_patches.h"
#include "support/shapes.h"

namespace {

using fabvdb::Mesh;
using fabvdb::Vec3;
using fabvdb::powder::CavityPatches;
using fabvdb::powder::OrientationFlow;
using fabvdb::powder::PowderSamples;
using fabvdb::volume::SurfaceRayCaster;

const double voxel = 0.5;
// Walls off the sampling lattice, so no sample lies on one.
const Vec3 room_lo{-5.1, -3.1, 0.1}, room_hi{5.1, 3.1, 8.1};
const double room_volume = 10.2 * 6.2 * 8.0;
const double room_area = 2 * (10.2 * 6.2 + 10.2 * 8.0 + 6.2 * 8.0);

//! A patch per triangle of make_box, so the two floor triangles (0: the side
//! of the diagonal towards −x, +y; 1: the other) are patches of their own.
CavityPatches patch_per_triangle() {
    CavityPatches patches;
    for (uint32_t t = 0; t < 12; ++t) patches.patch_of_triangle.push_back(t);
    return patches;
}

//! Gravity down, and each patch's powder resting where `destination` says.
OrientationFlow falling_down(std::vector<uint32_t> destination) {
    OrientationFlow flow;
    flow.gravity = {0, 0, -1};
    flow.main_destination = std::move(destination);
    return flow;
}

std::vector<uint32_t> identity(uint32_t n) {
    std::vector<uint32_t> id(n);
    for (uint32_t i = 0; i < n; ++i) id[i] = i;
    return id;
}

PowderSamples drop(const openvdb::FloatGrid& cavity, const Mesh& surface, const OrientationFlow& flow,
                   size_t max_samples) {
    const SurfaceRayCaster caster(surface);
    fabvdb::Progress progress;
    return fabvdb::powder::drop_cavity_powder(cavity, patch_per_triangle(), caster, flow, max_samples, "room.stl",
                                              progress);
}

void expect_bad_input(const std::function<void()>& call, const std::string& text) {
    try {
        call();
        ADD_FAILURE() << "no exception: " << text;
    } catch (const fabvdb::Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_BAD_INPUT);
        EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    }
}

}  // namespace

TEST(PowderDrop, SamplesFillTheBoxAndRestOnTheFloorBelowThem) {
    openvdb::initialize();
    const auto cavity = fabvdb::test::box(room_lo, room_hi, voxel);
    const PowderSamples samples =
        drop(*cavity, fabvdb::test::make_box(room_lo, room_hi), falling_down(identity(12)), 100000);
    EXPECT_EQ(samples.spacing, voxel);
    EXPECT_EQ(samples.sample_volume, voxel * voxel * voxel);
    EXPECT_NEAR(samples.total_volume(), room_volume, 0.5 * samples.spacing * room_area);
    ASSERT_EQ(samples.rest_patch.size(), samples.position.size());
    ASSERT_EQ(samples.cell.size(), samples.position.size());
    size_t on_each[2] = {0, 0};
    for (size_t i = 0; i < samples.position.size(); ++i) {
        const Vec3& p = samples.position[i];
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(p[k], samples.origin[k] + samples.cell[i][k] * samples.spacing, 1e-9) << "sample " << i;
            EXPECT_GT(p[k], room_lo[k] - 0.5 * samples.spacing);
            EXPECT_LT(p[k], room_hi[k] + 0.5 * samples.spacing);
        }
        const bool above_diagonal = (p[1] - room_lo[1]) * 10.2 > (p[0] - room_lo[0]) * 6.2;
        const uint32_t below = above_diagonal ? 0 : 1;
        EXPECT_EQ(samples.rest_patch[i], below) << "sample at " << p[0] << ", " << p[1];
        ++on_each[below];
    }
    EXPECT_GT(on_each[0], 0u);
    EXPECT_GT(on_each[1], 0u);
}

TEST(PowderDrop, RestPatchIsTheMainDestinationOfTheFloorHit) {
    openvdb::initialize();
    const auto cavity = fabvdb::test::box(room_lo, room_hi, voxel);
    std::vector<uint32_t> destination = identity(12);
    destination[0] = destination[1] = 7;  // the floor's powder rests on the wall y = hi
    destination[2] = destination[3] = 8;  // the ceiling's (a sample a hair above it lands there)
    const PowderSamples samples = drop(*cavity, fabvdb::test::make_box(room_lo, room_hi), falling_down(destination), 2000);
    ASSERT_FALSE(samples.position.empty());
    for (size_t i = 0; i < samples.position.size(); ++i)
        EXPECT_EQ(samples.rest_patch[i], samples.position[i][2] < room_hi[2] ? 7u : 8u) << "sample " << i;
    // About 2000 samples on a coarser grid: the volume to within its cells.
    EXPECT_GT(samples.spacing, voxel);
    EXPECT_NEAR(samples.total_volume(), room_volume, 0.5 * samples.spacing * room_area);
}

TEST(PowderDrop, SlabOneVoxelThinIsSampledAtItsVoxels) {
    openvdb::initialize();
    const Vec3 lo{-5.25, -5.25, 0.25}, hi{5.25, 5.25, 0.75};
    const auto cavity = fabvdb::test::box(lo, hi, voxel);
    const PowderSamples samples = drop(*cavity, fabvdb::test::make_box(lo, hi), falling_down(identity(12)), 10);
    EXPECT_EQ(samples.spacing, voxel);
    EXPECT_NEAR(samples.total_volume(), 10.5 * 10.5 * 0.5, 1e-9);
    for (const Vec3& p : samples.position) EXPECT_EQ(p[2], 0.5);
}

TEST(PowderDrop, RefusesAnEmptyCavityAndOneWhoseDropsMissTheSurface) {
    openvdb::initialize();
    const Mesh room = fabvdb::test::make_box(room_lo, room_hi);
    const openvdb::FloatGrid::Ptr empty = openvdb::FloatGrid::create(1.5f);
    expect_bad_input([&] { drop(*empty, room, falling_down(identity(12)), 1000); }, "the cavity is empty");
    // A surface far from the cavity: every drop misses it.
    const Mesh elsewhere = fabvdb::test::make_box({100, 100, 100}, {101, 101, 101});
    const auto cavity = fabvdb::test::box(room_lo, room_hi, voxel);
    expect_bad_input([&] { drop(*cavity, elsewhere, falling_down(identity(12)), 1000); },
                     "room.stl: its cavity holds no powder sample");
}

TEST(PowderDrop, CancelledRunThrowsCancelled) {
    openvdb::initialize();
    const auto cavity = fabvdb::test::box(room_lo, room_hi, voxel);
    const SurfaceRayCaster caster(fabvdb::test::make_box(room_lo, room_hi));
    std::atomic<bool> cancel{true};
    fabvdb::Progress cancelled(nullptr, nullptr, &cancel);
    try {
        fabvdb::powder::drop_cavity_powder(*cavity, patch_per_triangle(), caster, falling_down(identity(12)), 1000,
                                           "room.stl", cancelled);
        FAIL() << "no exception";
    } catch (const fabvdb::Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_CANCELLED);
    }
}
