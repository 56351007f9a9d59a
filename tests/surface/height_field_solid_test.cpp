// The solid between two height fields over grid cells: closed, outward, its
// volume the integral of (upper − lower) over the cells, lines along Z cross
// it twice; cells that touch only at a corner are refused, and joined by
// join_corner_contacts into cells it accepts.
#include <gtest/gtest.h>

#include "core/error.h"
#include "support/ray_cast.h"
#include "support/shapes.h"
#include "surface/height_field_solid.h"

namespace {

using fabvdb::surface::HeightGrid;

TEST(HeightFieldSolid, LShapedSlabUnderATiltedTop) {
    HeightGrid grid;
    grid.x0 = -1;
    grid.y0 = 2;
    grid.step = 0.5;
    grid.nx = 6;
    grid.ny = 5;
    std::vector<char> cells(size_t(grid.nx * grid.ny), 0);
    for (int i = 0; i < 6; ++i) cells[size_t(i)] = 1;                  // bottom row
    for (int j = 0; j < 5; ++j) cells[size_t(j * grid.nx + 5)] = 1;     // right column
    std::vector<double> lower((grid.nx + 1) * (grid.ny + 1)), upper(lower.size());
    for (int j = 0; j <= grid.ny; ++j)
        for (int i = 0; i <= grid.nx; ++i) {
            const size_t v = size_t(j * (grid.nx + 1) + i);
            lower[v] = -1.0;
            upper[v] = 2.0 + 0.3 * grid.x(i) - 0.1 * grid.y(j);  // a plane: linear over every triangle
        }
    const fabvdb::Mesh solid = fabvdb::surface::height_field_solid(grid, cells, lower, upper);
    EXPECT_TRUE(fabvdb::test::closed_two_manifold(solid));
    EXPECT_FALSE(fabvdb::test::self_intersects(solid));
    double expected = 0;
    for (int j = 0; j < grid.ny; ++j)
        for (int i = 0; i < grid.nx; ++i)
            if (cells[size_t(j * grid.nx + i)]) {
                const double cx = grid.x(i) + 0.25, cy = grid.y(j) + 0.25;
                expected += 0.25 * (2.0 + 0.3 * cx - 0.1 * cy + 1.0);
            }
    EXPECT_NEAR(fabvdb::test::mesh_volume(solid), expected, 1e-9);
    const auto lines = fabvdb::test::check_double_height_field(solid, {0, 0, 1}, 40);
    EXPECT_GT(lines.lines, 100u);
    EXPECT_EQ(lines.lines_over_two, 0u);
}

TEST(HeightFieldSolid, RefusesCornerContactsAndInvertedHeights) {
    HeightGrid grid;
    grid.nx = grid.ny = 2;
    std::vector<double> lower(9, 0.0), upper(9, 1.0);
    const std::vector<char> diagonal{1, 0, 0, 1};
    EXPECT_THROW(fabvdb::surface::height_field_solid(grid, diagonal, lower, upper), fabvdb::Error);
    const std::vector<char> one{1, 0, 0, 0};
    EXPECT_THROW(fabvdb::surface::height_field_solid(grid, one, upper, lower), fabvdb::Error);
    EXPECT_THROW(fabvdb::surface::height_field_solid(grid, one, lower, std::vector<double>(3, 1.0)), fabvdb::Error);
}

TEST(HeightFieldSolid, JoinsCellsThatTouchOnlyAtACorner) {
    HeightGrid grid;
    grid.nx = 4;
    grid.ny = 3;
    // A staircase: each marked cell touches the next only at a corner.
    std::vector<char> cells(12, 0);
    cells[0] = cells[1 * 4 + 1] = cells[2 * 4 + 2] = 1;
    cells[2 * 4 + 0] = 1;  // touches (1, 1) at a corner from the other side
    const std::vector<char> given = cells;
    const size_t added = fabvdb::surface::join_corner_contacts(grid, cells);
    EXPECT_GT(added, 0u);
    size_t kept = 0, count = 0;
    for (size_t c = 0; c < cells.size(); ++c) {
        kept += given[c] && cells[c];
        count += cells[c] != given[c];
    }
    EXPECT_EQ(kept, 4u);
    EXPECT_EQ(count, added);
    for (int j = 0; j + 1 < grid.ny; ++j)
        for (int i = 0; i + 1 < grid.nx; ++i) {
            const bool a = cells[size_t(j * 4 + i)], b = cells[size_t(j * 4 + i + 1)];
            const bool c = cells[size_t((j + 1) * 4 + i)], d = cells[size_t((j + 1) * 4 + i + 1)];
            EXPECT_FALSE((a && d && !b && !c) || (b && c && !a && !d)) << "corner contact at " << i << ", " << j;
        }
    std::vector<double> lower(20, 0.0), upper(20, 1.0);
    const fabvdb::Mesh solid = fabvdb::surface::height_field_solid(grid, cells, lower, upper);
    EXPECT_TRUE(fabvdb::test::closed_two_manifold(solid));
    EXPECT_NEAR(fabvdb::test::mesh_volume(solid), double(4 + added), 1e-12);
    std::vector<char> none(12, 0);
    EXPECT_EQ(fabvdb::surface::join_corner_contacts(grid, none), 0u);
}

}  // namespace
