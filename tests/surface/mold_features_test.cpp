//! mold_features, with circular parting lines over a parting surface on a
//! 1 mm grid one cell beyond a block with a 10 mm margin: the sizes are the
//! documented fractions of the margin; a vertical prism is closed with the
//! volume of its regular polygon times its height; the gate is the lowest
//! point of each circle, the one vent its highest point, the channels one
//! 4-connected region (own flood fill) that joins every gate to the block's
//! top face and keeps out of the parts' shadow; keys sit in the four corners
//! and each pin crosses the parting surface by the key height on both sides,
//! inside a hole that is wider and deeper by the clearance. A part with no
//! parting line is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <queue>
#include <string>

#include "core/error.h"
#include "support/ray_cast.h"
#include "support/shapes.h"
#include "surface/mold_features.h"

namespace {

using fabvdb::Mesh;
using fabvdb::Vec3;
using fabvdb::surface::HeightGrid;
using fabvdb::surface::MoldFeatures;

const double margin = 10;

//! `count` points on the circle of radius `radius` about (cx, 0) in z = 0,
//! starting at angle 0 (so 3/4 of the way round is the lowest point).
std::vector<Vec3> circle(double cx, double radius, int count) {
    std::vector<Vec3> line;
    for (int k = 0; k < count; ++k) {
        const double angle = 2 * M_PI * k / count;
        line.push_back({cx + radius * std::cos(angle), radius * std::sin(angle), 0.0});
    }
    return line;
}

//! The parting surface z = slope·x on a 1 mm grid one cell beyond the block.
HeightGrid planar_surface(const Vec3& block_lo, const Vec3& block_hi, double slope) {
    HeightGrid grid;
    grid.step = 1;
    grid.x0 = block_lo[0] - 1;
    grid.y0 = block_lo[1] - 1;
    grid.nx = int(block_hi[0] - block_lo[0]) + 2;
    grid.ny = int(block_hi[1] - block_lo[1]) + 2;
    for (int j = 0; j <= grid.ny; ++j)
        for (int i = 0; i <= grid.nx; ++i) grid.z.push_back(slope * grid.x(i));
    return grid;
}

//! One part: a disk of radius 10 at the origin in a block 10 mm wider all round.
struct OneDisk {
    Vec3 part_lo{-10, -10, -5}, part_hi{10, 10, 5};
    Vec3 block_lo{-20, -20, -15}, block_hi{20, 20, 15};
    std::vector<std::vector<Vec3>> lines{circle(0, 10, 36)};
    MoldFeatures place(const HeightGrid& surface) const {
        return fabvdb::surface::place_mold_features(lines, surface, block_lo, block_hi, part_lo, part_hi,
                                                    fabvdb::surface::mold_feature_sizes(margin));
    }
};

//! The cell of the grid holding (x, y).
size_t cell_at(const HeightGrid& grid, double x, double y) {
    const int i = int(std::floor((x - grid.x0) / grid.step)), j = int(std::floor((y - grid.y0) / grid.step));
    return size_t(j) * size_t(grid.nx) + size_t(i);
}

//! Channel cells 4-connected to `start` (empty if `start` is no channel cell).
std::vector<char> channel_region(const HeightGrid& grid, const std::vector<char>& cells, size_t start) {
    std::vector<char> reached(cells.size(), 0);
    if (!cells[start]) return reached;
    std::queue<size_t> queue;
    queue.push(start);
    reached[start] = 1;
    while (!queue.empty()) {
        const int c = int(queue.front()), i = c % grid.nx, j = c / grid.nx;
        queue.pop();
        const int neighbours[4][2] = {{i - 1, j}, {i + 1, j}, {i, j - 1}, {i, j + 1}};
        for (const auto& [a, b] : neighbours) {
            if (a < 0 || b < 0 || a >= grid.nx || b >= grid.ny) continue;
            const size_t n = size_t(b) * size_t(grid.nx) + size_t(a);
            if (cells[n] && !reached[n]) {
                reached[n] = 1;
                queue.push(n);
            }
        }
    }
    return reached;
}

//! Whether a cell of the top row (the block's +Y face and beyond) is in `region`.
bool reaches_top(const HeightGrid& grid, const std::vector<char>& region) {
    for (int i = 0; i < grid.nx; ++i)
        if (region[size_t(grid.ny - 1) * size_t(grid.nx) + size_t(i)]) return true;
    return false;
}

//! Volume of a regular `sides`-gon prism of circumradius r and height h.
double prism_volume(double r, double h, int sides) { return 0.5 * sides * r * r * std::sin(2 * M_PI / sides) * h; }

//! z range of the mesh's vertices within `radius` of (x, y) horizontally.
std::array<double, 2> z_range_near(const Mesh& mesh, double x, double y, double radius) {
    std::array<double, 2> range{1e300, -1e300};
    for (const Vec3& v : mesh.vertices)
        if (std::hypot(v[0] - x, v[1] - y) <= radius + 1e-9) {
            range[0] = std::min(range[0], v[2]);
            range[1] = std::max(range[1], v[2]);
        }
    return range;
}

void expect_bad_input(const std::vector<std::vector<Vec3>>& lines, const std::string& text) {
    const OneDisk disk;
    const HeightGrid surface = planar_surface(disk.block_lo, disk.block_hi, 0);
    try {
        fabvdb::surface::place_mold_features(lines, surface, disk.block_lo, disk.block_hi, disk.part_lo, disk.part_hi,
                                             fabvdb::surface::mold_feature_sizes(margin));
        ADD_FAILURE() << "no exception";
    } catch (const fabvdb::Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_BAD_INPUT);
        EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    }
}

}  // namespace

