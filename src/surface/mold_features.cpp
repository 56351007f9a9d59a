//! Gates, runners, sprue, vents and registration keys (see mold_features.h).
#include "surface/mold_features.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "surface/height_field_solid.h"

namespace fabvdb::surface {

namespace {

// Marks the cells whose centres lie within `half_width` of the axis-aligned
// segment from (ax, ay) to (bx, by).
void mark_segment(const HeightGrid& grid, double ax, double ay, double bx, double by, double half_width,
                  std::vector<char>& cells) {
    const double x_lo = std::min(ax, bx) - half_width, x_hi = std::max(ax, bx) + half_width;
    const double y_lo = std::min(ay, by) - half_width, y_hi = std::max(ay, by) + half_width;
    for (int j = 0; j < grid.ny; ++j)
        for (int i = 0; i < grid.nx; ++i) {
            const double cx = grid.x(i) + 0.5 * grid.step, cy = grid.y(j) + 0.5 * grid.step;
            if (cx >= x_lo && cx <= x_hi && cy >= y_lo && cy <= y_hi) cells[size_t(j) * size_t(grid.nx) + size_t(i)] = 1;
        }
}

// Lowest and highest parting-surface height within `radius` of (x, y).
std::array<double, 2> surface_range(const HeightGrid& grid, double x, double y, double radius) {
    std::array<double, 2> range{1e300, -1e300};
    for (int j = 0; j <= grid.ny; ++j)
        for (int i = 0; i <= grid.nx; ++i)
            if (std::hypot(grid.x(i) - x, grid.y(j) - y) <= radius + 1.5 * grid.step) {
                range[0] = std::min(range[0], grid.at(i, j));
                range[1] = std::max(range[1], grid.at(i, j));
            }
    return range;
}

}  // namespace

MoldFeatureSizes mold_feature_sizes(double margin) {
    MoldFeatureSizes sizes;
    sizes.runner_half_width = margin / 10;
    sizes.vent_half_width = margin / 30;
    sizes.runner_clearance = margin / 4;
    sizes.key_radius = margin / 10;
    sizes.key_height = margin / 5;
    sizes.key_clearance = 0.2;
    return sizes;
}

Mesh vertical_prism(double center_x, double center_y, double radius, double z0, double z1, int sides) {
    Mesh prism;
    prism.vertices.push_back({center_x, center_y, z0});
    prism.vertices.push_back({center_x, center_y, z1});
    for (int k = 0; k < sides; ++k) {
        const double angle = 2 * M_PI * k / sides;
        const double x = center_x + radius * std::cos(angle), y = center_y + radius * std::sin(angle);
        prism.vertices.push_back({x, y, z0});
        prism.vertices.push_back({x, y, z1});
    }
    for (int k = 0; k < sides; ++k) {
        const uint32_t b0 = uint32_t(2 + 2 * k), t0 = b0 + 1;
        const uint32_t b1 = uint32_t(2 + 2 * ((k + 1) % sides)), t1 = b1 + 1;
        prism.triangles.push_back({0, b1, b0});
        prism.triangles.push_back({1, t0, t1});
        prism.triangles.push_back({b0, b1, t1});
        prism.triangles.push_back({b0, t1, t0});
    }
    return prism;
}

MoldFeatures place_mold_features(const std::vector<std::vector<Vec3>>& parting_lines, const HeightGrid& surface,
                                 const Vec3& block_lo, const Vec3& block_hi, const Vec3& part_lo,
                                 const Vec3& part_hi, const MoldFeatureSizes& sizes) {
    std::vector<Vec3> parting_line;
    for (const auto& line : parting_lines) {
        if (line.empty()) throw Error(FABVDB_ERR_BAD_INPUT, "a part has no parting line");
        parting_line.insert(parting_line.end(), line.begin(), line.end());
    }
    if (parting_line.empty()) throw Error(FABVDB_ERR_BAD_INPUT, "the part has no parting line");
    MoldFeatures features;
    features.channel_cells.assign(size_t(surface.nx) * size_t(surface.ny), 0);
    const double exit_y = surface.y(surface.ny);

    // A gate at each part's lowest point, a runner straight down from it
    // (nothing else is below a part in a row along X), one runner along
    // below all the parts to their right, then up as the sprue through the
    // top face.
    const double runner_y = part_lo[1] - sizes.runner_clearance;
    const double sprue_x = part_hi[0] + sizes.runner_clearance;
    const double w = sizes.runner_half_width;
    double runner_start = sprue_x;
    for (const auto& line : parting_lines) {
        const Vec3 gate = *std::min_element(line.begin(), line.end(),
                                            [](const Vec3& a, const Vec3& b) { return a[1] < b[1]; });
        features.gates.push_back(gate);
        mark_segment(surface, gate[0], gate[1], gate[0], runner_y, w, features.channel_cells);
        runner_start = std::min(runner_start, gate[0]);
    }
    mark_segment(surface, runner_start, runner_y, sprue_x, runner_y, w, features.channel_cells);
    mark_segment(surface, sprue_x, runner_y, sprue_x, exit_y, w, features.channel_cells);

    // Vents: points higher than every other parting-line point within the
    // margin, highest first, whose way straight up is clear of the part.
    std::vector<Vec3> candidates;
    const double neighbourhood = block_hi[0] - part_hi[0];
    for (const Vec3& p : parting_line) {
        bool highest = true, clear = true;
        for (const Vec3& q : parting_line) {
            const double dx = q[0] - p[0], dy = q[1] - p[1];
            if (dy > 0 && std::hypot(dx, dy) < neighbourhood) highest = false;
            if (dy > 2 * surface.step && std::abs(dx) < sizes.vent_half_width + surface.step) clear = false;
        }
        if (highest && clear) candidates.push_back(p);
    }
    std::sort(candidates.begin(), candidates.end(), [](const Vec3& a, const Vec3& b) { return a[1] > b[1]; });
    for (const Vec3& p : candidates) {
        if (features.vents.size() == 4) break;
        bool apart = std::abs(p[0] - sprue_x) > 2 * (w + surface.step);
        for (const Vec3& v : features.vents) apart = apart && std::abs(p[0] - v[0]) > 4 * w;
        if (!apart) continue;
        features.vents.push_back(p);
        mark_segment(surface, p[0], p[1], p[0], exit_y, std::max(sizes.vent_half_width, 0.6 * surface.step),
                     features.channel_cells);
    }

    // Channels that meet only at a cell's corner would pinch the channel solid.
    join_corner_contacts(surface, features.channel_cells);

    // Keys near the four corners, in the margin between the runner and the border.
    const double inset = 0.35 * (block_hi[0] - part_hi[0]);
    for (double x : {block_lo[0] + inset, block_hi[0] - inset})
        for (double y : {block_lo[1] + inset, block_hi[1] - inset}) {
            features.key_centers.push_back({x, y});
            const auto range = surface_range(surface, x, y, sizes.key_radius + sizes.key_clearance);
            const Mesh pin = vertical_prism(x, y, sizes.key_radius, range[0] - sizes.key_height,
                                            range[1] + sizes.key_height, 24);
            const Mesh hole = vertical_prism(x, y, sizes.key_radius + sizes.key_clearance,
                                             range[0] - sizes.key_height,
                                             range[1] + sizes.key_height + sizes.key_clearance, 24);
            for (auto [target, add] : {std::pair{&features.pins, &pin}, std::pair{&features.holes, &hole}}) {
                const uint32_t offset = uint32_t(target->vertices.size());
                target->vertices.insert(target->vertices.end(), add->vertices.begin(), add->vertices.end());
                for (Triangle t : add->triangles) target->triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
            }
        }
    return features;
}

}  // namespace fabvdb::surface
