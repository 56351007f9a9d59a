//! Per-axis projected overlaps: project the outer triangles on the plane
//! normal to the axis, bin their 2-D boxes in a uniform grid, test each box
//! pair once (in the cell holding the lower corner of the boxes' overlap) and
//! clip the two triangles to measure the shared area.
#include "surface/moldability_terms.h"

#include <algorithm>
#include <atomic>
#include <cmath>

#include <tbb/parallel_for.h>

#include "surface/vec3_ops.h"

namespace fabvdb::surface {

namespace {

struct Point2 {
    double x, y;
};
using Polygon2 = std::vector<Point2>;

double signed_area(const Polygon2& p) {
    double twice = 0;
    for (size_t i = 0; i < p.size(); ++i) {
        const Point2& a = p[i];
        const Point2& b = p[(i + 1) % p.size()];
        twice += a.x * b.y - a.y * b.x;
    }
    return 0.5 * twice;
}

//! Area of the intersection of two counter-clockwise triangles (clipping).
double intersection_area(const std::array<Point2, 3>& a, const std::array<Point2, 3>& b) {
    Polygon2 polygon(a.begin(), a.end());
    Polygon2 clipped;
    for (int k = 0; k < 3 && !polygon.empty(); ++k) {
        const Point2 p = b[k];
        const Point2 q = b[(k + 1) % 3];
        const auto side = [&](const Point2& r) { return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x); };
        clipped.clear();
        for (size_t i = 0; i < polygon.size(); ++i) {
            const Point2& s = polygon[i];
            const Point2& e = polygon[(i + 1) % polygon.size()];
            const double ss = side(s);
            const double se = side(e);
            if (ss >= 0) clipped.push_back(s);
            if ((ss >= 0) != (se >= 0)) {
                const double t = ss / (ss - se);
                clipped.push_back({s.x + t * (e.x - s.x), s.y + t * (e.y - s.y)});
            }
        }
        polygon.swap(clipped);
    }
    return polygon.size() < 3 ? 0.0 : std::abs(signed_area(polygon));
}

struct Box2 {
    double lo[2], hi[2];
};

MoldabilityTerms::Overlaps overlaps_along_axis(const Shell& shell, const Vec3& axis) {
    const size_t n = shell.triangle_count();
    const Vec3 helper = std::abs(axis[0]) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 u = normalized(cross(axis, helper));
    const Vec3 v = cross(axis, u);
    std::vector<std::array<Point2, 3>> projected(n);
    std::vector<Box2> boxes(n);
    std::vector<char> usable(n);
    double mean_size = 0;
    for (size_t t = 0; t < n; ++t) {
        auto& tri = projected[t];
        for (int k = 0; k < 3; ++k) {
            const Vec3& p = shell.outer.vertices[shell.outer.triangles[t][k]];
            tri[k] = {dot(p, u), dot(p, v)};
        }
        const double facing = dot(shell.normal[t], axis);
        usable[t] = std::abs(facing) > 1e-9;
        if (facing < 0) std::swap(tri[1], tri[2]);  // counter-clockwise in (u, v)
        Box2& box = boxes[t];
        box.lo[0] = std::min({tri[0].x, tri[1].x, tri[2].x});
        box.hi[0] = std::max({tri[0].x, tri[1].x, tri[2].x});
        box.lo[1] = std::min({tri[0].y, tri[1].y, tri[2].y});
        box.hi[1] = std::max({tri[0].y, tri[1].y, tri[2].y});
        mean_size += (box.hi[0] - box.lo[0]) + (box.hi[1] - box.lo[1]);
    }
    mean_size = std::max(mean_size / (2.0 * n), 1e-12);
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    for (const Box2& b : boxes)
        for (int k = 0; k < 2; ++k) {
            lo[k] = std::min(lo[k], b.lo[k]);
            hi[k] = std::max(hi[k], b.hi[k]);
        }
    const double cell = 2.0 * mean_size;
    const int nx = std::max(1, int((hi[0] - lo[0]) / cell) + 1);
    const int ny = std::max(1, int((hi[1] - lo[1]) / cell) + 1);
    const auto cell_of = [&](double value, int k) {
        return std::clamp(int((value - lo[k]) / cell), 0, (k == 0 ? nx : ny) - 1);
    };
    std::vector<uint32_t> cell_start(size_t(nx) * ny + 1, 0);
    for (size_t t = 0; t < n; ++t) {
        if (!usable[t]) continue;
        for (int j = cell_of(boxes[t].lo[1], 1); j <= cell_of(boxes[t].hi[1], 1); ++j)
            for (int i = cell_of(boxes[t].lo[0], 0); i <= cell_of(boxes[t].hi[0], 0); ++i)
                ++cell_start[size_t(j) * nx + i + 1];
    }
    for (size_t c = 1; c < cell_start.size(); ++c) cell_start[c] += cell_start[c - 1];
    std::vector<uint32_t> cell_items(cell_start.back());
    std::vector<uint32_t> fill(cell_start.begin(), cell_start.end() - 1);
    for (size_t t = 0; t < n; ++t) {
        if (!usable[t]) continue;
        for (int j = cell_of(boxes[t].lo[1], 1); j <= cell_of(boxes[t].hi[1], 1); ++j)
            for (int i = cell_of(boxes[t].lo[0], 0); i <= cell_of(boxes[t].hi[0], 0); ++i)
                cell_items[fill[size_t(j) * nx + i]++] = uint32_t(t);
    }
    const double area_scale = shell.unit_scale * shell.unit_scale;
    const double tiny = 1e-9 * mean_size * mean_size;
    std::vector<std::vector<std::pair<uint32_t, float>>> found(n);
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const size_t c = size_t(j) * nx + i;
            for (uint32_t x = cell_start[c]; x < cell_start[c + 1]; ++x)
                for (uint32_t y = x + 1; y < cell_start[c + 1]; ++y) {
                    const uint32_t a = cell_items[x], b = cell_items[y];
                    const Box2& ba = boxes[a];
                    const Box2& bb = boxes[b];
                    const double overlap_lo_x = std::max(ba.lo[0], bb.lo[0]);
                    const double overlap_lo_y = std::max(ba.lo[1], bb.lo[1]);
                    if (overlap_lo_x > std::min(ba.hi[0], bb.hi[0]) || overlap_lo_y > std::min(ba.hi[1], bb.hi[1]))
                        continue;
                    if (cell_of(overlap_lo_x, 0) != i || cell_of(overlap_lo_y, 1) != j) continue;
                    if (dot(shell.normal[a], axis) * dot(shell.normal[b], axis) < 0) continue;
                    const double shared = intersection_area(projected[a], projected[b]);
                    if (shared <= tiny) continue;
                    found[a].push_back({b, float(shared * area_scale)});
                    found[b].push_back({a, float(shared * area_scale)});
                }
        }
    MoldabilityTerms::Overlaps result;
    result.offset.assign(n + 1, 0);
    for (size_t t = 0; t < n; ++t) result.offset[t + 1] = result.offset[t] + uint32_t(found[t].size());
    result.partner.reserve(result.offset.back());
    result.area.reserve(result.offset.back());
    for (size_t t = 0; t < n; ++t)
        for (const auto& [partner, area] : found[t]) {
            result.partner.push_back(partner);
            result.area.push_back(area);
        }
    return result;
}

}  // namespace

