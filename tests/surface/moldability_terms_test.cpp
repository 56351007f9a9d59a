//! moldability_terms: the overhang term and the projected overlap against
//! values worked out by hand, and the precomputed pairs of a shell against
//! the geometry: on a convex sphere no two outer triangles facing the same
//! side of an axis overlap in projection (it is a double height field), while
//! two stacked spheres overlap by the lens where their projected discs meet;
//! and updating the terms of a few (spread or in one patch) or of many moved
//! triangles gives the pairs measured from scratch.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

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

namespace {

//! Per axis and triangle, the (partner, area) pairs sorted by partner.
using PairLists = std::vector<std::vector<std::vector<std::pair<uint32_t, float>>>>;

PairLists pair_lists(const MoldabilityTerms& terms) {
    PairLists lists(terms.overlaps.size());
    for (size_t a = 0; a < terms.overlaps.size(); ++a) {
        const auto& o = terms.overlaps[a];
        lists[a].resize(o.offset.size() - 1);
        for (size_t t = 0; t + 1 < o.offset.size(); ++t) {
            for (uint32_t k = o.offset[t]; k < o.offset[t + 1]; ++k) lists[a][t].emplace_back(o.partner[k], o.area[k]);
            std::sort(lists[a][t].begin(), lists[a][t].end());
        }
    }
    return lists;
}

//! Moves `count` vertices of the lower of the stacked spheres (every 7th off
//! its bounding box, or with `clustered` the nearest to a point of its upper
//! half; 7% of the way to its centre: the unit scale stays), updates the
//! terms of the triangles around them and compares with the terms measured
//! from scratch.
void expect_update_equals_recompute(size_t count, bool clustered = false) {
    fabvdb::Progress progress;
    fabvdb::Mesh mesh =
        fabvdb::test::merged(fabvdb::test::make_sphere({0, 0, 0}, 10.0, 3), fabvdb::test::make_sphere({0, 0, 30}, 10.0, 3));
    const fabvdb::surface::Shell before = fabvdb::test::shell_of(mesh, 1.0);
    MoldabilityTerms updated = fabvdb::surface::compute_moldability_terms(before, 0.0, progress);
    std::vector<char> moved(mesh.vertices.size(), 0);
    std::vector<size_t> order;
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
        const Vec3& p = mesh.vertices[v];
        if (p[2] > 15 || std::abs(p[0]) > 9 || std::abs(p[1]) > 9 || std::abs(p[2]) > 9) continue;  // not on the bounding box
        if (clustered || v % 7 == 0) order.push_back(v);
    }
    if (clustered) {
        const auto distance = [&](size_t v) {
            const Vec3& p = mesh.vertices[v];
            return std::hypot(p[0] - 3.0, p[1] - 2.0, p[2] - 8.5);
        };
        std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return distance(a) < distance(b); });
    }
    ASSERT_GE(order.size(), count);
    for (size_t i = 0; i < count; ++i) {
        const size_t v = order[i];
        moved[v] = 1;
        mesh.vertices[v] = {0.93 * mesh.vertices[v][0], 0.93 * mesh.vertices[v][1], 0.93 * mesh.vertices[v][2]};
    }
    const fabvdb::surface::Shell after = fabvdb::test::shell_of(mesh, 1.0);
    ASSERT_EQ(after.unit_scale, before.unit_scale);
    std::vector<uint32_t> changed;
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
        if (moved[mesh.triangles[t][0]] || moved[mesh.triangles[t][1]] || moved[mesh.triangles[t][2]])
            changed.push_back(uint32_t(t));
    std::vector<int> axes(updated.axes.size());
    for (size_t a = 0; a < axes.size(); ++a) axes[a] = int(a);
    fabvdb::surface::update_moldability_terms(after, changed, axes, updated);
    const MoldabilityTerms fresh = fabvdb::surface::compute_moldability_terms(after, 0.0, progress);
    EXPECT_EQ(updated.pair_count, fresh.pair_count);
    // The same partners; the same areas but for the rounding of clipping a
    // pair in the other order (a changed triangle is clipped against the
    // other one, not by increasing index).
    const PairLists got = pair_lists(updated), expected = pair_lists(fresh);
    ASSERT_EQ(got.size(), expected.size());
    size_t compared = 0;
    for (size_t a = 0; a < got.size(); ++a)
        for (size_t t = 0; t < got[a].size(); ++t) {
            ASSERT_EQ(got[a][t].size(), expected[a][t].size()) << "axis " << a << " triangle " << t;
            for (size_t k = 0; k < got[a][t].size(); ++k) {
                EXPECT_EQ(got[a][t][k].first, expected[a][t][k].first) << "axis " << a << " triangle " << t;
                EXPECT_NEAR(got[a][t][k].second, expected[a][t][k].second, 1e-5 * expected[a][t][k].second + 1e-15);
                ++compared;
            }
        }
    EXPECT_GT(compared, 1000u);
}

}  // namespace

TEST(MoldabilityTerms, UpdatingAFewMovedTrianglesEqualsMeasuringAgain) {
    expect_update_equals_recompute(2);  // about 12 triangles: each box against the changed ones
}

TEST(MoldabilityTerms, UpdatingAMovedPatchEqualsMeasuringAgain) {
    expect_update_equals_recompute(5, true);  // a patch under the upper sphere: most triangles out of its reach
}

TEST(MoldabilityTerms, UpdatingManyMovedTrianglesEqualsMeasuringAgain) {
    expect_update_equals_recompute(40);  // about 240 triangles: through the grid
}
