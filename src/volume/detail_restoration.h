//! Detail restoration (thesis §3.6.1): each part of a decomposition, given as
//! the closed low-resolution solid the decomposition found, gets its outer
//! surface back from the full-resolution input. With φ the input's level set,
//! ψᵢ the part's, ω the shell thickness and δ the reach,
//!   restoredᵢ = max(φ, ψᵢ − δ, (ψᵢ − min_{j≠i} ψⱼ)/2, −φ − ω):
//! the input solid within δ of the part (the part thickened outward), split
//! from its neighbours where they are equally near, and no deeper than ω
//! below the input surface, so the inner surface stays at the shell's inner
//! offset (thin features thinner than 2ω stay solid). The parts stay disjoint.
//! Returns level sets on the input's transform. Cancellable.
#pragma once

#include <string>
#include <vector>

#include <openvdb/openvdb.h>

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::volume {

struct DetailRestorationOptions {
    double shell_thickness = 0.0;  //!< ω, mm (> 0)
    double reach = 0.0;            //!< δ, mm (> 0): how far the input may lie outside the low-res part
    std::string input_name = "mesh";  //!< what the input is called in error messages
};

//! `input`: level set of the full-resolution input. `parts`: closed solids.
//! Throws Error(INVALID_ARGUMENT) for options out of range, BAD_INPUT for a
//! part that encloses no volume or that keeps under half of its volume when
//! restored at the input's voxel (a part about a voxel thin).
std::vector<openvdb::FloatGrid::Ptr> restore_part_details(const openvdb::FloatGrid& input,
                                                          const std::vector<Mesh>& parts,
                                                          const DetailRestorationOptions& options,
                                                          Progress& progress);

}  // namespace fabvdb::volume
