//! gyroid_infill with cell 4 mm, strut 1 mm, in a box cavity on a 0.25 mm
//! grid (so the nodes fall on voxels). Worked by hand: the gyroid
//! sin x cos y + sin y cos z + sin z cos x (period 1 cell) is 3·½ = 3/2 at
//! (1, 1, 1)/8 of a cell, a node, so the voxel there is strut (+r); it is −3/2
//! at (3, 3, 3)/8, on the other labyrinth's skeleton √3/4 of a cell from the
//! nearest strut, so that voxel stays void. Carving only adds material
//! (carved ≥ cavity, the outside stays material), keeps transform and
//! background, and on a whole cell equals max(cavity, r − distance to the
//! struts) with the struts listed here from the eight nodes (gyroid = 3/2)
//! of a cell. The memory estimate grows as the struts' area over the voxel
//! squared. Bad lattices and a cancelled run are refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <string>

#include "core/error.h"
#include "support/plain_level_set.h"
#include "support/shapes.h"
#include "volume/gyroid_infill.h"

namespace {

using fabvdb::volume::GyroidStruts;

const double voxel = 0.25;
const GyroidStruts lattice{4.0, 1.0};

openvdb::FloatGrid::Ptr box_cavity() {
    openvdb::initialize();
    return fabvdb::test::plain_level_set(fabvdb::test::make_box({-6, -6, -6}, {6, 6, 6}), voxel);
}

double gyroid_at_cell_fraction(double x, double y, double z) {
    const double a = 2 * M_PI * x, b = 2 * M_PI * y, c = 2 * M_PI * z;
    return std::sin(a) * std::cos(b) + std::sin(b) * std::cos(c) + std::sin(c) * std::cos(a);
}

template <class Call>
void expect_invalid(Call call, const std::string& text) {
    try {
        call();
        ADD_FAILURE() << "no exception";
    } catch (const fabvdb::Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_INVALID_ARGUMENT);
        EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    }
}

}  // namespace

TEST(GyroidInfill, ValidatesTheLattice) {
    EXPECT_NO_THROW(fabvdb::volume::validate_gyroid_struts({4.0, 1.0}));  // exactly a quarter
    expect_invalid([] { fabvdb::volume::validate_gyroid_struts({0.0, 0.5}); }, "cell must be > 0");
    expect_invalid([] { fabvdb::volume::validate_gyroid_struts({NAN, 0.5}); }, "cell must be > 0");
    expect_invalid([] { fabvdb::volume::validate_gyroid_struts({4.0, 0.0}); }, "strut must be > 0");
    expect_invalid([] { fabvdb::volume::validate_gyroid_struts({4.0, INFINITY}); }, "strut must be > 0");
    expect_invalid([] { fabvdb::volume::validate_gyroid_struts({4.0, 1.01}); }, "quarter of the cell");
    fabvdb::Progress progress;
    const auto cavity = box_cavity();
    expect_invalid([&] { fabvdb::volume::carve_gyroid_struts(*cavity, {4.0, 2.0}, progress); }, "quarter of the cell");
}

TEST(GyroidInfill, NodeIsStrutAndTheOtherLabyrinthStaysVoid) {
    ASSERT_NEAR(gyroid_at_cell_fraction(1 / 8.0, 1 / 8.0, 1 / 8.0), 1.5, 1e-12);
    ASSERT_NEAR(gyroid_at_cell_fraction(3 / 8.0, 3 / 8.0, 3 / 8.0), -1.5, 1e-12);
    const auto cavity = box_cavity();
    fabvdb::Progress progress;
    const auto carved = fabvdb::volume::carve_gyroid_struts(*cavity, lattice, progress);
    const auto in = carved->getConstAccessor();
    const auto before = cavity->getConstAccessor();
    // (0.5, 0.5, 0.5) mm is voxel (2, 2, 2): on the strut axis, r = 0.5 inside the strut.
    EXPECT_NEAR(in.getValue(openvdb::Coord(2, 2, 2)), 0.5f, 1e-6);
    // The same node one cell over, (4.5, 0.5, 0.5) mm: too near the wall to be void anyway.
    EXPECT_GT(in.getValue(openvdb::Coord(18, 2, 2)), 0.0f);
    // (1.5, 1.5, 1.5) mm is voxel (6, 6, 6): √3 mm from the struts, beyond r and the band.
    EXPECT_LT(before.getValue(openvdb::Coord(6, 6, 6)), 0.0f);
    EXPECT_EQ(in.getValue(openvdb::Coord(6, 6, 6)), before.getValue(openvdb::Coord(6, 6, 6)));
    EXPECT_EQ(carved->transform(), cavity->transform());
    EXPECT_EQ(carved->background(), cavity->background());
}

TEST(GyroidInfill, CarvingOnlyAddsMaterialInsideTheCavity) {
    const auto cavity = box_cavity();
    fabvdb::Progress progress;
    const auto carved = fabvdb::volume::carve_gyroid_struts(*cavity, lattice, progress);
    const auto in = carved->getConstAccessor();
    const auto before = cavity->getConstAccessor();
    const openvdb::CoordBBox box(openvdb::Coord(-32), openvdb::Coord(32));
    for (auto it = box.begin(); it; ++it) {
        const float was = before.getValue(*it), now = in.getValue(*it);
        EXPECT_GE(now, was) << *it;
        // Outside, max(cavity, r − distance) stays material and rises to r at most.
        if (was > 0.0f) EXPECT_LE(now, std::max(was, 0.5f)) << "outside the cavity at " << *it;
    }
}

