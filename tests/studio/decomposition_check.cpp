//! decomposition_check FILE.json — runs the independent checks of
//! tests/support/decomposition_checks (parts disjoint and covering, each part
//! connected, M⁺ and M⁻ of each part connected, overhang energies measured
//! again) on a decomposition.json written by someone else: the studio's
//! browser test calls it on what the page saved.
//! decomposition_check --cast PART.stl TOP.stl BOTTOM.stl DX DY DZ — checks
//! a cast part and its two mold pieces as the page's "Make molds" wrote them
//! (support/ray_cast: each closed, 2-manifold, free of self-intersections and
//! of triangles degenerate as stored, of positive volume; the part a double
//! height field along d).
//! Exit 0 when every check passes, 1 otherwise (gtest prints which).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/progress.h"
#include "io/mesh_io.h"
#include "support/decomposition_checks.h"
#include "support/ray_cast.h"
#include "support/shapes.h"

namespace {

std::string checked_path;
std::vector<std::string> cast_paths;  // part, top, bottom
fabvdb::Vec3 cast_direction{0, 0, 1};

TEST(CastPart, PartAndMoldPiecesAreValidSolids) {
    if (cast_paths.empty()) GTEST_SKIP();
    fabvdb::Progress progress;
    for (size_t i = 0; i < cast_paths.size(); ++i) {
        const fabvdb::Mesh mesh = fabvdb::io::read_mesh(cast_paths[i], progress);
        SCOPED_TRACE(cast_paths[i]);
        EXPECT_TRUE(fabvdb::test::closed_two_manifold(mesh));
        EXPECT_FALSE(fabvdb::test::self_intersects(mesh));
        EXPECT_EQ(fabvdb::test::degenerate_triangle_count(fabvdb::test::stored_as_float(mesh)), 0u);
        EXPECT_GT(fabvdb::test::mesh_volume(mesh), 0.0);
        if (i == 0) {
            const fabvdb::test::HeightFieldCheck field =
                fabvdb::test::check_double_height_field(mesh, cast_direction, 60);
            EXPECT_GT(field.lines, 0u);
            EXPECT_EQ(field.lines_over_two, 0u);
            EXPECT_EQ(field.odd_lines, 0u);
        }
    }
}

TEST(SavedDecomposition, PassesTheIndependentChecks) {
    if (checked_path.empty()) GTEST_SKIP();
    const nlohmann::json document = fabvdb::test::read_decomposition(checked_path);
    const std::vector<double> areas = fabvdb::test::check_decomposition(document);
    EXPECT_GE(areas.size(), 1u);
    for (double area : areas) EXPECT_GT(area, 0.0);
}

}  // namespace

int main(int argc, char** argv) {
    testing::InitGoogleTest(&argc, argv);
    if (argc == 8 && std::string(argv[1]) == "--cast") {
        cast_paths = {argv[2], argv[3], argv[4]};
        cast_direction = {std::atof(argv[5]), std::atof(argv[6]), std::atof(argv[7])};
    } else if (argc == 2) {
        checked_path = argv[1];
    } else {
        fprintf(stderr, "usage: decomposition_check FILE.json | --cast PART.stl TOP.stl BOTTOM.stl DX DY DZ\n");
        return 2;
    }
    return RUN_ALL_TESTS();
}
