// The Gaussian RBF parting surface: passes through the parting line, is
// smooth between, flattens to the mean height far from it, stays inside the
// block; and its sheet is a grid of upward triangles.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "surface/parting_surface.h"

namespace {

using fabvdb::Vec3;
using fabvdb::surface::HeightGrid;

HeightGrid grid_over(double lo, double hi, double step) {
    HeightGrid grid;
    grid.x0 = grid.y0 = lo;
    grid.step = step;
    grid.nx = grid.ny = int(std::round((hi - lo) / step));
    return grid;
}

// Bilinear-free lookup: the nearest grid vertex's height.
double nearest(const HeightGrid& grid, double x, double y) {
    const int i = int(std::round((x - grid.x0) / grid.step)), j = int(std::round((y - grid.y0) / grid.step));
    return grid.at(i, j);
}

TEST(PartingSurface, InterpolatesAWavyLoop) {
    // A circle of radius 20 whose height waves twice around it.
    std::vector<Vec3> line;
    for (int k = 0; k < 400; ++k) {
        const double a = 2 * M_PI * k / 400;
        line.push_back({20 * std::cos(a), 20 * std::sin(a), 3 * std::cos(2 * a)});
    }
    HeightGrid grid = grid_over(-60, 60, 0.5);
    fabvdb::surface::interpolate_parting_surface(line, -20, 20, {}, grid);
    for (int k = 0; k < 400; k += 7) {
        const Vec3& p = line[k];
        // The grid vertex is within 0.36 of the point; the slope is below 1.
        EXPECT_NEAR(nearest(grid, p[0], p[1]), p[2], 0.5) << k;
    }
    EXPECT_NEAR(grid.at(0, 0), 0.0, 0.05);  // far corner: the mean height
    for (double z : grid.z) {
        EXPECT_GE(z, -20);
        EXPECT_LE(z, 20);
    }
    const fabvdb::Mesh sheet = fabvdb::surface::height_grid_sheet(grid);
    EXPECT_EQ(sheet.triangles.size(), size_t(2 * grid.nx * grid.ny));
    for (const auto& t : sheet.triangles) {
        const Vec3 &a = sheet.vertices[t[0]], &b = sheet.vertices[t[1]], &c = sheet.vertices[t[2]];
        EXPECT_GT((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]), 0.0);
    }
}

TEST(PartingSurface, ClampsToTheBlock) {
    std::vector<Vec3> line{{0, 0, 50}, {1, 0, 50}, {0, 1, 50}, {1, 1, 50}};
    HeightGrid grid = grid_over(-5, 5, 1);
    fabvdb::surface::interpolate_parting_surface(line, -10, 10, {}, grid);
    for (double z : grid.z) EXPECT_LE(z, 10.0);
}

TEST(PartingSurface, RefusesTooFewPointsAndEmptyGrids) {
    HeightGrid grid = grid_over(0, 1, 1);
    EXPECT_THROW(fabvdb::surface::interpolate_parting_surface({{0, 0, 0}}, 0, 1, {}, grid), fabvdb::Error);
    HeightGrid empty;
    EXPECT_THROW(fabvdb::surface::interpolate_parting_surface({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, 0, 1, {}, empty),
                 fabvdb::Error);
}

}  // namespace
