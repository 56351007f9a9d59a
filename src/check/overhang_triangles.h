//! The triangles of a surface that need support when printed with `up` as the
//! build direction: those facing down more steeply than the process allows —
//! tilted from vertical by more than `overhang_degrees`, i.e. whose unit
//! normal n has n·(−up) > sin(overhang_degrees) — and not lying on the build
//! plate (all three corners within `plate_tolerance` of the lowest point
//! along up). 90 degrees: nothing needs support. Pure.
#pragma once

#include <cstdint>
#include <vector>

#include "core/mesh.h"

namespace fabvdb::check {

//! One flag per triangle; `up` need not be unit.
std::vector<uint8_t> overhang_triangles(const Mesh& surface, const Vec3& up, double overhang_degrees,
                                        double plate_tolerance);

}  // namespace fabvdb::check
