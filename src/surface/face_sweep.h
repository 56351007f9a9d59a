//! The volume a part's faces sweep along ±Z to a plane (the swept volumes SV
//! of thesis §3.6.3, in the frame where the parting direction is +Z): for
//! `upward`, the solid between the part's downward-facing triangles (its lower
//! mold face M⁻) and the plane z = `plane_z` above it: the part and everything
//! above it; otherwise the solid between the upward-facing triangles (M⁺)
//! and the plane below: the part and everything below it. Built from the
//! part's own triangles (no resampling), so the mold cavity matches the part
//! exactly. Requires the part to be a double height field along Z with a
//! 2-manifold face set; the caller's boolean validation rejects anything else.
#pragma once

#include "core/mesh.h"

namespace fabvdb::surface {

//! Throws Error(BAD_INPUT) when the part has no face of the needed side, or a
//! face parallel to Z (its side is undefined), or when the plane does not
//! clear the part.
Mesh sweep_faces_to_plane(const Mesh& part, bool upward, double plane_z);

}  // namespace fabvdb::surface
