//! winding_number (see winding_number.h): a sum of atan2 over the triangles.
#include "support/winding_number.h"

#include <cmath>

#include "support/check_vec3.h"

namespace fabvdb::test {

double winding_number(const Mesh& mesh, const Vec3& p) {
    double total = 0;
    for (const Triangle& t : mesh.triangles) {
        const Vec3 a = sub(mesh.vertices[t[0]], p), b = sub(mesh.vertices[t[1]], p), c = sub(mesh.vertices[t[2]], p);
        const double la = norm(a), lb = norm(b), lc = norm(c);
        total += 2.0 * std::atan2(dot(a, cross(b, c)), la * lb * lc + dot(a, b) * lc + dot(b, c) * la + dot(c, a) * lb);
    }
    return total / (4.0 * M_PI);
}

}  // namespace fabvdb::test
