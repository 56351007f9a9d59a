// Overhang removal by ARAP deformation on a folded sheet: two 1.5 mm plates
// one above the other, 1 mm apart over two thirds of their length and joined
// over the rest, so lines along +Z through the fold cross it four times. The
// deformation must pull the plates together (the swept part then adds much
// less than the sweep alone, which fills the gap), keep the surface within
// the displacement bound of the input's outer faces, and leave a part the
// sweep turns into a double height field. Volumes by the divergence theorem
// on the meshes and moldability, inside and outside by the test support's own
// ray casting, not by anything the deformation or the sweep computed.
#include <gtest/gtest.h>

#include <atomic>

#include <openvdb/openvdb.h>
#include <openvdb/tools/Composite.h>

#include "core/error.h"
#include "support/plain_level_set.h"
#include "support/ray_cast.h"
#include "support/shapes.h"
#include "surface/overhang_deformation.h"
#include "volume/double_height_field_mesh.h"
#include "volume/sweep.h"

namespace {

using fabvdb::Mesh;
using fabvdb::Vec3;
using fabvdb::test::make_box;
using fabvdb::test::mesh_volume;
using fabvdb::test::plain_level_set;

const double voxel = 0.3;                 // mm
const double gap_volume = 20 * 30 * 1.0;  // the fold's gap: x < 20, 1 mm high
const Vec3 up{0, 0, 1};

class OverhangDeformation : public ::testing::Test {
protected:
    static void SetUpTestSuite() { openvdb::initialize(); }

    // 30 x 30 x 4 mm with the gap z in [1.5, 2.5] cut in from x = 0 to 20.
    static openvdb::FloatGrid::Ptr folded_sheet() {
        auto sheet = plain_level_set(make_box({0, 0, 0}, {30, 30, 4}), voxel);
        auto gap = plain_level_set(make_box({-2, -2, 1.5}, {20, 32, 2.5}), voxel);
        openvdb::tools::csgDifference(*sheet, *gap);
        return sheet;
    }

    static Mesh swept_part(const openvdb::FloatGrid& part) {
        fabvdb::Progress progress;
        auto swept = fabvdb::volume::sweep_double_height_field(part, up, {}, {}, progress);
        return fabvdb::volume::double_height_field_mesh(*swept, progress);
    }
};

TEST_F(OverhangDeformation, FoldClosesWithLessAddedVolumeAndStaysNearTheInput) {
    const auto sheet = folded_sheet();
    fabvdb::Progress progress;
    fabvdb::surface::OverhangDeformationOptions options;
    options.max_displacement = 0.6;
    const auto deformation = fabvdb::surface::deform_overhangs(*sheet, up, {}, options, progress);
    EXPECT_GT(deformation.handles, 1000u);
    EXPECT_GT(deformation.max_displacement, 0.4);
    EXPECT_LE(deformation.max_displacement, 2 * options.max_displacement);

    const Mesh swept_only = swept_part(*sheet);
    const Mesh deformed = swept_part(*deformation.part);
    // Premise: the sweep alone fills the gap.
    const double sheet_volume = 30 * 30 * 4 - gap_volume;
    EXPECT_NEAR(mesh_volume(swept_only) - sheet_volume, gap_volume, 0.1 * gap_volume);
    // With the deformation, at most half of it is added.
    EXPECT_LT(mesh_volume(deformed) - sheet_volume, 0.5 * gap_volume);

    // Still moldable along +Z after the sweep.
    const auto lines = fabvdb::test::check_double_height_field(deformed, up, 60);
    EXPECT_GT(lines.lines, 1000u);
    EXPECT_EQ(lines.lines_over_two, 0u);
    EXPECT_EQ(lines.odd_lines, 0u);

    // The outer faces (top, bottom, and the far end) moved by at most the
    // bound and a voxel: a point that far inside each face is inside the
    // result, that far outside is outside.
    const fabvdb::test::LineCaster caster(deformed, {0.31, 0.57, 0.76});
    const double reach = 2 * options.max_displacement + voxel;
    int checked = 0;
    for (double a = 3; a <= 27; a += 3)
        for (double b = 3; b <= 27; b += 3) {
            const std::vector<std::pair<Vec3, Vec3>> faces = {
                {{a, b, 4}, {0, 0, 1}}, {{a, b, 0}, {0, 0, -1}}, {{30, a, 0.4 + b * 0.12}, {1, 0, 0}}};
            for (const auto& [point, normal] : faces) {
                const Vec3 in{point[0] - reach * normal[0], point[1] - reach * normal[1], point[2] - reach * normal[2]};
                const Vec3 out{point[0] + reach * normal[0], point[1] + reach * normal[1],
                               point[2] + reach * normal[2]};
                EXPECT_TRUE(caster.inside(in)) << in[0] << " " << in[1] << " " << in[2];
                EXPECT_FALSE(caster.inside(out)) << out[0] << " " << out[1] << " " << out[2];
                ++checked;
            }
        }
    EXPECT_EQ(checked, 243);
}

TEST_F(OverhangDeformation, GapFilledByAnotherPartIsNotClosed) {
    const auto sheet = folded_sheet();
    // Another part occupies the gap: nothing may be pulled into it.
    const openvdb::FloatGrid::ConstPtr other = plain_level_set(make_box({-2, -2, 1.5}, {20, 32, 2.5}), voxel);
    fabvdb::Progress progress;
    fabvdb::surface::OverhangDeformationOptions options;
    options.max_displacement = 0.6;
    const auto deformation = fabvdb::surface::deform_overhangs(*sheet, up, {other}, options, progress);
    EXPECT_EQ(deformation.handles, 0u);
    EXPECT_EQ(deformation.moved_vertices, 0u);
    EXPECT_NEAR(mesh_volume(swept_part(*deformation.part)), mesh_volume(swept_part(*sheet)), 1e-6 * gap_volume);
}

TEST_F(OverhangDeformation, RefusesBadOptionsAndCancels) {
    const auto sheet = folded_sheet();
    fabvdb::Progress progress;
    fabvdb::surface::OverhangDeformationOptions options;
    try {
        fabvdb::surface::deform_overhangs(*sheet, up, {}, options, progress);
        ADD_FAILURE() << "a zero displacement was accepted";
    } catch (const fabvdb::Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_INVALID_ARGUMENT);
    }
    options.max_displacement = 0.6;
    std::atomic<bool> cancel{true};
    fabvdb::Progress cancelled(nullptr, nullptr, &cancel);
    try {
        fabvdb::surface::deform_overhangs(*sheet, up, {}, options, cancelled);
        ADD_FAILURE() << "a cancelled deformation returned";
    } catch (const fabvdb::Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_CANCELLED);
    }
}

}  // namespace
