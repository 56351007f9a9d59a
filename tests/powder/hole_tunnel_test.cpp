//! hole_tunnel against hand-worked cases (θ_r = 35°, tan θ_r = 0.700):
//! - passes_powder: a tunnel passes powder when its axis is within
//!   90° − θ_r of gravity; a flatter one when the slope of repose from its
//!   outer lip meets the inner mouth below its top: for a horizontal tunnel
//!   of diameter D and length L, when D > L·tan θ_r; never when it points up.
//! - crater_cone: a steep tunnel's cone rises from the rim of its mouth
//!   (apex at the centre, flat top of radius D/2), a flat tunnel's from its
//!   outer lip; below() read off the cone's radius at each height.
//! - rise_and_across on a 3-4-5 triangle.
#include <gtest/gtest.h>

#include <cmath>

#include "powder/hole_tunnel.h"

namespace {

using fabvdb::Vec3;
using fabvdb::powder::crater_cone;
using fabvdb::powder::CraterCone;
using fabvdb::powder::DrainHole;
using fabvdb::powder::passes_powder;

constexpr double kRepose = 35.0 * M_PI / 180.0;

DrainHole tunnel(const Vec3& axis, double diameter, double through) {
    DrainHole hole;
    hole.center = {0, 0, 0};
    hole.axis = axis;
    hole.diameter = diameter;
    hole.through = through;
    hole.depth = through + diameter;
    return hole;
}

Vec3 tilted(double degrees) { return {std::sin(degrees * M_PI / 180), 0, -std::cos(degrees * M_PI / 180)}; }

}  // namespace

TEST(HoleTunnel, PassesPowderByHand) {
    const DrainHole down = tunnel({0, 0, -1}, 4.0, 2.5);
    EXPECT_TRUE(passes_powder(down, {0, 0, -1}, kRepose));
    // 50° off the axis: within 90° − 35° = 55°, steep.
    EXPECT_TRUE(passes_powder(down, tilted(50), kRepose));
    // Pointing up: powder would have to climb the tunnel.
    EXPECT_FALSE(passes_powder(down, {0, 0, 1}, kRepose));
    // Horizontal: passes when D > L·tan θ_r (4 > 2.5·0.70 = 1.75), not for L = 8 (5.6 > 4).
    EXPECT_TRUE(passes_powder(down, {1, 0, 0}, kRepose));
    EXPECT_FALSE(passes_powder(tunnel({0, 0, -1}, 4.0, 8.0), {1, 0, 0}, kRepose));
    // L = 5.6 / 0.7 ± a little: the limit D = L·tan θ_r.
    EXPECT_TRUE(passes_powder(tunnel({0, 0, -1}, 4.0, 5.6), {1, 0, 0}, kRepose));
    EXPECT_FALSE(passes_powder(tunnel({0, 0, -1}, 4.0, 5.8), {1, 0, 0}, kRepose));
    // 60° off the axis (30° below horizontal), L = 2.5: the outer lip lies
    // below the inner mouth's top; L = 100 holds it back (the tunnel falls at
    // tan 30° = 0.58 < 0.70).
    EXPECT_TRUE(passes_powder(down, tilted(60), kRepose));
    EXPECT_FALSE(passes_powder(tunnel({0, 0, -1}, 4.0, 100.0), tilted(60), kRepose));
}

TEST(HoleTunnel, CraterConeOfASteepTunnelRisesFromTheRim) {
    const CraterCone cone = crater_cone(tunnel({0, 0, -1}, 4.0, 2.5), {0, 0, -1}, kRepose);
    EXPECT_EQ(cone.apex, (Vec3{0, 0, 0}));
    EXPECT_DOUBLE_EQ(cone.mouth, 2.0);
    EXPECT_DOUBLE_EQ(cone.tan_repose, std::tan(kRepose));
    // Over the mouth powder drains down to one radius below the centre.
    EXPECT_TRUE(cone.below({0, 0, -3}));
    EXPECT_FALSE(cone.below({1, 0, -1}));
    // Beside it, below the apex, it stays.
    EXPECT_TRUE(cone.below({5, 0, -0.1}));
    // At height 1 the cone's radius is 1 / 0.700 + 2 = 3.43.
    EXPECT_TRUE(cone.below({0, 3.5, 1}));
    EXPECT_FALSE(cone.below({0, 3.3, 1}));
}

TEST(HoleTunnel, CraterConeOfAFlatTunnelRisesFromTheOuterLip) {
    // Gravity +x across a tunnel down −z: the lip is the rim's lowest point
    // (+x, one radius) at the outer end (z = −2.5).
    const CraterCone cone = crater_cone(tunnel({0, 0, -1}, 4.0, 2.5), {1, 0, 0}, kRepose);
    EXPECT_NEAR(cone.apex[0], 2.0, 1e-12);
    EXPECT_NEAR(cone.apex[1], 0.0, 1e-12);
    EXPECT_NEAR(cone.apex[2], -2.5, 1e-12);
    EXPECT_EQ(cone.mouth, 0.0);
    // 1 above the lip (x = 1) the cone's radius is 1 / 0.700 = 1.43.
    EXPECT_FALSE(cone.below({1, 0, -2.5 + 1.4}));
    EXPECT_TRUE(cone.below({1, 0, -2.5 + 1.5}));
}

TEST(HoleTunnel, RiseAndAcross) {
    const auto [rise, across] = fabvdb::powder::rise_and_across({3, 4, 5}, {0, 0, 1}, {0, 0, -1});
    EXPECT_DOUBLE_EQ(rise, 4.0);
    EXPECT_DOUBLE_EQ(across, 5.0);
}
