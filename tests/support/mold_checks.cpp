//! Independent checks of a two-piece mold (see mold_checks.h).
#include "support/mold_checks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <queue>

#include "support/check_vec3.h"
#include "support/ray_cast.h"
#include "support/shapes.h"

namespace fabvdb::test {

namespace {

struct Frame {
    Vec3 u, v, w;
};
Frame frame_of(const Vec3& d) {
    Frame f;
    f.w = unit(d);
    const Vec3 helper = std::abs(f.w[2]) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0};
    f.u = unit(cross(helper, f.w));
    f.v = cross(f.w, f.u);
    return f;
}

struct Extent {
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
};
Extent extent_in(const Frame& f, const std::vector<const Mesh*>& meshes) {
    Extent e;
    for (const Mesh* mesh : meshes)
        for (const Vec3& p : mesh->vertices) {
            const double c[3] = {dot(p, f.u), dot(p, f.v), dot(p, f.w)};
            for (int k = 0; k < 3; ++k) e.lo[k] = std::min(e.lo[k], c[k]), e.hi[k] = std::max(e.hi[k], c[k]);
        }
    return e;
}

Vec3 world(const Frame& f, double a, double b, double c) {
    return {a * f.u[0] + b * f.v[0] + c * f.w[0], a * f.u[1] + b * f.v[1] + c * f.w[1],
            a * f.u[2] + b * f.v[2] + c * f.w[2]};
}

// Length of the set inside `inside` and outside `outside` and within [lo, hi]
// along the line, from sorted crossing parameters.
double covered_length(const std::vector<double>& inside, const std::vector<double>& outside, double lo, double hi) {
    std::vector<double> cuts{lo, hi};
    for (double t : inside) cuts.push_back(std::clamp(t, lo, hi));
    for (double t : outside) cuts.push_back(std::clamp(t, lo, hi));
    std::sort(cuts.begin(), cuts.end());
    double length = 0;
    for (size_t i = 0; i + 1 < cuts.size(); ++i) {
        const double mid = 0.5 * (cuts[i] + cuts[i + 1]);
        const auto parity = [mid](const std::vector<double>& ts) {
            return std::count_if(ts.begin(), ts.end(), [mid](double t) { return t < mid; }) % 2 == 1;
        };
        if (parity(inside) && !parity(outside)) length += cuts[i + 1] - cuts[i];
    }
    return length;
}

// The frame of the block: d, and the in-plane axis its side faces face,
// found as the dominant direction (mod 90°) of the bottom piece's faces
// parallel to d, weighted by area.
Frame block_frame(const Mesh& piece, const Vec3& d) {
    Frame f = frame_of(d);
    std::vector<double> weight(360, 0.0), largest(360, 0.0), angle_of_largest(360, 0.0);
    for (const auto& t : piece.triangles) {
        const Vec3 &a = piece.vertices[t[0]], &b = piece.vertices[t[1]], &c = piece.vertices[t[2]];
        const Vec3 n = cross(sub(b, a), sub(c, a));
        const double area2 = norm(n);
        if (area2 == 0 || std::abs(dot(n, f.w)) > 1e-6 * area2) continue;
        // Mod 90°, in [-45°, 45°): a face a hair off an axis either way (the
        // float coordinates of a tilted block) lands in one bin.
        double angle = std::atan2(dot(n, f.v), dot(n, f.u));
        angle = std::fmod(angle + 4.25 * M_PI, 0.5 * M_PI) - 0.25 * M_PI;
        const int bin = std::clamp(int((angle + 0.25 * M_PI) / (0.5 * M_PI) * 360), 0, 359);
        weight[bin] += area2;
        if (area2 > largest[bin]) largest[bin] = area2, angle_of_largest[bin] = angle;
    }
    const int best = int(std::max_element(weight.begin(), weight.end()) - weight.begin());
    const double angle = angle_of_largest[size_t(best)], c = std::cos(angle), s = std::sin(angle);
    Frame g = f;
    for (int k = 0; k < 3; ++k) g.u[k] = c * f.u[k] + s * f.v[k], g.v[k] = -s * f.u[k] + c * f.v[k];
    return g;
}

}  // namespace

