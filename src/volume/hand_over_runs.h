//! Hand-over of the runs a part cannot keep (thesis §3.6.2, the sweep's
//! keep-out): where other parts split a column of a swept part along its
//! parting direction, its mesh keeps one run (column_runs.h) and would drop
//! the others with the input surface they carry. The part's own material in
//! those runs (not the sweep's fill) is given to the other parts instead,
//! each voxel to the part nearest to it (usually the one that split the
//! column, which the run then continues), so the caller can sweep the parts
//! again from the new split. The parts stay disjoint: what one part gives up,
//! it loses. Cancellable.
#pragma once

#include <vector>

#include <openvdb/openvdb.h>

#include "core/progress.h"

namespace fabvdb::volume {

struct HandOver {
    std::vector<openvdb::FloatGrid::Ptr> parts;  //!< the new own material, on the parts' transform
    std::vector<double> given;     //!< mm³ each part gave up
    std::vector<double> received;  //!< mm³ each part received
};

//! `own`: each part's material before the sweep (level sets on one
//! transform). `swept`: each part as swept and kept out of the others
//! (sweep_double_height_field's results, in order). `kept_surface`: the input
//! surface's level set (column_runs.h; nullptr: the longest run is kept).
//! With a single part nothing is given. Throws Error(INVALID_ARGUMENT) when
//! the lists differ in length.
HandOver hand_over_unkept_runs(const std::vector<openvdb::FloatGrid::Ptr>& own,
                               const std::vector<openvdb::FloatGrid::Ptr>& swept,
                               const openvdb::FloatGrid* kept_surface, Progress& progress);

}  // namespace fabvdb::volume
