//! moldability_terms: the overhang term and the projected overlap against
//! values worked out by hand, and the precomputed pairs of a shell against
//! the geometry: on a convex sphere no two outer triangles facing the same
//! side of an axis overlap in projection (it is a double height field), while
//! two stacked spheres overlap by the lens where their projected discs meet.
#include <gtest/gtest.h>

#include <cmath>

#include "surface/moldability_terms.h"
#include "surface/shell.h"
#include "shell_shapes.h"

namespace {

using fabvdb::Vec3;
using fabvdb::surface::MoldabilityTerms;

constexpr double kPi = 3.14159265358979323846;

Vec3 from_angle(double theta) { return {std::sin(theta), 0.0, std::cos(theta)}; }

//! Σ of the pairs' overlap areas along the axis of direction `d` (each pair once).
double overlap_sum(const MoldabilityTerms& terms, int d) {
    double total = 0;
    for (float area : terms.overlaps_along(d).area) total += area;
    return total / 2;
}

int direction_index(const MoldabilityTerms& terms, const Vec3& d) {
    return fabvdb::test::nearest_direction(terms.directions.directions, d);
}

}  // namespace

TEST(MoldabilityTerms, OverhangTermByHand) {
    const Vec3 up{0, 0, 1};
    // Facing straight down (θ = π): −cos(π)·|p_d(t)| = the whole area.
    EXPECT_NEAR(fabvdb::surface::overhang_term({0, 0, -1}, 2.0, up, 0.0), 2.0, 1e-12);
    // The draft does not push θ + φ past π: still the whole area.
    EXPECT_NEAR(fabvdb::surface::overhang_term({0, 0, -1}, 2.0, up, 0.1), 2.0, 1e-12);
    // θ = 120°, no draft: −cos(120°)·area·|cos 120°| = 0.5 · 0.5 · area.
    EXPECT_NEAR(fabvdb::surface::overhang_term(from_angle(2 * kPi / 3), 1.0, up, 0.0), 0.25, 1e-12);
    // Facing up or sideways (θ ≤ π/2) with no draft: no overhang.
    EXPECT_EQ(fabvdb::surface::overhang_term(from_angle(kPi / 3), 1.0, up, 0.0), 0.0);
    EXPECT_EQ(fabvdb::surface::overhang_term(from_angle(kPi / 2 - 0.05), 1.0, up, 0.0), 0.0);
    // θ = 85° with a 10° draft: θ > π/2 − φ, so −cos(95°)·area·cos(85°).
    const double theta = 85 * kPi / 180, draft = 10 * kPi / 180;
    EXPECT_NEAR(fabvdb::surface::overhang_term(from_angle(theta), 1.0, up, draft),
                -std::cos(theta + draft) * std::cos(theta), 1e-12);
    // θ = 75° with a 10° draft: under π/2 − φ, no overhang.
    EXPECT_EQ(fabvdb::surface::overhang_term(from_angle(75 * kPi / 180), 1.0, up, draft), 0.0);
}

TEST(MoldabilityTerms, ProjectedOverlapByHand) {
    const std::array<Vec3, 3> a{{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}}};  // area 2
    // The same triangle lifted along the axis: full overlap.
    const std::array<Vec3, 3> above{{{0, 0, 5}, {2, 0, 5}, {0, 2, 5}}};
    EXPECT_NEAR(fabvdb::surface::projected_overlap(a, above, {0, 0, 1}), 2.0, 1e-9);
    // Shifted by 1 along x: the overlap is the triangle (1,0) (2,0) (1,1), area 0.5.
    const std::array<Vec3, 3> shifted{{{1, 0, 3}, {3, 0, 3}, {1, 2, 3}}};
    EXPECT_NEAR(fabvdb::surface::projected_overlap(a, shifted, {0, 0, 1}), 0.5, 1e-9);
    // Projected along −z the same.
    EXPECT_NEAR(fabvdb::surface::projected_overlap(a, shifted, {0, 0, -1}), 0.5, 1e-9);
    // Apart: none.
    const std::array<Vec3, 3> apart{{{3, 3, 1}, {5, 3, 1}, {3, 5, 1}}};
    EXPECT_NEAR(fabvdb::surface::projected_overlap(a, apart, {0, 0, 1}), 0.0, 1e-12);
    // Along x both triangles project edge-on (to segments): no area.
    EXPECT_NEAR(fabvdb::surface::projected_overlap(a, above, {1, 0, 0}), 0.0, 1e-12);
    // A square's two halves meet only along the diagonal: no area.
    const std::array<Vec3, 3> other_half{{{2, 0, 1}, {2, 2, 1}, {0, 2, 1}}};
    EXPECT_NEAR(fabvdb::surface::projected_overlap(a, other_half, {0, 0, 1}), 0.0, 1e-9);
}

