//! A mesh with every triangle turned round: the same surface, facing the
//! other way. Pure; costs a copy of the mesh.
#pragma once

#include <utility>

#include "core/mesh.h"

namespace fabvdb {

inline Mesh turned_inside_out(Mesh mesh) {
    for (Triangle& t : mesh.triangles) std::swap(t[1], t[2]);
    return mesh;
}

}  // namespace fabvdb
