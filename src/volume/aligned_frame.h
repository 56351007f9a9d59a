//! The right-handed orthonormal frame (e1, e2, d) whose third axis is a given
//! direction d: molds are built in it (d becomes +Z, e2 is the "up" axis when
//! the mold stands for pouring). Deterministic: e1 is perpendicular to d and to
//! the world axis least aligned with d. Pure functions on plain vectors.
#pragma once

#include "core/mesh.h"

namespace fabvdb::volume {

struct AlignedFrame {
    Vec3 e1, e2, d;
    //! World point → frame coordinates (x along e1, y along e2, z along d).
    Vec3 to_frame(const Vec3& world) const;
    //! Frame coordinates → world point.
    Vec3 to_world(const Vec3& local) const;
};

//! Throws Error(INVALID_ARGUMENT) when `direction` is zero or not finite.
AlignedFrame aligned_frame(const Vec3& direction);

//! The mesh with every vertex mapped by `to_frame` (or `to_world` when
//! `inverse`); rotations keep orientation, so triangles are unchanged.
Mesh rotate_mesh(const Mesh& mesh, const AlignedFrame& frame, bool inverse);

}  // namespace fabvdb::volume
