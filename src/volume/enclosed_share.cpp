//! The share of a surface that encloses volume (see enclosed_share.h).
#include "volume/enclosed_share.h"

#include <algorithm>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

namespace fabvdb::volume {

namespace {

// Inside one shell, w stays under this where holes or stray pieces bend it.
constexpr double one_shell_ceiling = 1.5;
// Off closed shells, overlapping or repeated, w is a whole number; taken
// from a tree this accurate (Barill's β), it is within this of one.
constexpr double whole_accuracy = 4.0;
constexpr double whole_tolerance = 0.02;

bool whole(double w) { return std::fabs(w - std::round(w)) <= whole_tolerance; }

//! One probe pair: a thousandth of the triangle's size off its centroid, on
//! both sides of its plane; its twice area (0: a degenerate triangle).
struct Probe {
    Vec3 front, back;
    double twice_area = 0.0;
};

Probe probe_of(const Mesh& mesh, const Triangle& t) {
    const Vec3& a = mesh.vertices[t[0]];
    const Vec3& b = mesh.vertices[t[1]];
    const Vec3& c = mesh.vertices[t[2]];
    Probe probe;
    Vec3 centroid;
    for (int k = 0; k < 3; ++k) centroid[k] = (a[k] + b[k] + c[k]) / 3.0;
    const Vec3 u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const Vec3 normal{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const double twice_area = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
    if (!(twice_area > 0.0)) return probe;
    // A thousandth of the triangle's size off its plane: well inside any wall
    // the triangle bounds, far above the rounding of the centroid (relative
    // 1e-16 of the coordinates).
    const double offset = 1e-3 * std::sqrt(0.5 * twice_area) / twice_area;
    for (int k = 0; k < 3; ++k) {
        probe.front[k] = centroid[k] + offset * normal[k];
        probe.back[k] = centroid[k] - offset * normal[k];
    }
    probe.twice_area = twice_area;
    return probe;
}

}  // namespace

double enclosed_share(const Mesh& mesh, const WindingNumber& winding, double inside, size_t max_probes) {
    const size_t count = mesh.triangles.size();
    if (count == 0 || max_probes == 0) return 0.0;
    const size_t stride = std::max<size_t>(1, count / max_probes);
    const size_t probes = (count + stride - 1) / stride;
    // Per probe: 1 encloses, 0 does not, 2 reaches past one shell's ceiling
    // (decided below, whole numbers or not).
    std::vector<Probe> probe(probes);
    std::vector<char> verdict(probes, 0);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, probes), [&](const tbb::blocked_range<size_t>& range) {
        for (size_t i = range.begin(); i != range.end(); ++i) {
            probe[i] = probe_of(mesh, mesh.triangles[i * stride]);
            if (probe[i].twice_area == 0.0) continue;
            const double high = std::max(winding(probe[i].front), winding(probe[i].back));
            verdict[i] = high < inside ? 0 : high <= one_shell_ceiling ? 1 : 2;
        }
    });
    if (std::find(verdict.begin(), verdict.end(), char(2)) != verdict.end()) {
        const WindingNumber accurate(mesh, whole_accuracy);
        tbb::parallel_for(tbb::blocked_range<size_t>(0, probes), [&](const tbb::blocked_range<size_t>& range) {
            for (size_t i = range.begin(); i != range.end(); ++i) {
                if (verdict[i] != 2) continue;
                const double front = accurate(probe[i].front), back = accurate(probe[i].back);
                verdict[i] = whole(front) && whole(back) && std::round(std::min(front, back)) >= 0.0;
            }
        });
    }
    using Sums = std::pair<double, double>;  // area enclosing, area probed
    const Sums sums = tbb::parallel_reduce(
        tbb::blocked_range<size_t>(0, probes), Sums{0.0, 0.0},
        [&](const tbb::blocked_range<size_t>& range, Sums sums) {
            for (size_t i = range.begin(); i != range.end(); ++i) {
                sums.second += probe[i].twice_area;
                if (verdict[i] == 1) sums.first += probe[i].twice_area;
            }
            return sums;
        },
        [](Sums a, Sums b) { return Sums{a.first + b.first, a.second + b.second}; });
    return sums.second > 0.0 ? sums.first / sums.second : 0.0;
}

}  // namespace fabvdb::volume
