// Exact booleans on closed meshes: volumes of unions, differences and
// intersections of boxes and spheres by the divergence theorem; defective
// inputs are refused with an error naming them.
#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "support/ray_cast.h"
#include "support/shapes.h"
#include "surface/mesh_boolean.h"

namespace {

using fabvdb::Mesh;
using fabvdb::surface::BooleanOperation;
using fabvdb::surface::mesh_boolean;

TEST(MeshBoolean, BoxesUniteSubtractIntersect) {
    const Mesh a = fabvdb::test::make_box({0, 0, 0}, {2, 2, 2});
    const Mesh b = fabvdb::test::make_box({1, 1, 1}, {3, 3, 3});
    fabvdb::Progress progress;
    const Mesh unite = mesh_boolean(a, "a", {{BooleanOperation::unite, &b, "b"}}, progress);
    const Mesh subtract = mesh_boolean(a, "a", {{BooleanOperation::subtract, &b, "b"}}, progress);
    const Mesh intersect = mesh_boolean(a, "a", {{BooleanOperation::intersect, &b, "b"}}, progress);
    EXPECT_NEAR(fabvdb::test::mesh_volume(unite), 15.0, 1e-9);
    EXPECT_NEAR(fabvdb::test::mesh_volume(subtract), 7.0, 1e-9);
    EXPECT_NEAR(fabvdb::test::mesh_volume(intersect), 1.0, 1e-9);
    for (const Mesh* m : {&unite, &subtract, &intersect}) {
        EXPECT_TRUE(fabvdb::test::closed_two_manifold(*m));
        EXPECT_FALSE(fabvdb::test::self_intersects(*m));
    }
}

TEST(MeshBoolean, SequenceWithCoplanarFaces) {
    // A block, a slab sharing its bottom face, minus a sphere through both.
    const Mesh block = fabvdb::test::make_box({0, 0, 0}, {10, 10, 5});
    const Mesh slab = fabvdb::test::make_box({2, 2, 0}, {8, 8, 7});
    const Mesh ball = fabvdb::test::make_sphere({5, 5, 5}, 2.0, 3);
    fabvdb::Progress progress;
    const Mesh result = mesh_boolean(block, "block",
                                     {{BooleanOperation::unite, &slab, "slab"},
                                      {BooleanOperation::subtract, &ball, "ball"}},
                                     progress);
    const double expected = 500.0 + 36.0 * 2 - fabvdb::test::mesh_volume(ball);
    EXPECT_NEAR(fabvdb::test::mesh_volume(result), expected, 1e-6);
    EXPECT_TRUE(fabvdb::test::closed_two_manifold(result));
    fabvdb::test::LineCaster caster(result, {0.1, 0.2, 1.0});
    EXPECT_FALSE(caster.inside({5, 5, 5}));
    EXPECT_TRUE(caster.inside({3, 3, 6.5}));
}

void expect_refused(const Mesh& bad, const std::string& defect) {
    const Mesh box = fabvdb::test::make_box({0, 0, 0}, {1, 1, 1});
    fabvdb::Progress progress;
    try {
        mesh_boolean(box, "the box", {{BooleanOperation::unite, &bad, "the operand"}}, progress);
        FAIL() << "expected an error for " << defect;
    } catch (const fabvdb::Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_BAD_INPUT);
        const std::string message = e.what();
        EXPECT_NE(message.find("the operand"), std::string::npos) << message;
        EXPECT_NE(message.find(defect), std::string::npos) << message;
    }
}

TEST(MeshBoolean, RefusesDefectiveInputsNamingThem) {
    Mesh open = fabvdb::test::make_box({0, 0, 0}, {2, 2, 2});
    open.triangles.pop_back();
    expect_refused(open, "not closed");
    const Mesh crossing = fabvdb::test::merged(fabvdb::test::make_box({0, 0, 0}, {2, 2, 2}),
                                               fabvdb::test::make_box({1, 1, 1}, {3, 3, 3}));
    expect_refused(crossing, "intersects itself");
    expect_refused(fabvdb::test::flipped(fabvdb::test::make_box({0, 0, 0}, {2, 2, 2})), "inside out");
    expect_refused(Mesh{}, "no triangles");
}

}  // namespace
