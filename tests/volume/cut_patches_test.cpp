// cut_patches on a box (make_box: triangles 0-1 bottom, 2-3 top, 4-11 the
// sides) with cuts marked by hand: none gives one patch; the loop around the
// top face parts it from the rest, with every cut edge between the two; a
// cut that stops short parts nothing and gives nothing, as does an open
// surface; edges between untouched triangles are never cuts.
#include "volume/cut_patches.h"

#include <gtest/gtest.h>

#include "support/shapes.h"

namespace fabvdb::volume {
namespace {

// make_box's vertex i is at ((i & 1), (i & 2) / 2, (i & 4) / 4): the top
// face is 4-5-7-6.
CutSurface box_cut_along(const std::vector<std::pair<uint32_t, uint32_t>>& edges) {
    CutSurface surface;
    surface.mesh = test::make_box({0, 0, 0}, {1, 1, 1});
    for (const auto& [a, b] : edges) {
        surface.cut_edges.insert(CutSurface::edge_key(a, b));
        surface.cut_edges.insert(CutSurface::edge_key(b, a));
    }
    return surface;
}

TEST(CutPatches, NoCutIsOnePatch) {
    const std::optional<Patches> patches = cut_patches(box_cut_along({}));
    ASSERT_TRUE(patches.has_value());
    EXPECT_EQ(patches->count, 1u);
    EXPECT_EQ(patches->of_triangle, std::vector<uint32_t>(12, 0));
    EXPECT_TRUE(patches->across_cuts.empty());
}

TEST(CutPatches, ALoopPartsTheTopFace) {
    const std::optional<Patches> patches = cut_patches(box_cut_along({{4, 5}, {5, 7}, {7, 6}, {6, 4}}));
    ASSERT_TRUE(patches.has_value());
    EXPECT_EQ(patches->count, 2u);
    // Numbered in order of first triangle: the bottom's patch is 0.
    std::vector<uint32_t> expected(12, 0);
    expected[2] = expected[3] = 1;
    EXPECT_EQ(patches->of_triangle, expected);
    // Each of the 4 cut edges once, between the two patches.
    ASSERT_EQ(patches->across_cuts.size(), 4u);
    for (const auto& [p, q] : patches->across_cuts) EXPECT_EQ(std::minmax(p, q), std::minmax(0u, 1u));
}

TEST(CutPatches, ACutThatDoesNotPartGivesNothing) {
    // Three sides of the top face: the fourth joins it to the rest.
    EXPECT_FALSE(cut_patches(box_cut_along({{4, 5}, {5, 7}, {7, 6}})).has_value());
    // The top face's diagonal 4-7 alone, inside one face.
    EXPECT_FALSE(cut_patches(box_cut_along({{4, 7}})).has_value());
}

TEST(CutPatches, AnOpenSurfaceGivesNothing) {
    CutSurface surface = box_cut_along({});
    surface.mesh.triangles.pop_back();
    EXPECT_FALSE(cut_patches(surface).has_value());
}

TEST(CutPatches, EdgesBetweenUntouchedTrianglesAreNeverCuts) {
    // With every triangle untouched, the loop is ignored.
    CutSurface surface = box_cut_along({{4, 5}, {5, 7}, {7, 6}, {6, 4}});
    surface.first_piece = 12;
    const std::optional<Patches> patches = cut_patches(surface);
    ASSERT_TRUE(patches.has_value());
    EXPECT_EQ(patches->count, 1u);
    EXPECT_TRUE(patches->across_cuts.empty());
}

}  // namespace
}  // namespace fabvdb::volume
