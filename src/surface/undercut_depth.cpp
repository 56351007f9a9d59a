//! Undercut depth by casting lines along the direction (see undercut_depth.h).
#include "surface/undercut_depth.h"

#include <algorithm>
#include <cmath>

#include "core/vec3_ops.h"
#include "volume/aligned_frame.h"

namespace fabvdb::surface {

namespace {

struct Crossing {
    double height;  //!< along the direction
    bool own;       //!< a triangle of the part
    bool leaving;   //!< the triangle faces along the direction
};

constexpr int max_lines_per_side = 512;

}  // namespace

UndercutDepth undercut_depth(const Shell& shell, const std::vector<int>& part_of_triangle, int part,
                             const Vec3& direction, double spacing, double reach) {
    UndercutDepth result;
    const volume::AlignedFrame frame = volume::aligned_frame(direction);
    const Vec3 &d = frame.d, &e1 = frame.e1, &e2 = frame.e2;
    // On the input where the shell has it, each input triangle labelled as
    // its nearest S_low triangle and facing as the input does as a whole.
    const bool on_input = !shell.input.triangles.empty();
    const Mesh& mesh = on_input ? shell.input : shell.outer;
    const size_t n = mesh.triangles.size();
    const auto part_of = [&](size_t t) { return part_of_triangle[on_input ? shell.input_nearest[t] : t]; };
    const double orientation = on_input && signed_volume(mesh) < 0 ? -1.0 : 1.0;
    const auto facing_of = [&](size_t t) {
        if (!on_input) return dot(shell.normal[t], d);
        const Triangle& f = mesh.triangles[t];
        const Vec3 normal = cross(mesh.vertices[f[1]] - mesh.vertices[f[0]], mesh.vertices[f[2]] - mesh.vertices[f[0]]);
        return orientation * dot(normal, d);
    };

    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    for (size_t t = 0; t < n; ++t) {
        if (part_of(t) != part) continue;
        for (uint32_t v : mesh.triangles[t]) {
            const double uv[2] = {dot(mesh.vertices[v], e1), dot(mesh.vertices[v], e2)};
            for (int k = 0; k < 2; ++k) {
                lo[k] = std::min(lo[k], uv[k]);
                hi[k] = std::max(hi[k], uv[k]);
            }
        }
    }
    if (!(lo[0] <= hi[0]) || !(spacing > 0)) return result;
    const double step = std::max({spacing, (hi[0] - lo[0]) / max_lines_per_side, (hi[1] - lo[1]) / max_lines_per_side});
    const int cols = int(std::floor((hi[0] - lo[0]) / step)) + 1;
    const int rows = int(std::floor((hi[1] - lo[1]) / step)) + 1;
    // Lines at cell centres, offset from the part's extreme vertices.
    const double u0 = lo[0] + 0.5 * ((hi[0] - lo[0]) - (cols - 1) * step);
    const double v0 = lo[1] + 0.5 * ((hi[1] - lo[1]) - (rows - 1) * step);
    std::vector<std::vector<Crossing>> lines(size_t(cols) * size_t(rows));

    for (size_t t = 0; t < n; ++t) {
        const double facing = facing_of(t);
        if (facing == 0) continue;
        double u[3], v[3], h[3];
        for (int k = 0; k < 3; ++k) {
            const Vec3& p = mesh.vertices[mesh.triangles[t][k]];
            u[k] = dot(p, e1);
            v[k] = dot(p, e2);
            h[k] = dot(p, d);
        }
        const double area2 = (u[1] - u[0]) * (v[2] - v[0]) - (u[2] - u[0]) * (v[1] - v[0]);
        if (area2 == 0) continue;
        const int c0 = std::max(0, int(std::ceil((std::min({u[0], u[1], u[2]}) - u0) / step)));
        const int c1 = std::min(cols - 1, int(std::floor((std::max({u[0], u[1], u[2]}) - u0) / step)));
        const int r0 = std::max(0, int(std::ceil((std::min({v[0], v[1], v[2]}) - v0) / step)));
        const int r1 = std::min(rows - 1, int(std::floor((std::max({v[0], v[1], v[2]}) - v0) / step)));
        for (int r = r0; r <= r1; ++r) {
            const double y = v0 + r * step;
            for (int c = c0; c <= c1; ++c) {
                const double x = u0 + c * step;
                // Barycentric coordinates in the projection (a line through a
                // shared edge meets both triangles: the same crossing twice,
                // which makes no gap).
                const double b1 = ((x - u[0]) * (v[2] - v[0]) - (u[2] - u[0]) * (y - v[0])) / area2;
                const double b2 = ((u[1] - u[0]) * (y - v[0]) - (x - u[0]) * (v[1] - v[0])) / area2;
                const double b0 = 1 - b1 - b2;
                if (b0 < 0 || b1 < 0 || b2 < 0) continue;
                lines[size_t(r) * size_t(cols) + size_t(c)].push_back(
                    {b0 * h[0] + b1 * h[1] + b2 * h[2], part_of(t) == part, facing > 0});
            }
        }
    }

    // What the sweep makes of each line: filled from the lowest to the highest
    // point of the part on it (lo > hi: the line misses the part). The part
    // holds ω under its surface (its prisms), so where the line's lowest own
    // crossing leaves the part (another part's surface, or none, below it)
    // the part's material starts ω lower, and alike above a highest own
    // crossing that enters it.
    std::vector<double> lo_of(lines.size(), 1e300), hi_of(lines.size(), -1e300);
    for (size_t i = 0; i < lines.size(); ++i) {
        std::vector<Crossing>& line = lines[i];
        std::sort(line.begin(), line.end(), [](const Crossing& a, const Crossing& b) { return a.height < b.height; });
        const Crossing* lowest = nullptr;
        const Crossing* highest = nullptr;
        for (const Crossing& c : line) {
            if (!c.own) continue;
            if (!lowest) lowest = &c;
            highest = &c;
        }
        if (!lowest) continue;
        lo_of[i] = lowest->height - (lowest->leaving ? shell.thickness : 0.0);
        hi_of[i] = highest->height + (highest->leaving ? 0.0 : shell.thickness);
    }
    // How deep the filled lines bury the point at height h on line (c, r):
    // to the line's ends, or across to the nearest line that is not filled
    // at h (a line ending within a rounding tolerance of h has its surface
    // there), up to `reach`.
    const double tolerance = 1e-3 * step;
    const auto buried = [&](int c, int r, double h) {
        const size_t i = size_t(r) * size_t(cols) + size_t(c);
        double depth = std::min({h - lo_of[i], hi_of[i] - h, reach});
        const int radius = int(std::ceil(depth / step));
        for (int dr = -radius; dr <= radius; ++dr)
            for (int dc = -radius; dc <= radius; ++dc) {
                const double across = step * std::sqrt(double(dr * dr + dc * dc));
                if (across >= depth) continue;
                const int c2 = c + dc, r2 = r + dr;
                const bool outside = c2 < 0 || r2 < 0 || c2 >= cols || r2 >= rows;
                const size_t j = size_t(r2) * size_t(cols) + size_t(c2);
                if (outside || !(lo_of[j] + tolerance < h && h < hi_of[j] - tolerance)) depth = across;
            }
        return depth;
    };
    for (size_t i = 0; i < lines.size(); ++i) {
        const std::vector<Crossing>& line = lines[i];
        const int c = int(i % size_t(cols)), r = int(i / size_t(cols));
        for (size_t k = 0; k + 1 < line.size(); ++k) {
            const Crossing& out = line[k];
            const Crossing& in = line[k + 1];
            if (!out.own || !in.own || !out.leaving || in.leaving || !(in.height > out.height)) continue;
            for (const double h : {out.height, in.height}) {
                const double depth = buried(c, r, h);
                if (depth > result.depth) {
                    result.depth = depth;
                    result.at = (u0 + c * step) * e1 + (v0 + r * step) * e2 + h * d;
                }
            }
        }
    }
    return result;
}

}  // namespace fabvdb::surface
