//! The repair pipeline (repair.h) held to the fidelity gate
//! (input_fidelity.h): the repaired surface is measured against the input,
//! and where it is not the input's model at the voxel asked for (features
//! thinner than two voxels closed or lost, a fin of a scan, a bird's legs),
//! the input is repaired again at half the voxel, up to `refinements` times
//! and while the memory budget holds (a refinement the budget refuses, or
//! one whose surface has no consistent inside, ends the attempts) — not when the far surface with no clear solid on either
//! side (sheets, which no voxel size makes solid) alone fails the gate. Returns the last attempt and its figures; the caller
//! decides what a failure means (require_faithful).
//! Costs one repair and one fidelity measure per attempt: each halving
//! takes about four times the voxels of the one before.
#pragma once

#include <string>
#include <vector>

#include "core/centred_frame.h"
#include "core/mesh.h"
#include "core/progress.h"
#include "volume/input_fidelity.h"
#include "volume/repair.h"

namespace fabvdb::volume {

struct FaithfulRepair {
    RepairResult repaired;
    FidelityLimits limits;          //!< of the last voxel tried
    Fidelity fidelity;              //!< of the last attempt
    std::vector<double> voxels;     //!< mm, every voxel tried, in order
    std::vector<std::string> warnings;  //!< one per refinement: why, and at which voxel
    double fidelity_seconds = 0.0;  //!< spent measuring, over every attempt
};

//! Repairs `source` (the input, or the input as orient_soup oriented it) and
//! measures the result against `input` (far: two voxels, and half the
//! thickness of a sheet thickened on purpose, whose volume is not
//! compared). `frame`: when given,
//! `source` and `input` are in it and the repair is repair_in_frame's;
//! else repair's, in world coordinates.
FaithfulRepair faithful_repair(const Mesh& input, const Mesh& source, RepairOptions options, int refinements,
                               const CentredFrame* frame, Progress& progress);

}  // namespace fabvdb::volume
