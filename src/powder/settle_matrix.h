//! The settle matrix S(g) = lim T(g)^k: where powder starting on each patch
//! comes to rest for gravity g. Takes T(g) and the patches; computes the limit
//! exactly by one pass from the lowest patch up (T moves powder only to lower
//! patches), keeping per row the `max_entries` largest destinations above
//! `min_weight`, renormalised. Guarantees: row-stochastic; every destination
//! is a fixed point of T(g) (a floor or a wall with no lower neighbour).
#pragma once

#include "core/mesh.h"
#include "powder/cavity_patches.h"
#include "powder/stochastic_matrix.h"

namespace fabvdb::powder {

StochasticMatrix settle_matrix(const StochasticMatrix& transfer, const CavityPatches& patches, const Vec3& gravity,
                               size_t max_entries = 8, float min_weight = 1e-3f);

}  // namespace fabvdb::powder
