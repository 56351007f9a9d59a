//! Consistent orientation of a triangle soup before its winding number is
//! taken: exactly coincident points are merged, degenerate and duplicate
//! triangles removed (what CGAL's `repair_polygon_soup` keeps of triangles,
//! found by sorting), each connected piece oriented consistently (CGAL
//! `orient_polygon_soup`, which splits non-manifold vertices and edges),
//! then every piece whose signed volume (about its own centroid) is
//! negative is flipped, so inverted shells count as solids —
//! except the walls of cavities: a piece the input oriented inward that lies
//! wholly inside the other pieces' solid stays inward, so hollow parts stay
//! hollow (an input stored inside out as a whole, most of its area inward,
//! is read turned round: its cavities' walls are the pieces it has outward).
//! Unreferenced vertices are dropped. Costs a sort of the points and one of
//! the triangles besides CGAL's orientation, and a winding-number tree of the
//! outward pieces when some piece came inward. Reports progress; throws
//! Error(CANCELLED).
#pragma once

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::volume {

Mesh orient_soup(const Mesh& mesh, Progress& progress);

}  // namespace fabvdb::volume