TEST(MoldabilityTerms, ConvexSphereHasNoSameSideOverlaps) {
    fabvdb::Progress progress;
    const fabvdb::surface::Shell shell = fabvdb::test::shell_of(fabvdb::test::make_sphere({0, 0, 0}, 10.0, 3), 1.0);
    const MoldabilityTerms terms = fabvdb::surface::compute_moldability_terms(shell, 0.0, progress);
    ASSERT_EQ(terms.directions.directions.size(), 162u);
    ASSERT_EQ(terms.axes.size(), 81u);
    // Neighbours sharing an edge may touch along it (zero area); no pair of a
    // convex surface facing the same side overlaps in area.
    for (const auto& axis : terms.overlaps)
        for (float area : axis.area) EXPECT_LT(area, 1e-9f);
}

TEST(MoldabilityTerms, StackedSpheresOverlapByTheirDiscs) {
    // Two spheres of radius 10 stacked along z, 30 apart: along z the upper
    // halves overlap over the projected disc, and so do the lower halves, so
    // the pairs sum to twice the disc's area (the icosphere's outline is a
    // polygon a little inside the circle); along x they are apart.
    fabvdb::Progress progress;
    const fabvdb::surface::Shell shell = fabvdb::test::shell_of(
        fabvdb::test::merged(fabvdb::test::make_sphere({0, 0, 0}, 10.0, 3), fabvdb::test::make_sphere({0, 0, 30}, 10.0, 3)),
        1.0);
    const MoldabilityTerms terms = fabvdb::surface::compute_moldability_terms(shell, 0.0, progress);
    // The candidate nearest +z need not be +z: along it the discs are offset
    // by the part of (0, 0, 30) across it, and meet in a lens of area
    // 2r²·acos(s/2r) − (s/2)·√(4r² − s²).
    const int z = direction_index(terms, {0, 0, 1});
    const Vec3& axis = terms.directions.directions[z];
    const double r = 10.0, s = 30.0 * std::sqrt(1.0 - axis[2] * axis[2]);
    ASSERT_LT(s, 2 * r);
    const double lens = (2 * r * r * std::acos(s / (2 * r)) - 0.5 * s * std::sqrt(4 * r * r - s * s)) *
                        shell.unit_scale * shell.unit_scale;
    EXPECT_NEAR(overlap_sum(terms, z), 2 * lens, 0.04 * 2 * lens);
    EXPECT_LT(overlap_sum(terms, z), 2 * lens);
    EXPECT_NEAR(overlap_sum(terms, direction_index(terms, {0, 0, -1})), overlap_sum(terms, z), 1e-9);
    EXPECT_LT(overlap_sum(terms, direction_index(terms, {1, 0, 0})), 1e-9);

    // Each pair is listed from both sides with the same area, and only for
    // triangles facing the same side of the axis.
    const MoldabilityTerms::Overlaps& along_z = terms.overlaps_along(z);
    const Vec3& d = terms.directions.directions[z];
    size_t checked = 0;
    for (uint32_t t = 0; t + 1 < along_z.offset.size(); ++t)
        for (uint32_t k = along_z.offset[t]; k < along_z.offset[t + 1]; ++k) {
            const uint32_t u = along_z.partner[k];
            bool mirrored = false;
            for (uint32_t j = along_z.offset[u]; j < along_z.offset[u + 1]; ++j)
                mirrored |= along_z.partner[j] == t && along_z.area[j] == along_z.area[k];
            EXPECT_TRUE(mirrored);
            const auto dot = [&](uint32_t i) {
                return shell.normal[i][0] * d[0] + shell.normal[i][1] * d[1] + shell.normal[i][2] * d[2];
            };
            EXPECT_GE(dot(t) * dot(u), 0.0);
            ++checked;
        }
    EXPECT_GT(checked, 0u);
}
