//! Coordinates as float-storing files hold them (see float_coordinates.h).
#include "core/float_coordinates.h"

namespace fabvdb {

double nearest_float(double x) {
    volatile float rounded = static_cast<float>(x);
    return rounded;
}

Vec3 nearest_float(const Vec3& p) { return {nearest_float(p[0]), nearest_float(p[1]), nearest_float(p[2])}; }

bool on_float_grid(const Mesh& mesh) {
    for (const Vec3& p : mesh.vertices)
        for (double c : p)
            if (nearest_float(c) != c) return false;
    return true;
}

Vec3 stored_position(const Vec3& local, const CentredFrame& frame) {
    Vec3 stored;
    for (int k = 0; k < 3; ++k) stored[k] = nearest_float(local[k] + frame.offset[k]) - frame.offset[k];
    return stored;
}

}  // namespace fabvdb
