//! Moving far-off models near the origin and back (see centred_frame.h).
#include "core/centred_frame.h"

#include <cmath>

namespace fabvdb {

CentredFrame centred_frame(const Mesh& mesh) {
    CentredFrame frame;
    if (mesh.triangles.empty()) return frame;
    const BoundingBox box = bounding_box(mesh);
    for (int k = 0; k < 3; ++k) {
        const double centre = 0.5 * (box.min[k] + box.max[k]);
        const double extent = box.max[k] - box.min[k];
        // Same sign and within a factor 2 of the centre: |centre| >= extent.
        if (std::isfinite(centre) && std::abs(centre) > extent) frame.offset[k] = centre;
    }
    return frame;
}

Mesh to_local(Mesh mesh, const CentredFrame& frame) {
    if (frame.identity()) return mesh;
    for (Vec3& p : mesh.vertices)
        for (int k = 0; k < 3; ++k) p[k] -= frame.offset[k];
    return mesh;
}

void to_world(Mesh& mesh, const CentredFrame& frame) {
    if (frame.identity()) return;
    for (Vec3& p : mesh.vertices)
        for (int k = 0; k < 3; ++k) p[k] += frame.offset[k];
}

}  // namespace fabvdb
