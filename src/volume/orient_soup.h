//! Consistent orientation of a triangle soup before its winding number is
//! taken: exactly coincident points are merged, degenerate and duplicate
//! triangles removed, each connected piece oriented consistently (CGAL
//! `repair_polygon_soup` + `orient_polygon_soup`, which splits non-manifold
//! vertices and edges), then every piece whose signed volume (about its own
//! centroid) is negative is flipped, so inverted shells count as solids —
//! except the walls of cavities: a piece the input oriented inward that lies
//! wholly inside the other pieces' solid stays inward, so hollow parts stay
//! hollow.
//! Unreferenced vertices are dropped. Reports progress; throws Error(CANCELLED).
#pragma once

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::volume {

Mesh orient_soup(const Mesh& mesh, Progress& progress);

}  // namespace fabvdb::volume
