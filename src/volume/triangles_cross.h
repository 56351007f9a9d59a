//! Whether two triangles of a mesh cross: meet other than along the edge or
//! at the corner they share, decided as CGAL's self-intersection test does
//! (exact predicates, Epick): no shared vertex, the triangles intersect; one
//! shared vertex, the edge opposite it in one meets the other; a shared edge,
//! the two lie in one plane on the same side of it; all three shared, a
//! duplicate. Floating-point filters with a certain sign (certain_sign.h)
//! settle most pairs before the exact predicates. Pure; thread-safe.
#pragma once

#include <vector>

#include "core/mesh.h"

namespace fabvdb::volume {

//! Whether triangles `a` and `b` of `mesh` cross. `embedded`: per vertex,
//! whether its fan is embedded (embedded_fans.h); a pair that shares such a
//! vertex, or an edge at one, does not cross unless it is a duplicate (all
//! three vertices shared).
bool triangles_cross(const Mesh& mesh, const std::vector<char>& embedded, const Triangle& a, const Triangle& b);

}  // namespace fabvdb::volume
