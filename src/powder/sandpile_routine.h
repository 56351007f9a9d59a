//! An operator's routine for the reference simulation: the first (printing)
//! orientation, then `turns` − 1 orientations drawn uniformly, with a seeded
//! generator, from the orientation set — the same routine for the same seed
//! on every machine (a fixed 64-bit Mersenne twister, no library
//! distribution).
#pragma once

#include <cstdint>
#include <vector>

#include "core/mesh.h"

namespace fabvdb::powder {

std::vector<Vec3> operator_routine(const Vec3& first, const std::vector<Vec3>& orientation_set, int turns,
                                   uint64_t seed);

}  // namespace fabvdb::powder
