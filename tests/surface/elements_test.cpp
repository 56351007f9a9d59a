// make_elements on the shell of a unit box, whose triangle adjacency is worked
// out by hand from make_box's faces (0-1 bottom, 2-3 top, 4-5 y = 0, 6-7
// y = 1, 8-9 x = 0, 10-11 x = 1): one element per triangle without no-cut
// sets; thin segments and strokes become single elements, overlapping ones
// merge; triangles outside the domain belong to none and border nothing,
// and a set joins its members in the domain whatever its first member.
#include "surface/elements.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "shell_shapes.h"
#include "support/shapes.h"

namespace fabvdb::surface {
namespace {

Shell box_shell() { return test::shell_of(test::make_box({0, 0, 0}, {1, 1, 1}), 0.1); }

const std::vector<char> everywhere(12, 1);

// The elements of the listed triangles, sorted.
std::vector<int> elements_of(const Elements& elements, const std::vector<uint32_t>& triangles) {
    std::vector<int> found;
    for (uint32_t t : triangles) found.push_back(elements.element_of_triangle[t]);
    std::sort(found.begin(), found.end());
    return found;
}

// Every element's triangles map back to it, and adjacency is symmetric,
// sorted, free of the element itself and of −1.
void expect_consistent(const Elements& elements) {
    ASSERT_EQ(elements.adjacent.size(), elements.triangles.size());
    for (size_t e = 0; e < elements.triangles.size(); ++e) {
        EXPECT_FALSE(elements.triangles[e].empty()) << "element " << e;
        for (uint32_t t : elements.triangles[e]) EXPECT_EQ(elements.element_of_triangle[t], int(e)) << "element " << e;
        const auto& adjacent = elements.adjacent[e];
        EXPECT_TRUE(std::is_sorted(adjacent.begin(), adjacent.end()));
        for (int f : adjacent) {
            ASSERT_GE(f, 0);
            ASSERT_LT(size_t(f), elements.triangles.size());
            EXPECT_NE(f, int(e));
            const auto& back = elements.adjacent[size_t(f)];
            EXPECT_TRUE(std::binary_search(back.begin(), back.end(), int(e))) << e << " and " << f;
        }
    }
}

TEST(Elements, OnePerTriangleWithoutNoCutSets) {
    const Shell shell = box_shell();
    const Elements elements = make_elements(shell, {}, everywhere);
    ASSERT_EQ(elements.triangles.size(), 12u);
    for (uint32_t t = 0; t < 12; ++t) {
        EXPECT_EQ(elements.element_of_triangle[t], int(t));
        EXPECT_EQ(elements.triangles[t], std::vector<uint32_t>{t});
        EXPECT_EQ(elements.adjacent[t].size(), 3u) << "triangle " << t;
    }
    expect_consistent(elements);
    // Bottom triangle (0, 2, 3): across its diagonal triangle 1, across edge
    // 0-2 the x = 0 face's (0, 6, 2) = 9, across 2-3 the y = 1 face's (2, 7, 3) = 7.
    EXPECT_EQ(elements.adjacent[0], (std::vector<int>{1, 7, 9}));
}

TEST(Elements, ThinSegmentsBecomeSingleElements) {
    Shell shell = box_shell();
    shell.thin_segment[0] = shell.thin_segment[1] = 0;  // bottom
    shell.thin_segment[2] = shell.thin_segment[3] = 1;  // top
    const Elements elements = make_elements(shell, {}, everywhere);
    ASSERT_EQ(elements.triangles.size(), 10u);
    expect_consistent(elements);
    // Numbered by first triangle: bottom, top, then the sides 4..11 as 2..9.
    EXPECT_EQ(elements.triangles[0], (std::vector<uint32_t>{0, 1}));
    EXPECT_EQ(elements.triangles[1], (std::vector<uint32_t>{2, 3}));
    for (uint32_t t = 4; t < 12; ++t) EXPECT_EQ(elements.element_of_triangle[t], int(t) - 2);
    // The bottom borders the four side triangles along its rim: (0, 1, 5) = 4,
    // (2, 7, 3) = 7, (0, 6, 2) = 9 and (1, 3, 7) = 10; never the top.
    EXPECT_EQ(elements.adjacent[0], (std::vector<int>{4 - 2, 7 - 2, 9 - 2, 10 - 2}));
    EXPECT_EQ(elements.adjacent[1].size(), 4u);
    EXPECT_EQ(std::count(elements.adjacent[1].begin(), elements.adjacent[1].end(), 0), 0);
}

TEST(Elements, OverlappingNoCutSetsMerge) {
    Shell shell = box_shell();
    shell.thin_segment[10] = shell.thin_segment[11] = 4;  // the x = 1 face
    // Two strokes sharing triangle 5, the second reaching the thin segment.
    const Elements elements = make_elements(shell, {{4, 5}, {5, 10}}, everywhere);
    ASSERT_EQ(elements.triangles.size(), 12u - 3u);
    expect_consistent(elements);
    const int merged = elements.element_of_triangle[4];
    EXPECT_EQ(elements_of(elements, {4, 5, 10, 11}), std::vector<int>(4, merged));
    EXPECT_EQ(elements.triangles[size_t(merged)], (std::vector<uint32_t>{4, 5, 10, 11}));
    // Disjoint strokes stay apart.
    const Elements apart = make_elements(box_shell(), {{0, 1}, {2, 3}}, everywhere);
    EXPECT_EQ(apart.triangles.size(), 10u);
    EXPECT_NE(apart.element_of_triangle[0], apart.element_of_triangle[2]);
}

TEST(Elements, OnlyTheDomainTakesPart) {
    Shell shell = box_shell();
    std::vector<char> domain = everywhere;
    domain[2] = domain[3] = 0;  // not the top
    shell.thin_segment[1] = shell.thin_segment[2] = 0;  // a segment reaching out of the domain
    const Elements elements = make_elements(shell, {{0, 3}}, domain);
    EXPECT_EQ(elements.element_of_triangle[2], -1);
    EXPECT_EQ(elements.element_of_triangle[3], -1);
    // In the domain, triangles 0 and 1 are single elements: their sets
    // reached them only through the top.
    ASSERT_EQ(elements.triangles.size(), 10u);
    EXPECT_NE(elements.element_of_triangle[0], elements.element_of_triangle[1]);
    expect_consistent(elements);
    for (const auto& triangles : elements.triangles)
        for (uint32_t t : triangles) EXPECT_TRUE(domain[t]);
    // The top's neighbours border one fewer element: triangle 5 = (0, 5, 4)
    // has (0, 1, 5) = 4, (0, 4, 6) = 8 and the top's (4, 5, 7) = 2 around it.
    const int five = elements.element_of_triangle[5];
    EXPECT_EQ(elements.adjacent[size_t(five)],
              (std::vector<int>{elements.element_of_triangle[4], elements.element_of_triangle[8]}));
    // A set whose first member is outside the domain still joins the rest.
    std::vector<char> no_two = everywhere;
    no_two[2] = 0;
    const Elements stroke = make_elements(box_shell(), {{2, 4, 5}}, no_two);
    EXPECT_EQ(stroke.element_of_triangle[4], stroke.element_of_triangle[5]);
    Shell segment_shell = box_shell();
    segment_shell.thin_segment[2] = segment_shell.thin_segment[4] = segment_shell.thin_segment[5] = 0;
    const Elements segment = make_elements(segment_shell, {}, no_two);
    EXPECT_EQ(segment.element_of_triangle[4], segment.element_of_triangle[5]);
    EXPECT_EQ(segment.triangles.size(), 10u);
    // Nothing in the domain: no elements.
    const Elements none = make_elements(shell, {{0, 1}}, std::vector<char>(12, 0));
    EXPECT_TRUE(none.triangles.empty());
    EXPECT_EQ(none.element_of_triangle, std::vector<int>(12, -1));
}

}  // namespace
}  // namespace fabvdb::surface
