// make_tube: rings of n vertices joined by quads split in two; caps fan
// to a centre vertex (pin) or join the inner and outer rings (tube).
#include "support/tube.h"

#include <cmath>

namespace fabvdb::test {

Mesh make_tube(double r0, double r1, double height, int n) {
    Mesh mesh;
    const auto ring = [&](double r, double z) {
        const uint32_t first = uint32_t(mesh.vertices.size());
        for (int i = 0; i < n; ++i) {
            const double a = 2.0 * M_PI * i / n;
            mesh.vertices.push_back({r * std::cos(a), r * std::sin(a), z});
        }
        return first;
    };
    const auto band = [&](uint32_t lo, uint32_t hi, bool outward) {
        for (int i = 0; i < n; ++i) {
            const uint32_t a = lo + i, b = lo + (i + 1) % n, c = hi + (i + 1) % n, d = hi + i;
            if (outward) {
                mesh.triangles.push_back({a, b, c});
                mesh.triangles.push_back({a, c, d});
            } else {
                mesh.triangles.push_back({a, c, b});
                mesh.triangles.push_back({a, d, c});
            }
        }
    };
    const uint32_t outer_bottom = ring(r1, 0.0), outer_top = ring(r1, height);
    band(outer_bottom, outer_top, true);
    if (r0 > 0.0) {
        const uint32_t inner_bottom = ring(r0, 0.0), inner_top = ring(r0, height);
        band(inner_bottom, inner_top, false);
        band(inner_top, outer_top, false);        // the top annulus, facing +z
        band(inner_bottom, outer_bottom, true);   // the bottom annulus, facing -z
    } else {
        const uint32_t top = uint32_t(mesh.vertices.size());
        mesh.vertices.push_back({0, 0, height});
        const uint32_t bottom = uint32_t(mesh.vertices.size());
        mesh.vertices.push_back({0, 0, 0});
        for (int i = 0; i < n; ++i) {
            mesh.triangles.push_back({outer_top + i, outer_top + (i + 1) % n, top});
            mesh.triangles.push_back({outer_bottom + (i + 1) % n, outer_bottom + i, bottom});
        }
    }
    return mesh;
}

}  // namespace fabvdb::test
