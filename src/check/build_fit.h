//! Whether a part fits a printer's build volume: as placed (its bounding box
//! in the print frame within the volume, side by side), or else turned by
//! quarter turns (some assignment of its three sides to the volume's axes
//! fits; which one is returned). Pure.
#pragma once

#include <array>

#include "core/mesh.h"

namespace fabvdb::check {

struct BuildFit {
    bool as_placed = false;               //!< every side fits its own axis
    bool turned = false;                  //!< some assignment of sides to axes fits
    std::array<int, 3> axes{0, 1, 2};     //!< when turned: the part's side that goes along x, y, z
};

//! `size`: the part's bounding-box sides in the print frame; `volume`: the
//! build volume's (both mm).
BuildFit fit_build_volume(const Vec3& size, const Vec3& volume);

}  // namespace fabvdb::check
