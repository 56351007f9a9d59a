//! Fill or trim, per column (thesis §3.6.2, the sweep's choice): where a
//! column along the parting direction meets a part in several runs, the
//! sweep fills the gaps between them, and the input surface bounding a gap
//! ends up buried inside the cast part. When such gaps form a connected
//! region (4-neighbour columns) whose deepest buried input surface lies
//! deeper than `min_depth` below the filled part's surface, the region is
//! split: columns whose own buried surface lies less than half that depth
//! deep are trimmed instead (they keep one run, the one carrying the most
//! input surface, the longer on a tie, and give up the others), the deeper
//! ones stay filled. A groove undercut by depth h then leaves its surface
//! within about h/2 of the part, filled on one side and trimmed on the
//! other, instead of buried h deep. A trimmed column is filled again when
//! the input surface it gave up lies farther from the trimmed part than its
//! own buried depth (rounds of this grow a fill over a given-up thin edge). Depths are measured in 3D on the filled
//! part's rebuilt signed distance, out to 4·min_depth (a deeper region counts
//! as that deep, so it is trimmed over a strip 2·min_depth deep only). Works
//! on the sweep's dense column block (index z along the parting direction).
//! Cancellable.
#pragma once

#include <cstddef>
#include <vector>

#include <openvdb/openvdb.h>
#include <openvdb/tools/Dense.h>

#include "core/progress.h"

namespace fabvdb::volume {

//! `original`: the block's values before the sweep (same layout as `filled`,
//! index z contiguous). `filled`: the swept block, rewritten in the trimmed
//! columns. `transform`: the block's index-to-world map. `surface`: level set
//! of the input surface (a run end counts as input surface within a voxel of
//! its zero). `background`: the part's narrow-band half width, mm. `others`:
//! the other parts' union as a level set (nullptr: none); input surface they
//! hold is not given up by trimming, so it never calls for a refill. Returns
//! the number of trimmed columns.
size_t trim_deep_fills(const std::vector<float>& original, openvdb::tools::Dense<float>& filled,
                       const openvdb::math::Transform& transform, const openvdb::FloatGrid& surface,
                       float background, double min_depth, const openvdb::FloatGrid* others, Progress& progress);

}  // namespace fabvdb::volume
