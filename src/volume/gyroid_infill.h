//! Gyroid strut infill of a cavity: struts of diameter `strut` along the
//! skeleton of one labyrinth of the gyroid sin x cos y + sin y cos z +
//! sin z cos x (period `cell`): the srs net, whose nodes are the maxima of
//! that function, 8 nodes and 12 straight struts per cubic cell, 3 struts per
//! node at 120°. Takes the cavity as a level set (negative in the void) and
//! returns it with the struts carved out (max(cavity, −struts)), so that
//! extracting it gives the void around the struts; the struts run into the
//! wall, so every strut inside the cavity is joined to it. The void stays one
//! open-cell region: strut ≤ cell/4 keeps the channels around the other
//! labyrinth's skeleton wider than a strut. Cancellable.
#pragma once

#include <cstdint>

#include <openvdb/openvdb.h>

#include "core/progress.h"

namespace fabvdb::volume {

struct GyroidStruts {
    double cell = 0.0;   //!< mm, side of the cubic cell, > 0
    double strut = 0.0;  //!< mm, strut diameter, in (0, cell/4]
};

//! Throws Error(INVALID_ARGUMENT) unless the lattice is valid (see above).
void validate_gyroid_struts(const GyroidStruts& lattice);

//! Bytes the carved band around the struts needs in a cavity of `cavity_volume` mm³.
uint64_t estimate_gyroid_struts_bytes(const GyroidStruts& lattice, double cavity_volume, double voxel_size);

//! `cavity`: a level set negative in the void (its narrow band and tiles);
//! the result has the same transform and background.
openvdb::FloatGrid::Ptr carve_gyroid_struts(const openvdb::FloatGrid& cavity, const GyroidStruts& lattice,
                                            Progress& progress);

}  // namespace fabvdb::volume
