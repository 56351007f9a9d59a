// front_winding_numbers on nested and inverted boxes, one patch a box, whose
// winding numbers are known: 0 outside everything, 1 inside an outward box,
// and in front of an inward (flipped) box, its inside, one less than
// around it. A patch with no facing triangle gets no ray, so no answer; a
// cancelled call throws.
#include "volume/front_winding_numbers.h"

#include <gtest/gtest.h>

#include <atomic>

#include "core/error.h"
#include "support/shapes.h"

namespace fabvdb::volume {
namespace {

// The boxes merged, each its own patch, in order.
std::optional<std::vector<int>> fronts_of(const std::vector<Mesh>& boxes) {
    Mesh mesh;
    std::vector<uint32_t> patch;
    for (const Mesh& box : boxes) {
        patch.resize(patch.size() + box.triangles.size(), uint32_t(&box - boxes.data()));
        mesh = test::merged(mesh, box);
    }
    Progress progress;
    return front_winding_numbers(mesh, patch, boxes.size(), progress);
}

TEST(FrontWindingNumbers, OneBoxEitherWay) {
    const Mesh box = test::make_box({0, 0, 0}, {1, 1, 1});
    EXPECT_EQ(fronts_of({box}), (std::vector<int>{0}));
    // Flipped, its front is its inside, where the winding number is −1.
    EXPECT_EQ(fronts_of({test::flipped(box)}), (std::vector<int>{-1}));
}

TEST(FrontWindingNumbers, NestedBoxes) {
    const Mesh outer = test::make_box({0, 0, 0}, {4, 4, 4});
    const Mesh inner = test::make_box({1, 1, 1}, {2, 3, 2});
    // A solid inside a solid: in front of the inner box, inside the outer.
    EXPECT_EQ(fronts_of({outer, inner}), (std::vector<int>{0, 1}));
    // A void: in front of the flipped inner box, inside the void.
    EXPECT_EQ(fronts_of({outer, test::flipped(inner)}), (std::vector<int>{0, 0}));
    // Side by side, apart: both fronts outside.
    EXPECT_EQ(fronts_of({inner, test::make_box({5, 0, 0}, {6, 1, 1})}), (std::vector<int>{0, 0}));
}

TEST(FrontWindingNumbers, APatchWithNoFacingTriangleGivesNothing) {
    // A zero-area triangle as a patch of its own, far behind the box.
    const Mesh box = test::make_box({0, 0, 0}, {1, 1, 1});
    const Mesh sliver = test::loose_triangles({{{{-10, -10, -10}, {-9, -9, -9}, {-8, -8, -8}}}});
    EXPECT_EQ(fronts_of({box, sliver}), std::nullopt);
}

TEST(FrontWindingNumbers, CancelledThrows) {
    const Mesh box = test::make_box({0, 0, 0}, {1, 1, 1});
    std::atomic<bool> cancel{true};
    Progress progress(nullptr, nullptr, &cancel);
    try {
        front_winding_numbers(box, std::vector<uint32_t>(box.triangles.size(), 0), 1, progress);
        ADD_FAILURE() << "not cancelled";
    } catch (const Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_CANCELLED);
    }
}

}  // namespace
}  // namespace fabvdb::volume
