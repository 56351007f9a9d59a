// Winding numbers taken per group of voxels give every voxel the side the
// exact winding number gives it, on a closed sphere and on a box with an open
// face (where w varies off the surface), in the band and off it, and most
// leaves of the closed sphere are taken by groups.
#include <gtest/gtest.h>

#include <cmath>

#include <openvdb/tree/LeafManager.h>

#include "core/progress.h"
#include "support/shapes.h"
#include "volume/edge_table.h"
#include "volume/leaf_winding.h"
#include "volume/position_ids.h"
#include "volume/unsigned_band.h"
#include "volume/winding_gradient_bound.h"

namespace {

using fabvdb::Mesh;
using fabvdb::Vec3;
namespace volume = fabvdb::volume;

Mesh open_box() { return fabvdb::test::make_open_box({0.13, 0.07, 0.11}, {10.13, 10.07, 10.11}); }

struct Counts {
    size_t grouped_leaves = 0, leaves = 0, band_checked = 0, off_band_checked = 0;
};

// Runs both steps on every leaf of the band of `mesh` and checks each voxel
// whose exact w is clear of 1/2 by more than the tree's error.
Counts check_sides(const Mesh& mesh, double voxel) {
    openvdb::initialize();
    fabvdb::Progress progress;
    const auto transform = openvdb::math::Transform::createLinearTransform(voxel);
    auto grid = volume::unsigned_band(mesh, *transform, 3.0f, progress);
    const volume::WindingNumber winding(mesh);
    const Mesh welded = volume::weld_positions(mesh);
    const volume::WindingGradientBound gradient(welded, volume::build_edge_table(welded));
    const float background = grid->background();
    const auto exact = [&](const openvdb::Coord& ijk) {
        const openvdb::Vec3d p = transform->indexToWorld(ijk);
        return winding.exact({p[0], p[1], p[2]});
    };
    Counts counts;
    openvdb::tree::LeafManager<openvdb::FloatTree> leaves(grid->tree());
    for (size_t i = 0; i < leaves.leafCount(); ++i) {
        volume::FloatLeaf& leaf = leaves.leaf(i);
        const openvdb::Vec3d lo = transform->indexToWorld(leaf.origin());
        const openvdb::Vec3d hi = transform->indexToWorld(leaf.origin().offsetBy(7));
        const double bound = gradient({{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}}, 0.5 / voxel);
        float w[volume::FloatLeaf::SIZE];
        const bool exact_band = volume::band_leaf_winding(leaf, winding, *transform, bound, w);
        ++counts.leaves;
        if (!exact_band) ++counts.grouped_leaves;
        const volume::FloatLeaf::NodeMaskType band = leaf.getValueMask();
        for (auto it = band.beginOn(); it; ++it) {
            const double e = exact(leaf.offsetToGlobalCoord(it.pos()));
            if (std::abs(e - 0.5) < 0.15) continue;
            EXPECT_EQ(w[it.pos()] >= 0.5, e >= 0.5);
            ++counts.band_checked;
            if (w[it.pos()] >= 0.5) leaf.setValueOn(it.pos(), -leaf.getValue(it.pos()));
        }
        volume::off_band_leaf_values(leaf, winding, *transform, bound, background, exact_band, w);
        for (auto it = band.beginOff(); it; ++it) {
            EXPECT_TRUE(leaf.isValueOn(it.pos()));
            const double e = exact(leaf.offsetToGlobalCoord(it.pos()));
            if (std::abs(e - 0.5) < 0.15) continue;
            EXPECT_EQ(leaf.getValue(it.pos()) < 0, e >= 0.5);
            ++counts.off_band_checked;
        }
    }
    return counts;
}

TEST(LeafWinding, ClosedSphereByGroups) {
    const Counts counts = check_sides(fabvdb::test::make_sphere({0.1, 0.2, 0.3}, 4.0, 3), 0.25);
    EXPECT_GT(counts.band_checked, 1000u);
    EXPECT_GT(counts.off_band_checked, 1000u);
    EXPECT_GT(counts.grouped_leaves, counts.leaves / 2);
}

TEST(LeafWinding, OpenBoxSidesAcrossAndAwayFromTheHole) {
    const Counts counts = check_sides(open_box(), 0.25);
    EXPECT_GT(counts.band_checked, 1000u);
    EXPECT_GT(counts.off_band_checked, 1000u);
    EXPECT_GT(counts.grouped_leaves, 0u);
    EXPECT_LT(counts.grouped_leaves, counts.leaves);
}

}  // namespace
