//! Powder flow for every orientation of a set, built in parallel: per gravity
//! direction g, the settle matrix S(g) (from the transfer T(g)) and the floor
//! regions — the edge-connected groups of patches where powder comes to rest
//! (a basin's floor), labelled per orientation, −1 on patches powder leaves.
//! Reports progress ("powder flow") and throws Error(CANCELLED).
#pragma once

#include <cstdint>
#include <vector>

#include "core/mesh.h"
#include "core/progress.h"
#include "powder/cavity_patches.h"
#include "powder/stochastic_matrix.h"
#include "volume/surface_ray_caster.h"
#include "powder/transfer_matrix.h"

namespace fabvdb::powder {

struct OrientationFlow {
    Vec3 gravity{0, 0, -1};
    StochasticMatrix settle;
    std::vector<int32_t> region;
    //! Where the largest share of each patch's powder comes to rest.
    std::vector<uint32_t> main_destination;
};

std::vector<OrientationFlow> build_orientation_flows(const CavityPatches& patches, const volume::SurfaceRayCaster& caster,
                                                     const std::vector<Vec3>& gravities,
                                                     const TransferOptions& options, Progress& progress);

}  // namespace fabvdb::powder
