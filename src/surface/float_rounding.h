//! Rounding a closed triangle mesh to single-precision coordinates (what an
//! STL file stores) without making it self-intersect. Points a hair apart,
//! which exact booleans leave where two solids graze, can round so that
//! sheets closer than a float step fold through each other. Every vertex
//! first goes to its nearest float position; then, in rounds, while
//! triangles cross (volume/crossing_pairs.h, exact predicates) or are
//! degenerate (exact collinearity):
//!  - each corner of a crossing pair, not shared with the other triangle,
//!    takes the float position nearest its exact one, within `search_ulps`
//!    float steps per axis, that lies on the side of the other triangle's
//!    plane its exact position lies on (rounding directed away from the
//!    sheet it grazes);
//!  - each corner of a degenerate triangle takes the nearest such position
//!    at which none of its triangles is degenerate or crosses one near it;
//!  - a triangle still offending after a round loses its shortest edge if
//!    that is under 256 float steps, collapsed into the endpoint whose
//!    triangles stay valid, only when the endpoints' common neighbours are
//!    the edge's two opposite corners (the mesh stays a closed 2-manifold).
//! Unless the first check found nothing to mend, the result is checked
//! whole: closed, 2-manifold, no triangle degenerate, no two crossing. Every
//! coordinate of the result is a float; unused vertices are dropped, the
//! others keep their order. Throws Error(INTERNAL) naming `name` when the
//! rounds do not converge.
#pragma once

#include <string>

#include "core/mesh.h"

namespace fabvdb::surface {

struct FloatRoundingOptions {
    //! Float steps per axis a vertex may move past its nearest float
    //! position to clear a crossing (0 to 16; 0: none, only edge
    //! collapses). Grazing sheets on a sphere's mold needed 8.
    int search_ulps = 8;
    //! Rounds of searching and collapsing before giving up (>= 1).
    int max_rounds = 16;
};

//! `mesh`: closed, 2-manifold, consistently oriented. Throws
//! Error(INVALID_ARGUMENT) for options out of range.
Mesh round_to_float(const Mesh& mesh, const std::string& name, const FloatRoundingOptions& options = {});

}  // namespace fabvdb::surface
