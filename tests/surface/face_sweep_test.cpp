//! sweep_faces_to_plane: swept volumes are closed 2-manifolds whose volume
//! (divergence theorem) is worked out by hand for an octahedron (no vertical
//! face; a = 10, h = 5) — the part
//! plus the prism of its shadow up (or down) to the plane — and for the dome
//! shell of mold_shapes satisfies V_up + V_down = V_part + (z_up − z_down)·A
//! with A the shadow's area, summed here over the part's upward faces. A
//! vertical face, a plane through the swept faces and a face set with no face
//! of the needed side are refused with Error(BAD_INPUT) saying which.
#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "support/mold_shapes.h"
#include "support/octahedron.h"
#include "support/ray_cast.h"
#include "support/shapes.h"
#include "surface/face_sweep.h"

namespace {

using fabvdb::Mesh;

//! Projected area on the xy plane of the triangles facing +z.
double upward_shadow_area(const Mesh& mesh) {
    double area = 0;
    for (const auto& t : mesh.triangles) {
        const auto &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
        const double twice = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        if (twice > 0) area += 0.5 * twice;
    }
    return area;
}

template <class Call>
void expect_bad_input(Call call, const std::string& text) {
    try {
        call();
        ADD_FAILURE() << "no exception";
    } catch (const fabvdb::Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_BAD_INPUT);
        EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    }
}

}  // namespace

TEST(FaceSweep, OctahedronSweptUpIsThePartAndThePrismAboveIt) {
    // a = 10, h = 5, plane z = 20: the region between the lower faces and the
    // plane, 2a²·20 + (1/3)·2a²·h.
    const Mesh part = fabvdb::test::make_octahedron({0, 0, 0}, 10, 5);
    const Mesh swept = fabvdb::surface::sweep_faces_to_plane(part, true, 20.0);
    EXPECT_TRUE(fabvdb::test::closed_two_manifold(swept));
    EXPECT_NEAR(fabvdb::test::mesh_volume(swept), 200.0 * 20.0 + 200.0 * 5.0 / 3.0, 1e-9);
    // 4 lower faces, their 4 caps and 2 wall triangles on each of the 4 rim edges.
    EXPECT_EQ(swept.triangles.size(), 16u);
    for (const auto& v : swept.vertices) EXPECT_TRUE(v[2] <= 0.0 || v[2] == 20.0) << v[2];
}

TEST(FaceSweep, OctahedronSweptDownIsThePartAndThePrismBelowIt) {
    const Mesh part = fabvdb::test::make_octahedron({0, 0, 0}, 10, 5);
    const Mesh swept = fabvdb::surface::sweep_faces_to_plane(part, false, -12.0);
    EXPECT_TRUE(fabvdb::test::closed_two_manifold(swept));
    EXPECT_NEAR(fabvdb::test::mesh_volume(swept), 200.0 * 12.0 + 200.0 * 5.0 / 3.0, 1e-9);
    for (const auto& v : swept.vertices) EXPECT_TRUE(v[2] >= 0.0 || v[2] == -12.0) << v[2];
}

TEST(FaceSweep, DomeShellSweepsAddUpToThePartAndItsShadowPrism) {
    const Mesh part = fabvdb::test::make_dome_shell(20, 16, 8, 32);
    const double top = 30, bottom = -10;
    const Mesh up = fabvdb::surface::sweep_faces_to_plane(part, true, top);
    const Mesh down = fabvdb::surface::sweep_faces_to_plane(part, false, bottom);
    EXPECT_TRUE(fabvdb::test::closed_two_manifold(up));
    EXPECT_TRUE(fabvdb::test::closed_two_manifold(down));
    const double part_volume = fabvdb::test::mesh_volume(part);
    ASSERT_GT(part_volume, 0);
    const double expected = part_volume + (top - bottom) * upward_shadow_area(part);
    EXPECT_NEAR(fabvdb::test::mesh_volume(up) + fabvdb::test::mesh_volume(down), expected, 1e-9 * expected);
    // Each sweep holds the part: more than the part, less than the prism.
    EXPECT_GT(fabvdb::test::mesh_volume(up), part_volume);
    EXPECT_GT(fabvdb::test::mesh_volume(down), part_volume);
}

TEST(FaceSweep, RefusesAVerticalFace) {
    expect_bad_input([] { fabvdb::surface::sweep_faces_to_plane(fabvdb::test::make_box({0, 0, 0}, {1, 1, 1}), true, 5); },
                     "parallel to the parting direction");
}

TEST(FaceSweep, RefusesAPlaneThroughTheSweptFaces) {
    // The lower faces of the octahedron reach from z = −5 to z = 0, the upper
    // ones from 0 to 5.
    const Mesh part = fabvdb::test::make_octahedron({0, 0, 0}, 10, 5);
    expect_bad_input([&] { fabvdb::surface::sweep_faces_to_plane(part, true, 0.0); }, "does not clear the part");
    expect_bad_input([&] { fabvdb::surface::sweep_faces_to_plane(part, false, 3.0); }, "does not clear the part");
}

TEST(FaceSweep, RefusesAPlaneThroughThePartBeyondTheSweptFaces) {
    // Swept up, the faces swept are the lower ones (z ≤ 0); a plane at z = 3
    // clears them but cuts the top of the part, which reaches z = 5.
    const Mesh part = fabvdb::test::make_octahedron({0, 0, 0}, 10, 5);
    expect_bad_input([&] { fabvdb::surface::sweep_faces_to_plane(part, true, 3.0); }, "does not clear the part");
    expect_bad_input([&] { fabvdb::surface::sweep_faces_to_plane(part, false, -3.0); }, "does not clear the part");
}

TEST(FaceSweep, RefusesAPartWithNoFaceOfTheNeededSide) {
    const Mesh facing_up = fabvdb::test::loose_triangles({{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}});
    expect_bad_input([&] { fabvdb::surface::sweep_faces_to_plane(facing_up, true, 5.0); }, "no face to sweep");
    EXPECT_EQ(fabvdb::surface::sweep_faces_to_plane(facing_up, false, -5.0).triangles.size(), 8u);
}
