// Duplicate triangles: a later triangle on the same three indices (any
// order or orientation) is a duplicate, the first copy is not, n copies give
// n - 1; equal positions under other indices do not count.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "support/shapes.h"
#include "surface/duplicate_triangles.h"

namespace {

using fabvdb::Mesh;
using fabvdb::surface::duplicate_triangles;

TEST(DuplicateTriangles, ClosedBoxHasNone) {
    EXPECT_TRUE(duplicate_triangles(fabvdb::test::make_box({0, 0, 0}, {1, 2, 3})).empty());
    EXPECT_TRUE(duplicate_triangles(Mesh{}).empty());
}

TEST(DuplicateTriangles, SameIndicesInAnyOrderOrOrientation) {
    Mesh mesh = fabvdb::test::make_box({0, 0, 0}, {1, 1, 1});
    const auto t3 = mesh.triangles[3], t5 = mesh.triangles[5], t7 = mesh.triangles[7];
    mesh.triangles.push_back(t3);                      // 12: the same
    mesh.triangles.push_back({t5[1], t5[2], t5[0]});   // 13: rotated
    mesh.triangles.push_back({t7[0], t7[2], t7[1]});   // 14: flipped
    mesh.triangles.push_back({t3[0], t3[1], 0});       // 15: shares two indices only
    EXPECT_EQ(duplicate_triangles(mesh), (std::vector<uint32_t>{12, 13, 14}));
}

TEST(DuplicateTriangles, OnlyTheLaterCopiesCount) {
    Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    // {0,1,2} four times (first at 1), {1,2,3} twice (first at 0).
    mesh.triangles = {{1, 2, 3}, {2, 1, 0}, {0, 1, 2}, {3, 2, 1}, {1, 0, 2}, {0, 2, 1}};
    EXPECT_EQ(duplicate_triangles(mesh), (std::vector<uint32_t>{2, 3, 4, 5}));
}

TEST(DuplicateTriangles, EqualPositionsUnderOtherIndicesAreNotDuplicates) {
    Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.triangles = {{0, 1, 2}, {3, 4, 5}, {0, 4, 2}};
    EXPECT_TRUE(duplicate_triangles(mesh).empty());
}

TEST(DuplicateTriangles, DegenerateTrianglesCompareByTheirIndexMultiset) {
    Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {1, 0, 0}};
    mesh.triangles = {{0, 0, 1}, {0, 1, 1}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    EXPECT_EQ(duplicate_triangles(mesh), (std::vector<uint32_t>{2, 3, 4}));
}

}  // namespace
