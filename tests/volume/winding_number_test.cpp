// The hierarchical winding number agrees with the exact sum, is 1 inside and 0
// outside closed outward shells, counts overlapping shells twice, and is about
// 1/2 across the mouth of an open box. The exact sum equals the triangles'
// solid angles taken one by one (tests/support's winding number, one atan2
// each), also where they add up past ±π (every face of an octahedron around
// its centre, flipped or not). A tree built in parallel is the same each time.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "support/octahedron.h"
#include "support/shapes.h"
#include "support/winding_number.h"
#include "volume/winding_number.h"

namespace {

using fabvdb::Mesh;
using fabvdb::volume::WindingNumber;

// The expansion's error stays well under the 1/2 threshold's margin, so the
// inside/outside decision agrees with the exact sum wherever it is clear.
TEST(WindingNumber, TreeMatchesExactSum) {
    const Mesh sphere = fabvdb::test::make_sphere({1, 2, 3}, 10.0, 4);
    const WindingNumber winding(sphere);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> coordinate(-20.0, 20.0);
    for (int i = 0; i < 2000; ++i) {
        const fabvdb::Vec3 q{coordinate(random), coordinate(random), coordinate(random)};
        const double exact = winding.exact(q), fast = winding(q);
        EXPECT_NEAR(fast, exact, 0.1);
        if (std::abs(exact - 0.5) > 0.1) EXPECT_EQ(fast >= 0.5, exact >= 0.5);
    }
}

// A tree over more triangles than one task builds (its subtrees built in
// parallel) agrees with the exact sum as well, and is the same tree each
// time it is built.
TEST(WindingNumber, TreeBuiltInParallelMatchesExactSum) {
    const Mesh sphere = fabvdb::test::make_sphere({1, 2, 3}, 10.0, 6);
    ASSERT_GT(sphere.triangles.size(), 50000u);
    const WindingNumber winding(sphere), again(sphere);
    std::mt19937 random(11);
    std::uniform_real_distribution<double> coordinate(-20.0, 20.0);
    for (int i = 0; i < 200; ++i) {
        const fabvdb::Vec3 q{coordinate(random), coordinate(random), coordinate(random)};
        const double exact = winding.exact(q), fast = winding(q);
        EXPECT_NEAR(fast, exact, 0.1);
        EXPECT_EQ(fast, again(q));
    }
}

TEST(WindingNumber, ExactSumIsTheTrianglesSolidAngles) {
    const Mesh octahedron = fabvdb::test::make_octahedron({0.1, -0.2, 0.3}, 2.0, 1.5);
    for (const Mesh& mesh : {octahedron, fabvdb::test::flipped(octahedron)}) {
        const WindingNumber winding(mesh);
        const double centre = winding.exact({0.1, -0.2, 0.3});
        EXPECT_NEAR(std::abs(centre), 1.0, 1e-12);
        EXPECT_NEAR(centre, fabvdb::test::winding_number(mesh, {0.1, -0.2, 0.3}), 1e-12);
    }
    std::mt19937 random(11);
    std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
    std::vector<std::array<fabvdb::Vec3, 3>> corners(300);
    for (auto& triangle : corners)
        for (auto& corner : triangle) corner = {coordinate(random), coordinate(random), coordinate(random)};
    const Mesh soup = fabvdb::test::loose_triangles(corners);
    const WindingNumber winding(soup);
    for (int i = 0; i < 500; ++i) {
        const fabvdb::Vec3 q{1.5 * coordinate(random), 1.5 * coordinate(random), 1.5 * coordinate(random)};
        EXPECT_NEAR(winding.exact(q), fabvdb::test::winding_number(soup, q), 1e-9);
    }
}

TEST(WindingNumber, InsideOneOutsideZero) {
    const Mesh torus = fabvdb::test::make_torus({0, 0, 0}, 10.0, 3.0, 64, 24);
    const WindingNumber winding(torus);
    EXPECT_NEAR(winding({10, 0, 0}), 1.0, 0.1);
    EXPECT_NEAR(winding({0, -10, 1}), 1.0, 0.1);
    EXPECT_NEAR(winding({0, 0, 0}), 0.0, 0.1);
    EXPECT_NEAR(winding({30, 5, 0}), 0.0, 0.1);
    EXPECT_NEAR(WindingNumber(fabvdb::test::flipped(torus))({10, 0, 0}), -1.0, 0.1);
}

TEST(WindingNumber, OverlapCountsTwice) {
    const Mesh both = fabvdb::test::merged(fabvdb::test::make_sphere({0, 0, 0}, 5.0, 3),
                                           fabvdb::test::make_sphere({3, 0, 0}, 5.0, 3));
    const WindingNumber winding(both);
    EXPECT_NEAR(winding({1.5, 0, 0}), 2.0, 0.1);
    EXPECT_NEAR(winding({-3, 0, 0}), 1.0, 0.1);
}

TEST(WindingNumber, HalfAcrossAnOpenFace) {
    const Mesh open = fabvdb::test::make_open_box({0, 0, 0}, {10, 10, 10});
    ASSERT_EQ(open.triangles.size(), 10u);
    const WindingNumber winding(open);
    EXPECT_NEAR(winding({5, 5, 10}), 0.5, 0.1);
    EXPECT_GT(winding({5, 5, 9}), 0.5);
    EXPECT_LT(winding({5, 5, 11}), 0.5);
}

TEST(WindingNumber, EmptyMeshIsZero) {
    EXPECT_EQ(WindingNumber(Mesh{})({0, 0, 0}), 0.0);
}

}  // namespace
