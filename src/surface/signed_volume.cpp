//! Signed volumes per component; the reference point is the centre of the
//! bounding box, which keeps the products small for meshes far from the origin.
#include "surface/signed_volume.h"

namespace fabvdb::surface {

std::vector<double> component_signed_volumes(const Mesh& mesh, const std::vector<uint32_t>& triangle_component,
                                             size_t component_count) {
    const BoundingBox box = bounding_box(mesh);
    const Vec3 origin{(box.min[0] + box.max[0]) / 2, (box.min[1] + box.max[1]) / 2, (box.min[2] + box.max[2]) / 2};
    std::vector<double> six_volumes(component_count, 0.0);
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        Vec3 p[3];
        for (int k = 0; k < 3; ++k)
            for (int d = 0; d < 3; ++d) p[k][d] = mesh.vertices[mesh.triangles[t][k]][d] - origin[d];
        six_volumes[triangle_component[t]] += six_signed_tetrahedron_volume(p[0], p[1], p[2]);
    }
    for (double& v : six_volumes) v /= 6.0;
    return six_volumes;
}

}  // namespace fabvdb::surface