double overhang_term(const Vec3& n, double area, const Vec3& d, double draft) {
    const double c = std::clamp(dot(n, d), -1.0, 1.0);
    const double theta = std::acos(c);
    if (theta <= M_PI / 2 - draft) return 0.0;
    return -std::cos(std::min(theta + draft, M_PI)) * area * std::abs(c);
}

MoldabilityTerms compute_moldability_terms(const Shell& shell, double draft_radians, Progress& progress) {
    MoldabilityTerms terms;
    terms.draft = draft_radians;
    terms.directions = thesis_directions();
    const size_t count = terms.directions.directions.size();
    terms.axis_of_direction.assign(count, -1);
    for (size_t i = 0; i < count; ++i) {
        const int j = terms.directions.opposite[i];
        if (terms.axis_of_direction[i] >= 0) continue;
        terms.axis_of_direction[i] = int(terms.axes.size());
        terms.axis_of_direction[size_t(j)] = int(terms.axes.size());
        terms.axes.push_back(terms.directions.directions[i]);
    }
    terms.overlaps.resize(terms.axes.size());
    progress.stage("moldability terms");
    std::atomic<size_t> done{0};
    tbb::parallel_for(size_t(0), terms.axes.size(), [&](size_t a) {
        if (progress.cancelled()) return;
        terms.overlaps[a] = overlaps_along_axis(shell, terms.axes[a]);
        progress.update(double(++done) / terms.axes.size());
    });
    progress.check();
    for (const auto& o : terms.overlaps) terms.pair_count += o.partner.size() / 2;
    return terms;
}

}  // namespace fabvdb::surface
