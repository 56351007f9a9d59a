//! trim_deep_fills, worked by hand on a box-shaped part (voxel 1 mm, x 10–29,
//! y 5–24, z 2–30 once swept) whose columns hold two runs:
//! - half A (x 10–19): a one-voxel run at z = 2 under a run z 4–30, so the
//!   surfaces at the gap lie at most 2 voxels above the bottom face;
//! - half B (x 20–29): runs z 2–10 and z 18–30, the gap's surfaces 9 and 13
//!   voxels inside, deeper than the 4·min_depth = 8 the depth is measured to,
//!   save within 4 voxels of a side face (x = 29.5, y = 4.5, y = 24.5).
//! With min_depth 2 the region is deep (8 > 2), so the columns less than half
//! as deep (< 4) are trimmed: all of A, and B within 3.5 voxels of a side
//! face; B's inner 6 × 12 columns, 4.5 voxels or more from every face, stay
//! filled. A trimmed column keeps the run with input surface at both ends,
//! the longer (A: z 4–30, B: z 18–30). Another part holds the whole block,
//! so no given-up surface asks for a refill. Columns without a gap and the
//! empty ones are not touched.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include <openvdb/tools/Dense.h>

#include "core/progress.h"
#include "volume/trim_deep_fills.h"

namespace {

struct Interval {
    int start, end;  // inside samples start..end (inclusive)
};

constexpr int kNx = 40, kNy = 30, kNz = 34;

//! Signed distance along z to a union of intervals (voxel 1): negative
//! inside, the surface half a voxel beyond each interval's end samples; +3
//! (outside) for none.
float along_z(const std::vector<Interval>& runs, int k) {
    float value = 3.0f;
    for (const Interval& r : runs) value = std::min(value, float(std::max(r.start - 0.5 - k, k - r.end - 0.5)));
    return value;
}

bool in_part(int i, int j) { return i >= 10 && i < 30 && j >= 5 && j < 25; }

std::vector<Interval> runs_before(int i, int j) {
    if (!in_part(i, j)) return {};
    if (i < 20) return {{2, 2}, {4, 30}};
    return {{2, 10}, {18, 30}};
}

//! Whether a column of half B lies 4.5 voxels or more from every side face.
bool deep_column(int i, int j) { return i >= 20 && i < 26 && j >= 9 && j < 21; }

openvdb::FloatGrid::Ptr level_set(const openvdb::tools::Dense<float>& block, const openvdb::math::Transform& xform) {
    auto grid = openvdb::FloatGrid::create(3.0f);
    grid->setTransform(xform.copy());
    grid->setGridClass(openvdb::GRID_LEVEL_SET);
    openvdb::tools::copyFromDense(block, *grid, 0.0f);
    return grid;
}

}  // namespace

TEST(TrimDeepFills, ShallowHalfOfADeepRegionIsTrimmed) {
    openvdb::initialize();
    const auto xform = openvdb::math::Transform::createLinearTransform(1.0);
    const openvdb::CoordBBox bbox(openvdb::Coord(0, 0, 0), openvdb::Coord(kNx - 1, kNy - 1, kNz - 1));
    openvdb::tools::Dense<float> original_block(bbox), filled(bbox);
    for (int i = 0; i < kNx; ++i)
        for (int j = 0; j < kNy; ++j)
            for (int k = 0; k < kNz; ++k) {
                const std::vector<Interval> before = runs_before(i, j);
                original_block.setValue(openvdb::Coord(i, j, k), along_z(before, k));
                const std::vector<Interval> swept =
                    before.empty() ? before : std::vector<Interval>{{before.front().start, before.back().end}};
                filled.setValue(openvdb::Coord(i, j, k), along_z(swept, k));
            }
    const std::vector<float> original(original_block.data(), original_block.data() + original_block.valueCount());
    const std::vector<float> swept(filled.data(), filled.data() + filled.valueCount());
    const openvdb::FloatGrid::Ptr surface = level_set(original_block, *xform);
    // Another part holding the whole block: no input surface is given up.
    openvdb::tools::Dense<float> everywhere(bbox, -3.0f);
    const openvdb::FloatGrid::Ptr others = level_set(everywhere, *xform);

    fabvdb::Progress progress;
    const size_t trimmed =
        fabvdb::volume::trim_deep_fills(original, filled, *xform, *surface, 3.0f, 2.0, others.get(), progress);

    size_t expected_trimmed = 0;
    for (int i = 0; i < kNx; ++i)
        for (int j = 0; j < kNy; ++j) {
            const size_t c = size_t(i) * kNy + size_t(j);
            const float* after = filled.data() + c * kNz;
            const float* before_swept = swept.data() + c * kNz;
            std::vector<int> inside;
            for (int k = 0; k < kNz; ++k)
                if (after[k] < 0) inside.push_back(k);
            if (!in_part(i, j)) {
                EXPECT_TRUE(inside.empty()) << i << " " << j;
                continue;
            }
            if (deep_column(i, j)) {
                // Still filled, as swept.
                EXPECT_TRUE(std::equal(after, after + kNz, before_swept)) << "column " << i << " " << j;
                continue;
            }
            ++expected_trimmed;
            const Interval kept = i < 20 ? Interval{4, 30} : Interval{18, 30};
            ASSERT_FALSE(inside.empty()) << i << " " << j;
            EXPECT_EQ(inside.front(), kept.start) << "column " << i << " " << j;
            EXPECT_EQ(inside.back(), kept.end) << "column " << i << " " << j;
            EXPECT_EQ(inside.size(), size_t(kept.end - kept.start + 1)) << "column " << i << " " << j;
        }
    EXPECT_EQ(expected_trimmed, 200u + 128u);
    EXPECT_EQ(trimmed, expected_trimmed);
}

TEST(TrimDeepFills, ShallowRegionStaysFilled) {
    // Only half A's gaps (at most 2 voxels deep), and min_depth 3: no region
    // is deeper than min_depth, nothing is trimmed.
    openvdb::initialize();
    const auto xform = openvdb::math::Transform::createLinearTransform(1.0);
    const openvdb::CoordBBox bbox(openvdb::Coord(0, 0, 0), openvdb::Coord(kNx - 1, kNy - 1, kNz - 1));
    openvdb::tools::Dense<float> original_block(bbox), filled(bbox);
    for (int i = 0; i < kNx; ++i)
        for (int j = 0; j < kNy; ++j)
            for (int k = 0; k < kNz; ++k) {
                const std::vector<Interval> before =
                    in_part(i, j) ? std::vector<Interval>{{2, 2}, {4, 30}} : std::vector<Interval>{};
                original_block.setValue(openvdb::Coord(i, j, k), along_z(before, k));
                filled.setValue(openvdb::Coord(i, j, k),
                                along_z(before.empty() ? before : std::vector<Interval>{{2, 30}}, k));
            }
    const std::vector<float> original(original_block.data(), original_block.data() + original_block.valueCount());
    const std::vector<float> swept(filled.data(), filled.data() + filled.valueCount());
    fabvdb::Progress progress;
    EXPECT_EQ(fabvdb::volume::trim_deep_fills(original, filled, *xform, *level_set(original_block, *xform), 3.0f, 3.0,
                                              nullptr, progress),
              0u);
    EXPECT_TRUE(std::equal(swept.begin(), swept.end(), filled.data()));
}