TEST(MoldFeatureSizes, AreTheDocumentedFractionsOfTheMargin) {
    const auto sizes = fabvdb::surface::mold_feature_sizes(15.0);
    EXPECT_DOUBLE_EQ(2 * sizes.runner_half_width, 15.0 / 5);
    EXPECT_DOUBLE_EQ(2 * sizes.vent_half_width, 15.0 / 15);
    EXPECT_DOUBLE_EQ(2 * sizes.key_radius, 15.0 / 5);
    EXPECT_DOUBLE_EQ(sizes.key_height, 15.0 / 5);
    EXPECT_DOUBLE_EQ(sizes.key_clearance, 0.2);
}

TEST(VerticalPrism, IsClosedWithThePolygonAreaTimesItsHeight) {
    const Mesh prism = fabvdb::surface::vertical_prism(3, -2, 1.5, -1, 4, 24);
    EXPECT_TRUE(fabvdb::test::closed_two_manifold(prism));
    EXPECT_NEAR(fabvdb::test::mesh_volume(prism), prism_volume(1.5, 5, 24), 1e-9);
    for (const Vec3& v : prism.vertices) {
        EXPECT_LE(std::hypot(v[0] - 3, v[1] + 2), 1.5 + 1e-12);
        EXPECT_TRUE(v[2] == -1 || v[2] == 4) << v[2];
    }
}

TEST(PlaceMoldFeatures, GateAtTheLowestPointVentAtTheHighest) {
    const OneDisk disk;
    const MoldFeatures features = disk.place(planar_surface(disk.block_lo, disk.block_hi, 0));
    ASSERT_EQ(features.gates.size(), 1u);
    EXPECT_NEAR(features.gates[0][0], 0, 1e-9);
    EXPECT_NEAR(features.gates[0][1], -10, 1e-9);
    ASSERT_EQ(features.vents.size(), 1u);
    EXPECT_NEAR(features.vents[0][0], 0, 1e-9);
    EXPECT_NEAR(features.vents[0][1], 10, 1e-9);
}