TEST(GyroidInfill, CarvedValueIsRadiusMinusTheDistanceToTheStruts) {
    // The struts worked out here: the eight nodes of a cell (where the gyroid
    // is 3/2), each joined to the three nodes √2/4 of a cell away (periodic
    // images included); on the voxels of the cell at the origin, deep in the
    // cavity, carved = max(cavity, r − distance to the nearest strut).
    const std::vector<openvdb::Vec3d> cell_nodes{{1, 1, 1}, {1, 7, 3}, {3, 1, 7}, {3, 7, 5},
                                                 {5, 3, 7}, {5, 5, 5}, {7, 3, 1}, {7, 5, 3}};
    std::vector<openvdb::Vec3d> nodes;  // in mm, the cell at the origin and its neighbours
    for (const auto& n : cell_nodes) {
        ASSERT_NEAR(gyroid_at_cell_fraction(n.x() / 8, n.y() / 8, n.z() / 8), 1.5, 1e-12) << n;
        for (int dx = -1; dx <= 1; ++dx)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dz = -1; dz <= 1; ++dz) nodes.push_back((n / 8.0 + openvdb::Vec3d(dx, dy, dz)) * lattice.cell);
    }
    const double strut_length = std::sqrt(2.0) / 4 * lattice.cell;
    std::vector<std::pair<openvdb::Vec3d, openvdb::Vec3d>> struts;
    for (const auto& a : nodes) {
        int degree = 0;
        for (const auto& b : nodes)
            if (std::abs((b - a).length() - strut_length) < 1e-9) {
                ++degree;
                struts.emplace_back(a, b);
            }
        if (a.x() >= 0 && a.x() < lattice.cell && a.y() >= 0 && a.y() < lattice.cell && a.z() >= 0 &&
            a.z() < lattice.cell)
            EXPECT_EQ(degree, 3) << a;
    }
    const auto distance_to_struts = [&](const openvdb::Vec3d& p) {
        double best = 1e300;
        for (const auto& [a, b] : struts) {
            const openvdb::Vec3d ab = b - a;
            const double t = std::clamp((p - a).dot(ab) / ab.lengthSqr(), 0.0, 1.0);
            best = std::min(best, (p - (a + ab * t)).length());
        }
        return best;
    };
    const auto cavity = box_cavity();
    fabvdb::Progress progress;
    const auto carved = fabvdb::volume::carve_gyroid_struts(*cavity, lattice, progress);
    const auto in = carved->getConstAccessor();
    const auto before = cavity->getConstAccessor();
    const double r = 0.5 * lattice.strut;
    size_t strut_voxels = 0;
    const openvdb::CoordBBox cell(openvdb::Coord(0), openvdb::Coord(15));
    for (auto it = cell.begin(); it; ++it) {
        const openvdb::Vec3d p = carved->transform().indexToWorld(*it);
        const double expected = std::max(double(before.getValue(*it)), r - distance_to_struts(p));
        EXPECT_NEAR(in.getValue(*it), expected, 1e-5) << *it;
        strut_voxels += expected > 0;
    }
    // About the struts' share of the volume: 12 cylinders of radius r and
    // length √2/4·cell fill 21% of it, less where they overlap at the nodes.
    EXPECT_GT(double(strut_voxels) / 4096, 0.12);
    EXPECT_LT(double(strut_voxels) / 4096, 0.21);
}

TEST(GyroidInfill, EstimateScalesWithTheStrutAreaOverTheVoxelSquared) {
    // The struts' surface grows with the cavity's volume, and a band a fixed
    // number of voxels deep around it has area / voxel² voxels: the extra
    // bytes of a second cavity volume are the same as of a third, and four
    // times as many at half the voxel (differences cancel any fixed overhead).
    const auto bytes = [](double volume, double voxel) {
        return double(fabvdb::volume::estimate_gyroid_struts_bytes(lattice, volume, voxel));
    };
    const double step = bytes(2e5, 0.25) - bytes(1e5, 0.25);
    EXPECT_GT(step, 0.0);
    EXPECT_NEAR(bytes(3e5, 0.25) - bytes(2e5, 0.25), step, 1e-3 * step);
    EXPECT_NEAR(bytes(2e5, 0.125) - bytes(1e5, 0.125), 4 * step, 1e-3 * 4 * step);
}

TEST(GyroidInfill, CancelledRunThrowsCancelled) {
    const auto cavity = box_cavity();
    std::atomic<bool> cancel{true};
    fabvdb::Progress cancelled(nullptr, nullptr, &cancel);
    try {
        fabvdb::volume::carve_gyroid_struts(*cavity, lattice, cancelled);
        FAIL() << "no exception";
    } catch (const fabvdb::Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_CANCELLED);
    }
}
