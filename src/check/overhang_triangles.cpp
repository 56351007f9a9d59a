//! overhang_triangles: one normal and one height test per triangle.
#include "check/overhang_triangles.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fabvdb::check {

std::vector<uint8_t> overhang_triangles(const Mesh& surface, const Vec3& up, double overhang_degrees,
                                        double plate_tolerance) {
    std::vector<uint8_t> chosen(surface.triangles.size(), 0);
    const double length = std::sqrt(up[0] * up[0] + up[1] * up[1] + up[2] * up[2]);
    if (!(length > 0.0) || overhang_degrees >= 90.0) return chosen;
    const Vec3 u{up[0] / length, up[1] / length, up[2] / length};
    const auto height = [&](const Vec3& p) { return p[0] * u[0] + p[1] * u[1] + p[2] * u[2]; };
    double lowest = std::numeric_limits<double>::infinity();
    for (const Triangle& t : surface.triangles)
        for (uint32_t v : t) lowest = std::min(lowest, height(surface.vertices[v]));
    const double limit = std::sin(overhang_degrees * M_PI / 180.0);
    for (size_t i = 0; i < surface.triangles.size(); ++i) {
        const Triangle& t = surface.triangles[i];
        const Vec3 n = triangle_normal(surface, t);
        const double n_length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (!(n_length > 0.0)) continue;
        const double down = -height(n) / n_length;
        bool on_plate = true;
        for (uint32_t v : t) on_plate = on_plate && height(surface.vertices[v]) <= lowest + plate_tolerance;
        chosen[i] = down > limit && !on_plate ? 1 : 0;
    }
    return chosen;
}

}  // namespace fabvdb::check
