// thin_sheets on thin regions whose holding is known by construction (0.3 mm
// sheets, the regions under 0.6 mm as the wall check finds them): a wall
// standing on a block is held along its foot only (one loop: a fin); a panel
// in a frame is two regions of one sheet held all round (two loops); the
// walls of a tray on a thick floor are held at their outer and inner foot
// (two loops); a closed thin-walled box is thin all over (no loop); a
// region's border loops shorter than the minimum are not counted; on
// surfaces given outright, a strip wrapped round its rim with one loop is a
// fin and a patch of one face with one loop is not (it faces one way).
#include "check/thin_sheets.h"

#include <gtest/gtest.h>

#include "support/shapes.h"
#include "volume/extract_mesh.h"
#include "volume/local_thickness.h"
#include "volume/signed_distance.h"

namespace fabvdb::check {
namespace {

constexpr double kVoxel = 0.06, kLimit = 0.6;

struct Reading {
    std::vector<SheetReading> sheets;
    std::vector<surface::TriangleRegion> regions;
};

Reading read(const Mesh& mesh, double min_loop = M_PI * kLimit) {
    volume::SignedDistanceOptions options;
    options.voxel_size = kVoxel;
    options.half_band_voxels = 12;  // the walk's reach (0.3 mm) and the ridge fit's samples beyond it
    Progress progress;
    const auto grid = volume::signed_distance_from_mesh(mesh, options, progress);
    const Mesh surface = volume::extract_mesh(*grid, 0.0, progress);
    const auto walls =
        volume::local_thickness(*grid, surface.vertices, volume::ThicknessSide::solid, kLimit / 2, progress);
    std::vector<uint8_t> chosen(surface.triangles.size());
    for (size_t t = 0; t < chosen.size(); ++t) {
        double sum = 0.0;
        for (uint32_t v : surface.triangles[t]) sum += walls.thickness[v];
        chosen[t] = sum / 3.0 < kLimit ? 1 : 0;
    }
    Reading reading;
    reading.regions = surface::triangle_regions(surface, chosen);
    reading.sheets = thin_sheets(surface, reading.regions, walls.centre, kVoxel, min_loop);
    return reading;
}

//! The regions of at least `area` mm²: those a test is about, not a crumb
//! the threshold might leave.
std::vector<size_t> large(const Reading& reading, double area) {
    std::vector<size_t> chosen;
    for (size_t r = 0; r < reading.regions.size(); ++r)
        if (reading.regions[r].area >= area) chosen.push_back(r);
    return chosen;
}

Mesh frame_around(double lo, double hi, double size, double height) {
    Mesh frame = test::make_box({0, 0, 0}, {lo, size, height});
    frame = test::merged(frame, test::make_box({hi, 0, 0}, {size, size, height}));
    frame = test::merged(frame, test::make_box({lo, 0, 0}, {hi, lo, height}));
    return test::merged(frame, test::make_box({lo, hi, 0}, {hi, size, height}));
}

TEST(ThinSheets, WallOnABlockIsAFin) {
    const Reading r = read(test::merged(test::make_box({0, 0, 0}, {8, 6, 2}), test::make_box({3.85, 1, 1.5}, {4.15, 5, 5})));
    const auto regions = large(r, 1.0);
    ASSERT_EQ(regions.size(), 1u);
    EXPECT_TRUE(r.sheets[regions[0]].fin);
    EXPECT_EQ(r.sheets[regions[0]].held_edges, 1);
    // Both faces (2 x 4 x 3 mm² above the root, a little less where the
    // root reads thick) and the rim make the region.
    EXPECT_GT(r.regions[regions[0]].area, 0.8 * 24.0);
}

TEST(ThinSheets, PanelInAFrameIsHeldAllRound) {
    const Reading r = read(test::merged(frame_around(3, 7, 10, 4), test::make_box({3, 3, 1.85}, {7, 7, 2.15})));
    const auto regions = large(r, 1.0);
    ASSERT_EQ(regions.size(), 2u);  // its two faces
    EXPECT_EQ(r.sheets[regions[0]].sheet, r.sheets[regions[1]].sheet);
    for (size_t k : regions) {
        EXPECT_FALSE(r.sheets[k].fin);
        EXPECT_EQ(r.sheets[k].held_edges, 2);
    }
}

TEST(ThinSheets, TrayAndClosedBoxAreWalls) {
    // Thin walls 0.3 mm around a 6 x 6 tray on a 2 mm floor: held at the
    // outer and the inner foot.
    const Mesh walls = frame_around(0.3, 5.7, 6, 5);
    const Reading tray = read(test::merged(walls, test::make_box({-1, -1, -1.5}, {7, 7, 0.5})));
    const auto tray_regions = large(tray, 1.0);
    ASSERT_EQ(tray_regions.size(), 1u);
    EXPECT_FALSE(tray.sheets[tray_regions[0]].fin);
    EXPECT_EQ(tray.sheets[tray_regions[0]].held_edges, 2);

    const Reading closed = read(test::merged(test::make_box({0, 0, 0}, {5, 4, 3}),
                                             test::flipped(test::make_box({0.3, 0.3, 0.3}, {4.7, 3.7, 2.7}))));
    const auto closed_regions = large(closed, 1.0);
    ASSERT_EQ(closed_regions.size(), 2u);  // the outer surface and the cavity's
    for (size_t k : closed_regions) {
        EXPECT_FALSE(closed.sheets[k].fin);
        EXPECT_EQ(closed.sheets[k].held_edges, 0);
    }
}

TEST(ThinSheets, ShortLoopsDoNotCount) {
    // The fin's root loop is about 2 x (4 + 0.3) mm long: with a longer
    // minimum it no longer counts, and the fin is held nowhere.
    const Reading r = read(test::merged(test::make_box({0, 0, 0}, {8, 6, 2}), test::make_box({3.85, 1, 1.5}, {4.15, 5, 5})),
                           20.0);
    const auto regions = large(r, 1.0);
    ASSERT_EQ(regions.size(), 1u);
    EXPECT_FALSE(r.sheets[regions[0]].fin);
    EXPECT_EQ(r.sheets[regions[0]].held_edges, 0);
    EXPECT_TRUE(thin_sheets(Mesh{}, {}, {}, kVoxel, 1.0).empty());
}

TEST(ThinSheets, OneFacedPatchIsNoFin) {
    // A 0.3 x 4 x 3 mm box open at its top: both faces, the ends and the
    // rim, bordered by one loop 8.6 mm long; its normals nearly cancel.
    const Mesh wrapped = test::make_open_box({0, 0, 0}, {0.3, 4, 3});
    const std::vector<Vec3> centres(wrapped.vertices.size(), Vec3{0.15, 2, 1.5});
    const auto one = surface::triangle_regions(wrapped, std::vector<uint8_t>(wrapped.triangles.size(), 1));
    ASSERT_EQ(one.size(), 1u);
    const SheetReading fin = thin_sheets(wrapped, one, centres, kVoxel, 1.0)[0];
    EXPECT_EQ(fin.held_edges, 1);
    EXPECT_TRUE(fin.two_sided);
    EXPECT_TRUE(fin.fin);

    // Its -x face alone: one loop 14 mm long too, but it faces one way.
    Mesh face;
    face.vertices = {{0, 0, 0}, {0, 4, 0}, {0, 4, 3}, {0, 0, 3}};
    face.triangles = {{0, 2, 1}, {0, 3, 2}};
    const auto patch = surface::triangle_regions(face, {1, 1});
    const SheetReading one_faced = thin_sheets(face, patch, std::vector<Vec3>(4, Vec3{0.15, 2, 1.5}), kVoxel, 1.0)[0];
    EXPECT_EQ(one_faced.held_edges, 1);
    EXPECT_FALSE(one_faced.two_sided);
    EXPECT_FALSE(one_faced.fin);
}

}  // namespace
}  // namespace fabvdb::check
