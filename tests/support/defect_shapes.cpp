//! Synthetic meshes with a known defect (see defect_shapes.h).
#include "support/defect_shapes.h"

#include <algorithm>
#include <random>

#include "support/shapes.h"

namespace fabvdb::test {

Mesh make_box_with_close_pair() {
    Mesh box = make_box({100, 100, 100}, {110, 110, 110});
    const uint32_t c00 = 4, c10 = 5, c01 = 6, c11 = 7;  // the top corners (x, y bits) of make_box
    box.triangles.erase(std::remove_if(box.triangles.begin(), box.triangles.end(),
                                       [&](const Triangle& t) {
                                           return box.vertices[t[0]][2] == 110 && box.vertices[t[1]][2] == 110 &&
                                                  box.vertices[t[2]][2] == 110;
                                       }),
                        box.triangles.end());
    const uint32_t p = uint32_t(box.vertices.size()), q = p + 1;
    box.vertices.push_back({105, 105.0000001, 110});
    box.vertices.push_back({105.0000001, 105, 110});
    // Counter-clockwise seen from above: c00, c10, c11, c01 around p and q.
    box.triangles.insert(box.triangles.end(), {{c00, c10, q}, {c10, c11, q}, {c11, p, q}, {c11, c01, p},
                                               {c01, c00, p}, {c00, q, p}});
    return box;
}

Mesh make_triangle_soup(uint32_t count, double side, double spread, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> place(0.0, side), corner(-spread, spread);
    Mesh soup;
    for (uint32_t t = 0; t < count; ++t) {
        const Vec3 centre{place(random), place(random), place(random)};
        for (int k = 0; k < 3; ++k)
            soup.vertices.push_back({centre[0] + corner(random), centre[1] + corner(random), centre[2] + corner(random)});
        soup.triangles.push_back({3 * t, 3 * t + 1, 3 * t + 2});
    }
    return soup;
}

Mesh make_box_with_cap(const Vec3& lo, const Vec3& hi) {
    Mesh mesh = make_box(lo, hi);
    // make_box's first triangle is (0, 2, 3): split its edge 0 -> 2 at m.
    const Triangle split = mesh.triangles[0];
    const uint32_t a = split[0], b = split[1], x = split[2];
    const uint32_t m = uint32_t(mesh.vertices.size());
    const Vec3& pa = mesh.vertices[a];
    const Vec3& pb = mesh.vertices[b];
    mesh.vertices.push_back({0.5 * (pa[0] + pb[0]), 0.5 * (pa[1] + pb[1]), 0.5 * (pa[2] + pb[2])});
    mesh.triangles[0] = {a, m, x};
    mesh.triangles.push_back({m, b, x});
    mesh.triangles.push_back({a, b, m});
    return mesh;
}

}  // namespace fabvdb::test
