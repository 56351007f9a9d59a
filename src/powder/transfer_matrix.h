//! The transfer matrix T(g) of one gravity direction g: where powder resting
//! on each patch goes in one step. A patch whose normal is within the angle of
//! repose of "up" (−g) is a floor and keeps its powder; a steeper wall that
//! still faces up passes it to its downhill neighbours, in proportion to the
//! shared border times the slope; an overhang (facing down) drops it along g
//! onto the patches that a small cone of rays hits, as radiosity's form
//! factors. Every move goes to a patch whose centroid is strictly lower, so
//! T(g) is acyclic apart from its fixed points (floors, and walls with no
//! lower neighbour). Row-stochastic.
#pragma once

#include "core/mesh.h"
#include "powder/cavity_patches.h"
#include "powder/stochastic_matrix.h"
#include "volume/surface_ray_caster.h"

namespace fabvdb::powder {

struct TransferOptions {
    double repose_radians = 0.6108652381980153;  // 35°
    int cone_rays = 5;
    double cone_half_angle_radians = 0.13962634015954636;  // 8°
};

StochasticMatrix transfer_matrix(const CavityPatches& patches, const volume::SurfaceRayCaster& caster, const Vec3& gravity,
                                 const TransferOptions& options);

}  // namespace fabvdb::powder
