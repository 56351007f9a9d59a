// The fidelity gate, on shapes whose answer is known by construction: the
// input itself passes with nothing far; a sliver of it, one of its two
// shells, an open sheet beside it, a copy moved by a wall's width or the
// input turned inside out fail,
// each for the reason it should (the far share, or the volume: a soup wound
// every which way has none to compare); the union of
// overlapping shells, an inside-out copy and an open box against its closed
// one pass; slit walls narrower than far may close; exempt balls leave what
// they hold out. Expected volumes and
// distances come from the shapes' construction, not from the code tested.
#include "volume/input_fidelity.h"

#include <gtest/gtest.h>

#include <atomic>
#include <utility>

#include "core/error.h"
#include "support/shapes.h"

namespace fabvdb::volume {
namespace {

FidelityLimits limits(double distance, double far_share) {
    FidelityLimits l;
    l.distance = distance;
    l.far_share = far_share;
    return l;
}

TEST(InputFidelity, TheInputItselfPasses) {
    Progress progress;
    const Mesh ball = test::make_sphere({1, 2, 3}, 10, 3);
    const Fidelity exact = measure_fidelity(ball, ball, exact_limits(ball), progress);
    EXPECT_TRUE(exact.passed) << exact.defect;
    EXPECT_FALSE(exact.volume_compared);
    const Fidelity f = measure_fidelity(ball, ball, voxel_limits(0.2), progress);
    EXPECT_TRUE(f.passed) << f.defect;
    EXPECT_EQ(f.samples, kFidelitySamples);
    EXPECT_LT(f.max, 1e-9);
    EXPECT_EQ(f.far_share, 0.0);
    // The estimate of the ball's volume is within its tolerance.
    EXPECT_NEAR(f.input_volume, test::mesh_volume(ball), f.volume_tolerance);
    EXPECT_NEAR(f.output_volume, test::mesh_volume(ball), 1e-9 * test::mesh_volume(ball));
}

// The model gone: an 8-triangle sliver 0.3 mm across where a 20 mm ball was.
TEST(InputFidelity, ASliverOfTheModelFails) {
    Progress progress;
    const Mesh ball = test::make_sphere({0, 0, 0}, 10, 3);
    const Mesh sliver = test::make_box({9.7, -0.15, -0.15}, {10.0, 0.15, 0.15});
    const Fidelity f = measure_fidelity(ball, sliver, voxel_limits(0.2), progress);
    EXPECT_FALSE(f.passed);
    EXPECT_GT(f.far_share, 0.95);
    EXPECT_GT(f.max, 15.0);
    EXPECT_NE(f.defect.find("farther than 0.4 mm"), std::string::npos) << f.defect;
    EXPECT_NE(f.defect.find("encloses"), std::string::npos) << f.defect;
    try {
        require_faithful(f, "scan.stl", "repaired solid");
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_INTERNAL);
        EXPECT_NE(std::string(e.what()).find("scan.stl: the repaired solid is not the input's model"),
                  std::string::npos)
            << e.what();
    }
}

// Two boxes far apart, and only one kept: half the surface is far.
TEST(InputFidelity, OneOfTwoShellsLostFails) {
    Progress progress;
    const Mesh a = test::make_box({0, 0, 0}, {10, 10, 10});
    const Mesh both = test::merged(a, test::make_box({30, 0, 0}, {40, 10, 10}));
    const Fidelity f = measure_fidelity(both, a, voxel_limits(0.2), progress);
    EXPECT_FALSE(f.passed);
    EXPECT_NEAR(f.far_share, 0.5, 0.03);
    EXPECT_NEAR(f.output_volume, 1000.0, 1e-9);
}

// Moved by 1 mm, more than two voxels of 0.2 mm: every face but the ones
// the move slides along is far.
TEST(InputFidelity, AMovedCopyFails) {
    Progress progress;
    const Mesh box = test::make_box({0, 0, 0}, {10, 10, 10});
    const Mesh moved = test::make_box({1, 0, 0}, {11, 10, 10});
    const Fidelity f = measure_fidelity(box, moved, voxel_limits(0.2), progress);
    EXPECT_FALSE(f.passed);
    EXPECT_NEAR(f.max, 1.0, 1e-9);
}

// Everything of the input on the output, but the output turned inside out
// encloses a negative volume: only the volume tells.
TEST(InputFidelity, AnInsideOutOutputFailsOnItsVolume) {
    Progress progress;
    const Mesh ball = test::make_sphere({0, 0, 0}, 10, 3);
    const Fidelity f = measure_fidelity(ball, test::flipped(ball), voxel_limits(0.2), progress);
    EXPECT_FALSE(f.passed);
    EXPECT_TRUE(f.volume_compared);
    EXPECT_LT(f.max, 1e-9);
    EXPECT_NE(f.defect.find("it encloses -"), std::string::npos) << f.defect;
}

// A soup wound every which way (a ball with every third triangle turned:
// its winding number about ⅓ inside) has no volume its winding number
// tells: not compared.
TEST(InputFidelity, ASoupWithoutAWindingVolumeIsNotComparedByVolume) {
    Progress progress;
    const Mesh ball = test::make_sphere({0, 0, 0}, 10, 3);
    Mesh soup = ball;
    for (size_t i = 0; i < soup.triangles.size(); i += 3) std::swap(soup.triangles[i][1], soup.triangles[i][2]);
    const Fidelity f = measure_fidelity(soup, ball, voxel_limits(0.2), progress);
    EXPECT_FALSE(f.volume_compared);
}

// Overlapping shells: their inner faces bound no solid and are left out;
// the union passes. The union of two boxes overlapping by half is the box
// they span.
TEST(InputFidelity, TheUnionOfOverlappingShellsPasses) {
    Progress progress;
    const Mesh shells = test::merged(test::make_box({0, 0, 0}, {10, 10, 10}), test::make_box({5, 0, 0}, {15, 10, 10}));
    const Mesh unite = test::make_box({0, 0, 0}, {15, 10, 10});
    EXPECT_TRUE(measure_fidelity(shells, unite, exact_limits(shells), progress).passed);
    const Fidelity f = measure_fidelity(shells, unite, voxel_limits(0.2), progress);
    EXPECT_TRUE(f.passed) << f.defect;
    EXPECT_GT(f.left_out, 0u);
    EXPECT_LE(f.max, 0.4);  // inner faces nearer than far count as they are
    EXPECT_NEAR(f.input_volume, 1500.0, f.volume_tolerance);
}

// Two boxes 0.1 mm apart, and one box over both (the slit closed): its
// walls may close where far is 0.4 mm, not where it is 0.04 mm.
TEST(InputFidelity, SlitsNarrowerThanFarMayClose) {
    Progress progress;
    const Mesh two = test::merged(test::make_box({0, 0, 0}, {10, 10, 10}), test::make_box({10.1, 0, 0}, {20, 10, 10}));
    const Mesh closed = test::make_box({0, 0, 0}, {20, 10, 10});
    const Fidelity coarse = measure_fidelity(two, closed, voxel_limits(0.2), progress);
    EXPECT_TRUE(coarse.passed) << coarse.defect;
    EXPECT_GT(coarse.left_out, 0u);
    const Fidelity fine = measure_fidelity(two, closed, voxel_limits(0.02), progress);
    EXPECT_FALSE(fine.passed);
    EXPECT_NEAR(fine.far_share, 200.0 / 1196.0, 0.02);  // the two walls: 200 of 1196 mm²
}

TEST(InputFidelity, InsideOutInputAgainstItsOutwardSolidPasses) {
    Progress progress;
    const Mesh ball = test::make_sphere({0, 0, 0}, 10, 3);
    EXPECT_TRUE(measure_fidelity(test::flipped(ball), ball, exact_limits(ball), progress).passed);
    const Fidelity f = measure_fidelity(test::flipped(ball), ball, voxel_limits(0.2), progress);
    EXPECT_TRUE(f.passed) << f.defect;
    EXPECT_NEAR(f.input_volume, test::mesh_volume(ball), f.volume_tolerance);
}

// An open box's solid is the box its winding number closes.
TEST(InputFidelity, AnOpenInputAgainstItsClosedSolidPasses) {
    Progress progress;
    const Mesh open_box = test::make_open_box({0, 0, 0}, {10, 10, 10});
    const Fidelity f = measure_fidelity(open_box, test::make_box({0, 0, 0}, {10, 10, 10}), voxel_limits(0.2),
                                        progress);
    EXPECT_TRUE(f.passed) << f.defect;
}

// The top of a 20 mm box moved down by 1 mm: the top face (a sixth of the
// surface) is far. A ball of 5 mm around the top's middle exempts a fifth of
// it, which is not enough; one that holds the whole top passes it.
TEST(InputFidelity, ExemptBallsLeaveWhatTheyHoldOut) {
    Progress progress;
    const Mesh box = test::make_box({0, 0, 0}, {20, 20, 20});
    const Mesh lowered = test::make_box({0, 0, 0}, {20, 20, 19});
    FidelityLimits l = limits(0.05, 0.01);
    l.volume = false;
    const Fidelity plain = measure_fidelity(box, lowered, l, progress);
    EXPECT_FALSE(plain.passed);
    EXPECT_NEAR(plain.far_share, 1.0 / 6.0 + 4.0 / 6.0 / 20.0, 0.02);
    l.exempt.push_back({{10, 10, 20}, 5.0});
    const Fidelity part = measure_fidelity(box, lowered, l, progress);
    EXPECT_FALSE(part.passed);
    EXPECT_NEAR(double(part.left_out) / double(part.samples), 3.14159 * 25.0 / 400.0 / 6.0, 0.01);
    l.exempt = {{{10, 10, 20}, 15.0}};
    const Fidelity whole = measure_fidelity(box, lowered, l, progress);
    EXPECT_TRUE(whole.passed) << whole.defect;
}

// A box and, beside it, an open 10 x 10 mm sheet: the sheet encloses no
// volume on either side, yet it is the model's; an output of the box alone
// leaves its 100 of the 700 mm² far, and says they are sheet.
TEST(InputFidelity, AnOpenSheetTheOutputLacksCounts) {
    Progress progress;
    const Mesh box = test::make_box({0, 0, 0}, {10, 10, 10});
    const Mesh sheet = test::loose_triangles({{Vec3{20, 0, 0}, Vec3{30, 0, 0}, Vec3{30, 10, 0}},
                                              {Vec3{20, 0, 0}, Vec3{30, 10, 0}, Vec3{20, 10, 0}}});
    FidelityLimits l = voxel_limits(0.2);
    l.volume = false;
    const Fidelity f = measure_fidelity(test::merged(box, sheet), box, l, progress);
    EXPECT_FALSE(f.passed);
    EXPECT_NEAR(f.far_share, 1.0 / 7.0, 0.02);
    EXPECT_NEAR(f.far_sheet_share, 1.0 / 7.0, 0.02);
    EXPECT_EQ(f.left_out, 0u);
    EXPECT_NE(f.defect.find("no clear solid on either side"), std::string::npos) << f.defect;
}

TEST(InputFidelity, AnEmptyOutputFails) {
    Progress progress;
    const Fidelity f = measure_fidelity(test::make_box({0, 0, 0}, {1, 1, 1}), Mesh{}, exact_limits(Mesh{}), progress);
    EXPECT_FALSE(f.passed);
    EXPECT_EQ(f.defect, "the output is empty");
}

TEST(InputFidelity, CancelledThrows) {
    std::atomic<bool> cancel{true};
    Progress progress(nullptr, nullptr, &cancel);
    const Mesh ball = test::make_sphere({0, 0, 0}, 10, 3);
    try {
        measure_fidelity(ball, ball, exact_limits(ball), progress);
        ADD_FAILURE() << "not cancelled";
    } catch (const Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_CANCELLED);
    }
}

}  // namespace
}  // namespace fabvdb::volume
