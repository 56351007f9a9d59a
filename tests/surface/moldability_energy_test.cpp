// moldability_energy against values worked out by hand: a hand-made part
// surface and overlap lists along ±z give E_H, E_L, the weighted total and the
// per-triangle shares exactly (inner triangles ignored, side triangles charged
// to the triangle they border, overlaps only within one side). On the shell
// of a cube with the real 162-direction terms: everything in M⁺ costs
// Σ_k d_k² · (face area 1) = 1 for any direction d, split by the normals' side
// it costs nothing, and the shares always add up to the total.
#include "surface/moldability_energy.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "shell_shapes.h"
#include "support/shapes.h"

namespace fabvdb::surface {
namespace {

// Terms with two directions, +z and −z, on one axis, and the overlaps of
// four outer triangles along it: (0, 1) 0.6, (0, 2) 0.4, (2, 3) 0.8.
MoldabilityTerms hand_terms() {
    MoldabilityTerms terms;
    terms.directions.directions = {{0, 0, 1}, {0, 0, -1}};
    terms.directions.opposite = {1, 0};
    terms.axis_of_direction = {0, 0};
    terms.axes = {{0, 0, 1}};
    MoldabilityTerms::Overlaps overlaps;
    overlaps.offset = {0, 2, 3, 5, 6};
    overlaps.partner = {1, 2, 0, 0, 3, 2};
    overlaps.area = {0.6f, 0.4f, 0.6f, 0.4f, 0.8f, 0.8f};
    terms.overlaps = {overlaps};
    terms.pair_count = 3;
    terms.draft = 0.0;
    return terms;
}

// A part made of outer triangles 0, 1 and 2 (3 is outside it), with an inner
// triangle and two side triangles.
PartSurface hand_surface() {
    PartSurface s;
    const double r = std::sqrt(3.0) / 2.0;
    const auto add = [&s](PartSurface::Kind kind, uint32_t source, const Vec3& normal, double area) {
        s.kind.push_back(kind);
        s.source.push_back(source);
        s.corners.push_back({0, 0, 0});
        s.normal.push_back(normal);
        s.area.push_back(area);
        s.adjacency_start.push_back(0);
    };
    s.adjacency_start.push_back(0);
    add(PartSurface::outer, 0, {0, 0, -1}, 2.0);
    add(PartSurface::outer, 1, {0, 0, 1}, 3.0);
    add(PartSurface::inner, 0, {0, 0, -1}, 5.0);
    add(PartSurface::side, 3 * 0 + 1, {0, 0, -1}, 1.0);  // borders triangle 0
    add(PartSurface::outer, 2, {0, 0, 1}, 4.0);
    add(PartSurface::side, 3 * 2 + 2, {r, 0, -0.5}, 1.0);  // borders triangle 2, 120° from +z
    return s;
}

// Per surface triangle of hand_surface: triangle 0 in M⁺, 1 in M⁻, 2 in M⁺.
const std::vector<char> hand_upper = {1, 0, 1, 1, 1, 1};

TEST(MoldabilityEnergy, HandMadePartAlongPlusZ) {
    const MoldabilityTerms terms = hand_terms();
    const PartSurface surface = hand_surface();
    std::vector<double> share(4, 0.0);
    const MoldabilityEnergy energy = moldability_energy(terms, surface, hand_upper, 0, {2.0, 3.0}, &share);
    // E_H: triangle 0 faces straight down in M⁺ (its area, 2); triangle 1
    // faces up in M⁻, against −z (3); the side under triangle 0 (1); the side
    // at 120° (cos² 120° · 1 = 0.25); triangle 2 faces up in M⁺ (0); the
    // inner triangle is ignored.
    EXPECT_NEAR(energy.overhang, 2.0 + 3.0 + 1.0 + 0.25, 1e-12);
    // E_L: only (0, 2) lie on one side, listed from both: ½·0.4 twice.
    EXPECT_NEAR(energy.overlap, double(0.4f), 1e-12);
    EXPECT_NEAR(energy.total, 2.0 * 6.25 + 3.0 * double(0.4f), 1e-12);
    EXPECT_NEAR(share[0], 2.0 * (2.0 + 1.0) + 3.0 * 0.5 * double(0.4f), 1e-12);
    EXPECT_NEAR(share[1], 2.0 * 3.0, 1e-12);
    EXPECT_NEAR(share[2], 2.0 * 0.25 + 3.0 * 0.5 * double(0.4f), 1e-12);
    EXPECT_EQ(share[3], 0.0);  // outside the part, though it overlaps triangle 2
    EXPECT_NEAR(share[0] + share[1] + share[2] + share[3], energy.total, 1e-12);
    // Without shares the same energy.
    const MoldabilityEnergy bare = moldability_energy(terms, surface, hand_upper, 0, {2.0, 3.0}, nullptr);
    EXPECT_EQ(bare.total, energy.total);
}

TEST(MoldabilityEnergy, HandMadePartAlongMinusZ) {
    const MoldabilityTerms terms = hand_terms();
    const PartSurface surface = hand_surface();
    const MoldabilityEnergy energy = moldability_energy(terms, surface, hand_upper, 1, {1.0, 1.0}, nullptr);
    // Along −z only triangle 2 (facing up, in M⁺) overhangs; the 120° side
    // is 60° from −z. The overlaps are those of the same axis.
    EXPECT_NEAR(energy.overhang, 4.0, 1e-12);
    EXPECT_NEAR(energy.overlap, double(0.4f), 1e-12);
    EXPECT_NEAR(energy.total, 4.0 + double(0.4f), 1e-12);
    // Moving triangle 1 to M⁺ puts the pair (0, 1) on one side too, and makes
    // triangle 1 (facing up) overhang against −z.
    std::vector<char> upper = hand_upper;
    upper[1] = 1;
    const MoldabilityEnergy moved = moldability_energy(terms, surface, upper, 1, {1.0, 1.0}, nullptr);
    EXPECT_NEAR(moved.overhang, 4.0 + 3.0, 1e-12);
    EXPECT_NEAR(moved.overlap, double(0.4f) + double(0.6f), 1e-12);
}

TEST(MoldabilityEnergy, CubeInOneHalfCostsOneForAnyDirection) {
    // A 2 mm cube (unit scale 1/2: every face has unit-cube area 1), as one
    // part with its inner walls. All in M⁺, the faces whose normal n_k
    // opposes d each cost d_k² · 1: together |d|² = 1.
    const Shell shell = test::shell_of(test::make_box({-1, -1, -1}, {1, 1, 1}), 0.5);
    Progress progress;
    const MoldabilityTerms terms = compute_moldability_terms(shell, 0.0, progress);
    const PartSurface surface = part_surface(shell, std::vector<int>(12, 0), 0);
    ASSERT_EQ(surface.size(), 24u);  // 12 outer, 12 inner (ignored)
    for (int direction : {0, 7, 40, 100, 161}) {
        SCOPED_TRACE(testing::Message() << "direction " << direction);
        const Vec3& d = terms.directions.directions[size_t(direction)];
        std::vector<double> share(12, 0.0);
        const MoldabilityEnergy all_upper =
            moldability_energy(terms, surface, std::vector<char>(surface.size(), 1), direction, {1.0, 1.0}, &share);
        EXPECT_NEAR(all_upper.overhang, 1.0, 1e-9);
        // A convex surface: no two triangles on one side overlap in area.
        EXPECT_NEAR(all_upper.overlap, 0.0, 1e-6);
        EXPECT_NEAR(std::accumulate(share.begin(), share.end(), 0.0), all_upper.total, 1e-9);
        // The weights scale each term.
        const MoldabilityEnergy weighted =
            moldability_energy(terms, surface, std::vector<char>(surface.size(), 1), direction, {3.0, 0.5}, nullptr);
        EXPECT_NEAR(weighted.total, 3.0 * weighted.overhang + 0.5 * weighted.overlap, 1e-12);
        EXPECT_NEAR(weighted.overhang, all_upper.overhang, 1e-12);
        // Each triangle on the side its normal faces: nothing overhangs.
        std::vector<char> facing(surface.size());
        for (size_t i = 0; i < surface.size(); ++i) {
            const Vec3& n = surface.normal[i];
            facing[i] = n[0] * d[0] + n[1] * d[1] + n[2] * d[2] >= 0.0;
        }
        EXPECT_NEAR(moldability_energy(terms, surface, facing, direction, {1.0, 1.0}, nullptr).overhang, 0.0, 1e-12);
    }
}

TEST(MoldabilityEnergy, SharesOfAPartStayOnItsTriangles) {
    // The upper half of the cube (triangles with their centroid above z = 0),
    // with side triangles along its rim: the shares land on its own outer
    // triangles only and add up to the total.
    const Shell shell = test::shell_of(test::make_box({-1, -1, -1}, {1, 1, 1}), 0.5);
    Progress progress;
    const MoldabilityTerms terms = compute_moldability_terms(shell, 0.0, progress);
    std::vector<int> part_of_triangle;
    for (const Triangle& t : shell.outer.triangles) {
        double z = 0;
        for (uint32_t v : t) z += shell.outer.vertices[v][2] / 3.0;
        part_of_triangle.push_back(z > 0 ? 0 : 1);
    }
    const PartSurface surface = part_surface(shell, part_of_triangle, 0);
    size_t sides = 0;
    for (auto kind : surface.kind) sides += kind == PartSurface::side;
    ASSERT_GT(sides, 0u);
    const int direction = test::nearest_direction(terms.directions.directions, {0.3, -0.2, -0.9});
    std::vector<double> share(12, 0.0);
    const MoldabilityEnergy energy =
        moldability_energy(terms, surface, std::vector<char>(surface.size(), 1), direction, {1.0, 2.0}, &share);
    EXPECT_GT(energy.overhang, 0.0);
    EXPECT_NEAR(std::accumulate(share.begin(), share.end(), 0.0), energy.total, 1e-9);
    for (size_t t = 0; t < 12; ++t)
        if (part_of_triangle[t] != 0) EXPECT_EQ(share[t], 0.0) << "triangle " << t;
}

}  // namespace
}  // namespace fabvdb::surface
