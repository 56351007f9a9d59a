//! Drilling: subtracts solid cylinders from a level set (CSG difference in
//! the level set, value by value: φ' = max(φ, −cylinder distance)), so the
//! holes are part of the volume before any mesh is extracted. Takes a level
//! set (negative inside, mm) and the cylinders (axis end points and radius);
//! returns a new level set, the input untouched, a narrow band of the same
//! width around the drilled surface. Cancellable (Error(CANCELLED)).
#pragma once

#include <vector>

#include <openvdb/openvdb.h>

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::volume {

struct DrillCylinder {
    Vec3 start{0, 0, 0};
    Vec3 end{0, 0, 1};
    double radius = 1.0;
};

openvdb::FloatGrid::Ptr drill_holes(const openvdb::FloatGrid& solid, const std::vector<DrillCylinder>& cylinders,
                                    Progress& progress);

}  // namespace fabvdb::volume
