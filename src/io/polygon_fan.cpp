//! add_polygon_fan: triangles (c0, ci, ci+1).
#include "io/polygon_fan.h"

namespace fabvdb::io {

void add_polygon_fan(Mesh& mesh, const uint32_t* corners, size_t count) {
    for (size_t i = 1; i + 1 < count; ++i) mesh.triangles.push_back({corners[0], corners[i], corners[i + 1]});
}

}  // namespace fabvdb::io
