//! The inside runs of one index column of a dense block (index z
//! contiguous), and which run a double-height-field part keeps where other
//! parts split a column: the one that crosses the input surface most (the
//! input surface it carries), the longer on a tie. Shared by the sweep's
//! fill-or-trim choice, the part mesher and the hand-over of the runs a part
//! cannot keep, so all three agree run for run.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include <openvdb/openvdb.h>

namespace fabvdb::volume {

//! Samples [start, end) of a column are inside (value < 0).
struct Run {
    size_t start, end;
};

//! The runs of `column` (nz values), bottom to top. The caller's block has
//! an outside sample at each end of every column, so a run never touches it.
std::vector<Run> inside_runs(const float* column, size_t nz);

//! Index z, from the column's first sample, of the zero crossing between
//! samples k and k + 1 (values of opposite sign).
double zero_crossing(const float* column, size_t k);

//! Counts the sign changes of a level set (the input surface) over a run of
//! one column of a block and the outside samples bounding it. Not
//! thread-safe (holds an accessor): one per thread.
class SurfaceCrossings {
public:
    //! `block`: the block's index-to-world map; `origin`: the block's first
    //! index; `surface`: the level set (nullptr: every count is 0).
    SurfaceCrossings(const openvdb::math::Transform& block, const openvdb::Coord& origin,
                     const openvdb::FloatGrid* surface);
    //! The column at block offsets (i, j) (from `origin`).
    size_t count(int i, int j, const Run& run) const;

private:
    const openvdb::math::Transform& block_;
    openvdb::Coord origin_;
    const openvdb::FloatGrid* surface_;
    std::optional<openvdb::FloatGrid::ConstAccessor> accessor_;
};

//! Index into `runs` (not empty) of the run the column keeps: the most
//! surface crossings (counted only when there are several runs), the longer
//! on a tie, the lower on a full tie.
size_t kept_run(const std::vector<Run>& runs, const SurfaceCrossings& crossings, int i, int j);

}  // namespace fabvdb::volume
