// triangle_regions: the chosen faces of two boxes make one region per box
// face group joined through vertices, with the exact area, centroid and box;
// nothing chosen gives no region; a flag count that does not match throws.
#include "surface/triangle_regions.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "support/shapes.h"

namespace fabvdb::surface {
namespace {

TEST(TriangleRegions, RegionsOfChosenFaces) {
    const Mesh boxes = test::merged(test::make_box({0, 0, 0}, {2, 3, 1}), test::make_box({10, 0, 0}, {11, 1, 1}));
    std::vector<uint8_t> all(boxes.triangles.size(), 1);
    const auto regions = triangle_regions(boxes, all);
    ASSERT_EQ(regions.size(), 2u);
    // The larger box first: area 2·(6 + 2 + 3) = 22.
    EXPECT_NEAR(regions[0].area, 22.0, 1e-12);
    EXPECT_NEAR(regions[1].area, 6.0, 1e-12);
    EXPECT_EQ(regions[0].triangles.size(), 12u);
    EXPECT_EQ(regions[0].vertices.size(), 8u);
    EXPECT_NEAR(regions[0].centroid[0], 1.0, 1e-12);
    EXPECT_NEAR(regions[0].centroid[1], 1.5, 1e-12);
    EXPECT_NEAR(regions[0].centroid[2], 0.5, 1e-12);
    EXPECT_EQ(regions[1].box.min[0], 10.0);
    EXPECT_EQ(regions[1].box.max[0], 11.0);

    std::vector<uint8_t> one(boxes.triangles.size(), 0);
    one[3] = 1;
    ASSERT_EQ(triangle_regions(boxes, one).size(), 1u);
    EXPECT_NEAR(triangle_regions(boxes, one)[0].area, triangle_area(boxes, boxes.triangles[3]), 1e-12);
    EXPECT_TRUE(triangle_regions(boxes, std::vector<uint8_t>(boxes.triangles.size(), 0)).empty());
    EXPECT_THROW(triangle_regions(boxes, {1, 0}), Error);
}

}  // namespace
}  // namespace fabvdb::surface