void check_two_piece_mold(const Mesh& part, const Vec3& d, const TwoPieceMold& mold) {
    const Frame f = block_frame(mold.bottom, d);
    // Each output is a closed, 2-manifold, self-intersection-free solid, as
    // the generator gives it and as an STL file (float) stores it.
    for (const Mesh* piece : {&mold.top, &mold.bottom}) {
        ASSERT_GT(piece->triangles.size(), 100u);
        EXPECT_TRUE(closed_two_manifold(*piece));
        EXPECT_FALSE(self_intersects(*piece));
        EXPECT_GT(mesh_volume(*piece), 0.0);
        const Mesh stored = stored_as_float(*piece);
        EXPECT_FALSE(self_intersects(stored)) << "as an STL file (float) stores it";
        EXPECT_EQ(degenerate_triangle_count(stored), 0u) << "as an STL file (float) stores it";
    }
    // The part is moldable along d.
    const auto part_lines = check_double_height_field(part, d, 60);
    EXPECT_EQ(part_lines.lines_over_two, 0u);

    // Each piece is a height field along d, ending at the block's face: the
    // top piece leaves along +d, the bottom along −d.
    const Extent block = extent_in(f, {&mold.top, &mold.bottom});
    // The pieces have float coordinates (what an STL file stores): a tilted
    // face is flat, and the two pieces meet, within a few float steps of the
    // largest coordinate (their rounding may move a vertex up to 8 steps off
    // its nearest float to keep a piece free of crossings, each piece on its
    // own: 20 steps is 4e-5 mm on a 50 mm block).
    float largest_coordinate = 0;
    for (const Mesh* piece : {&mold.top, &mold.bottom})
        for (const Vec3& p : piece->vertices)
            for (double c : p) largest_coordinate = std::max(largest_coordinate, float(std::abs(c)));
    const double tolerance =
        20.0 * (double(std::nextafter(largest_coordinate, HUGE_VALF)) - double(largest_coordinate));
    LineCaster top_lines(mold.top, f.w), bottom_lines(mold.bottom, f.w);
    int lines = 0;
    for (int i = 0; i < 50; ++i)
        for (int j = 0; j < 50; ++j) {
            const double a = block.lo[0] + (block.hi[0] - block.lo[0]) * (i + 0.37) / 50;
            const double b = block.lo[1] + (block.hi[1] - block.lo[1]) * (j + 0.61) / 50;
            const Vec3 origin = world(f, a, b, 0.0);
            const auto top = top_lines.crossings(origin), bottom = bottom_lines.crossings(origin);
            if (top.empty() || bottom.empty()) continue;
            ++lines;
            ASSERT_EQ(top.size(), 2u) << "top piece line " << i << "," << j;
            ASSERT_EQ(bottom.size(), 2u) << "bottom piece line " << i << "," << j;
            EXPECT_NEAR(top[1], block.hi[2], tolerance);
            EXPECT_NEAR(bottom[0], block.lo[2], tolerance);
            EXPECT_LE(bottom[1], top[0] + tolerance) << "pieces overlap along line " << i << "," << j;
        }
    EXPECT_GT(lines, 2000);

    // No interpenetration: the sampled common volume is ~0.
    const double block_volume =
        (block.hi[0] - block.lo[0]) * (block.hi[1] - block.lo[1]) * (block.hi[2] - block.lo[2]);
    Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
    for (const Mesh* piece : {&mold.top, &mold.bottom})
        for (const Vec3& p : piece->vertices)
            for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
    EXPECT_LT(sampled_common_volume({&mold.top, &mold.bottom}, lo, hi, 48), 1e-3 * block_volume);

    // The void minus the channels matches the part within 2%.
    const double part_volume = mesh_volume(part);
    LineCaster channel_lines(mold.channels, f.w), part_lines_caster(part, f.w);
    double channel_volume = 0;
    const int n = 300;
    const double cell = (block.hi[0] - block.lo[0]) * (block.hi[1] - block.lo[1]) / (double(n) * n);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const double a = block.lo[0] + (block.hi[0] - block.lo[0]) * (i + 0.5) / n;
            const double b = block.lo[1] + (block.hi[1] - block.lo[1]) * (j + 0.5) / n;
            const Vec3 origin = world(f, a, b, 0.0);
            channel_volume += cell * covered_length(channel_lines.crossings(origin), part_lines_caster.crossings(origin),
                                                    block.lo[2], block.hi[2]);
        }
    const double void_volume =
        block_volume - mesh_volume(mold.top) - mesh_volume(mold.bottom);
    EXPECT_NEAR(void_volume - channel_volume, part_volume, 0.02 * part_volume)
        << "void " << void_volume << " channels " << channel_volume;

    // The void is one connected region, open to the outside through the sprue:
    // the sampled cells of the part lie in one component of the empty cells
    // (up to 3%: cells a piece's lip at the parting line reaches into, or
    // sampled across the part's boundary), which reaches the block's border. Components are
    // 26-connected, so a thin shell part tilted across the cells does not
    // fall into diagonal-only pieces; small empty pockets that are not the
    // part (the clearance around the registration pins) are not counted.
    const int m = 80;
    std::vector<char> empty(size_t(m) * m * m, 0), in_part(empty.size(), 0);
    size_t part_cells = 0;
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j) {
            const double a = block.lo[0] + (block.hi[0] - block.lo[0]) * (i + 0.5) / m;
            const double b = block.lo[1] + (block.hi[1] - block.lo[1]) * (j + 0.5) / m;
            const Vec3 origin = world(f, a, b, 0.0);
            const auto top = top_lines.crossings(origin), bottom = bottom_lines.crossings(origin);
            const auto part_crossings = part_lines_caster.crossings(origin);
            for (int k = 0; k < m; ++k) {
                const double c = block.lo[2] + (block.hi[2] - block.lo[2]) * (k + 0.5) / m;
                const auto in = [c](const std::vector<double>& ts) {
                    return std::count_if(ts.begin(), ts.end(), [c](double t) { return t < c; }) % 2 == 1;
                };
                const size_t cell_index = (size_t(i) * m + j) * m + k;
                if (!in(top) && !in(bottom)) empty[cell_index] = 1;
                if (in(part_crossings)) {
                    in_part[cell_index] = 1;
                    ++part_cells;
                }
            }
        }
    ASSERT_GT(part_cells, 0u);
    std::vector<char> seen(empty.size(), 0);
    size_t largest = 0;
    bool largest_open = false;
    for (size_t start = 0; start < empty.size(); ++start) {
        if (!empty[start] || seen[start]) continue;
        size_t size = 0;
        bool open = false;
        std::queue<size_t> queue;
        queue.push(start);
        seen[start] = 1;
        while (!queue.empty()) {
            const size_t at = queue.front();
            queue.pop();
            size += in_part[at];
            const int i = int(at / (size_t(m) * m)), j = int(at / m % m), k = int(at % m);
            if (i == 0 || j == 0 || k == 0 || i == m - 1 || j == m - 1 || k == m - 1) open = true;
            for (int di = -1; di <= 1; ++di)
                for (int dj = -1; dj <= 1; ++dj)
                    for (int dk = -1; dk <= 1; ++dk) {
                        const int a = i + di, b = j + dj, c = k + dk;
                        if (a < 0 || b < 0 || c < 0 || a >= m || b >= m || c >= m) continue;
                        const size_t next = (size_t(a) * m + b) * m + c;
                        if (empty[next] && !seen[next]) seen[next] = 1, queue.push(next);
                    }
        }
        if (size > largest) largest = size, largest_open = open;
    }
    EXPECT_GE(double(largest), 0.97 * double(part_cells)) << "the void falls apart";
    EXPECT_TRUE(largest_open) << "the void does not reach the outside";
}

}  // namespace fabvdb::test
