//! Coordinates as float-storing files hold them (see float_coordinates.h).
#include "core/float_coordinates.h"

#include <algorithm>
#include <cmath>
#include <limits>

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

double float_step_over(const BoundingBox& local, const CentredFrame& frame) {
    double largest = 0.0;
    for (int k = 0; k < 3; ++k)
        largest = std::max({largest, std::abs(local.min[k] + frame.offset[k]), std::abs(local.max[k] + frame.offset[k])});
    const float at = static_cast<float>(largest);
    return double(std::nextafter(at, std::numeric_limits<float>::infinity())) - double(at);
}

}  // namespace fabvdb