TEST(PlaceMoldFeatures, ChannelsJoinTheGateAndTheVentToTheTopFaceOutsideThePart) {
    const OneDisk disk;
    const HeightGrid surface = planar_surface(disk.block_lo, disk.block_hi, 0);
    const MoldFeatures features = disk.place(surface);
    ASSERT_EQ(features.channel_cells.size(), size_t(surface.nx) * size_t(surface.ny));
    const std::vector<char> runner = channel_region(surface, features.channel_cells, cell_at(surface, 0.5, -10.5));
    EXPECT_TRUE(reaches_top(surface, runner));
    const std::vector<char> vent = channel_region(surface, features.channel_cells, cell_at(surface, 0.5, 10.5));
    EXPECT_TRUE(reaches_top(surface, vent));
    // Away from the gate and vent (by the runner's half width and a cell),
    // no channel cell lies over the disk.
    for (int j = 0; j < surface.ny; ++j)
        for (int i = 0; i < surface.nx; ++i) {
            if (!features.channel_cells[size_t(j) * size_t(surface.nx) + size_t(i)]) continue;
            const double x = surface.x(i) + 0.5, y = surface.y(j) + 0.5;
            EXPECT_GT(std::hypot(x, y), 10 - 1 - std::sqrt(0.5)) << "cell at " << x << ", " << y;
        }
}

TEST(PlaceMoldFeatures, TwoPartsInARowShareOneRunnerToTheSprue) {
    const std::vector<std::vector<Vec3>> lines{circle(-15, 8, 36), circle(15, 8, 36)};
    const Vec3 part_lo{-23, -8, -5}, part_hi{23, 8, 5}, block_lo{-33, -18, -15}, block_hi{33, 18, 15};
    const HeightGrid surface = planar_surface(block_lo, block_hi, 0);
    const MoldFeatures features = fabvdb::surface::place_mold_features(
        lines, surface, block_lo, block_hi, part_lo, part_hi, fabvdb::surface::mold_feature_sizes(margin));
    ASSERT_EQ(features.gates.size(), 2u);
    EXPECT_NEAR(features.gates[0][0], -15, 1e-9);
    EXPECT_NEAR(features.gates[1][0], 15, 1e-9);
    const std::vector<char> region = channel_region(surface, features.channel_cells, cell_at(surface, -14.5, -8.5));
    EXPECT_TRUE(region[cell_at(surface, 15.5, -8.5)]) << "the gates are not joined";
    EXPECT_TRUE(reaches_top(surface, region));
}

TEST(PlaceMoldFeatures, KeysInTheCornersCrossTheSurfaceInsideWiderHoles) {
    const OneDisk disk;
    const double slope = 0.2;
    const HeightGrid surface = planar_surface(disk.block_lo, disk.block_hi, slope);
    const MoldFeatures features = disk.place(surface);
    const auto sizes = fabvdb::surface::mold_feature_sizes(margin);
    // Corners inset by 0.35 of the margin.
    ASSERT_EQ(features.key_centers.size(), 4u);
    for (const auto& c : features.key_centers) {
        EXPECT_NEAR(std::abs(c[0]), 16.5, 1e-9);
        EXPECT_NEAR(std::abs(c[1]), 16.5, 1e-9);
    }
    EXPECT_TRUE(fabvdb::test::closed_two_manifold(features.pins));
    EXPECT_TRUE(fabvdb::test::closed_two_manifold(features.holes));
    double pins_volume = 0, holes_volume = 0;
    for (const auto& c : features.key_centers) {
        // The surface under a key spans slope·(x ± radius).
        const double r = sizes.key_radius, hole_r = r + sizes.key_clearance;
        const auto pin = z_range_near(features.pins, c[0], c[1], r);
        const auto hole = z_range_near(features.holes, c[0], c[1], hole_r);
        EXPECT_LE(pin[0], slope * (c[0] - r) - sizes.key_height);
        EXPECT_GE(pin[1], slope * (c[0] + r) + sizes.key_height);
        EXPECT_DOUBLE_EQ(hole[0], pin[0]);
        EXPECT_DOUBLE_EQ(hole[1], pin[1] + sizes.key_clearance);
        pins_volume += prism_volume(r, pin[1] - pin[0], 24);
        holes_volume += prism_volume(hole_r, hole[1] - hole[0], 24);
    }
    EXPECT_NEAR(fabvdb::test::mesh_volume(features.pins), pins_volume, 1e-9 * pins_volume);
    EXPECT_NEAR(fabvdb::test::mesh_volume(features.holes), holes_volume, 1e-9 * holes_volume);
}

TEST(PlaceMoldFeatures, RefusesAPartWithoutAPartingLine) {
    expect_bad_input({circle(0, 10, 36), {}}, "a part has no parting line");
    expect_bad_input({}, "the part has no parting line");
}
