//! How much of a surface encloses volume, measured in a few milliseconds
//! before any voxel is built: the share of the surface's area just off
//! which, on one side or the other, the generalized winding number reaches
//! `inside` (0.9) and is near 1 there (at most 1.5), or is a whole number
//! on both sides (overlapping or repeated closed shells, w = 2, 3, ...). It
//! is 1 for closed surfaces, near 1 for a scan with holes, and near 0 for
//! what encloses nothing — an open sheet, a single range scan, a terrain, a
//! soup of unconnected triangles, where w is ±1/2 beside each triangle (at
//! most 0.85 inside a hemispherical bowl, the scan of a ball) — and for a
//! tangle of open, crossing, inconsistently wound pieces whose w is nowhere
//! near 1 (−9 to 8 beside the faces of corpus cube_40k). Probes the
//! centroid of up to `max_probes` triangles (evenly strided), each at a
//! thousandth of the triangle's size off its plane on both sides. Pure,
//! thread-safe.
#pragma once

#include <cstddef>

#include "core/mesh.h"
#include "volume/winding_number.h"

namespace fabvdb::volume {

//! `mesh` and `winding` (built on it) as signed_distance orients them.
double enclosed_share(const Mesh& mesh, const WindingNumber& winding, double inside = 0.9,
                      size_t max_probes = 20000);

}  // namespace fabvdb::volume
