//! The share of a surface that encloses volume (see enclosed_share.h).
#include "volume/enclosed_share.h"

#include <algorithm>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

namespace fabvdb::volume {

double enclosed_share(const Mesh& mesh, const WindingNumber& winding, double inside, size_t max_probes) {
    const size_t count = mesh.triangles.size();
    if (count == 0 || max_probes == 0) return 0.0;
    const size_t stride = std::max<size_t>(1, count / max_probes);
    const size_t probes = (count + stride - 1) / stride;
    using Sums = std::pair<double, double>;  // area enclosing, area probed
    const Sums sums = tbb::parallel_reduce(
        tbb::blocked_range<size_t>(0, probes), Sums{0.0, 0.0},
        [&](const tbb::blocked_range<size_t>& range, Sums sums) {
            for (size_t i = range.begin(); i != range.end(); ++i) {
                const Triangle& t = mesh.triangles[i * stride];
                const Vec3& a = mesh.vertices[t[0]];
                const Vec3& b = mesh.vertices[t[1]];
                const Vec3& c = mesh.vertices[t[2]];
                Vec3 normal, centroid;
                for (int k = 0; k < 3; ++k) centroid[k] = (a[k] + b[k] + c[k]) / 3.0;
                const Vec3 u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
                normal = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
                const double twice_area = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
                if (!(twice_area > 0.0)) continue;
                // A thousandth of the triangle's size off its plane: well inside
                // any wall the triangle bounds, far above the rounding of the
                // centroid (relative 1e-16 of the coordinates).
                const double offset = 1e-3 * std::sqrt(0.5 * twice_area) / twice_area;
                double best = 0.0;
                for (double side : {1.0, -1.0}) {
                    Vec3 q;
                    for (int k = 0; k < 3; ++k) q[k] = centroid[k] + side * offset * normal[k];
                    best = std::max(best, winding(q));
                }
                sums.second += twice_area;
                if (best >= inside) sums.first += twice_area;
            }
            return sums;
        },
        [](Sums a, Sums b) { return Sums{a.first + b.first, a.second + b.second}; });
    return sums.second > 0.0 ? sums.first / sums.second : 0.0;
}

}  // namespace fabvdb::volume
