//! Gaussian RBF parting surface (see parting_surface.h).
#include "surface/parting_surface.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "core/error.h"

namespace fabvdb::surface {

namespace {

// Points evenly spaced by arc length along the polyline (open: the caller's
// points are samples of closed loops, and the resampling only thins them).
std::vector<Vec3> resampled(const std::vector<Vec3>& line, size_t count) {
    if (line.size() <= count) return line;
    std::vector<double> arc(line.size(), 0.0);
    for (size_t i = 1; i < line.size(); ++i) {
        const double dx = line[i][0] - line[i - 1][0], dy = line[i][1] - line[i - 1][1],
                     dz = line[i][2] - line[i - 1][2];
        arc[i] = arc[i - 1] + std::sqrt(dx * dx + dy * dy + dz * dz);
    }
    std::vector<Vec3> out;
    size_t at = 0;
    for (size_t k = 0; k < count; ++k) {
        const double target = arc.back() * double(k) / double(count);
        while (at + 1 < line.size() && arc[at + 1] < target) ++at;
        out.push_back(line[at]);
    }
    return out;
}

}  // namespace

void interpolate_parting_surface(const std::vector<Vec3>& parting_line, double z_min, double z_max,
                                 const PartingSurfaceOptions& options, HeightGrid& grid) {
    if (parting_line.size() < 3) throw Error(FABVDB_ERR_BAD_INPUT, "the parting line has fewer than 3 points");
    if (grid.nx < 1 || grid.ny < 1 || !(grid.step > 0))
        throw Error(FABVDB_ERR_INVALID_ARGUMENT, "the parting surface grid is empty");
    if (!(z_min < z_max)) throw Error(FABVDB_ERR_INVALID_ARGUMENT, "the mold block has no height");
    const std::vector<Vec3> points = resampled(parting_line, std::max<size_t>(3, options.max_constraints));
    const Eigen::Index n = Eigen::Index(points.size());

    double lo_x = points[0][0], hi_x = lo_x, lo_y = points[0][1], hi_y = lo_y, mean = 0.0;
    for (const Vec3& p : points) {
        lo_x = std::min(lo_x, p[0]), hi_x = std::max(hi_x, p[0]);
        lo_y = std::min(lo_y, p[1]), hi_y = std::max(hi_y, p[1]);
        mean += p[2];
    }
    mean /= double(n);
    double sigma = options.kernel_width;
    if (!(sigma > 0)) sigma = 0.2 * std::hypot(hi_x - lo_x, hi_y - lo_y);
    if (!(sigma > 0)) sigma = grid.step;
    const double inverse_sigma2 = 1.0 / (sigma * sigma);
    auto kernel = [&](double dx, double dy) { return std::exp(-(dx * dx + dy * dy) * inverse_sigma2); };

    Eigen::MatrixXd system(n, n);
    Eigen::VectorXd rhs(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        rhs[i] = points[size_t(i)][2] - mean;
        for (Eigen::Index j = 0; j <= i; ++j) {
            const double k = kernel(points[size_t(i)][0] - points[size_t(j)][0],
                                    points[size_t(i)][1] - points[size_t(j)][1]);
            system(i, j) = system(j, i) = k;
        }
        system(i, i) += std::max(options.regularization, 1e-12);
    }
    const Eigen::VectorXd weights = system.ldlt().solve(rhs);
    if (!weights.allFinite()) throw Error(FABVDB_ERR_INTERNAL, "the parting surface interpolation did not solve");

    grid.z.assign(size_t(grid.nx + 1) * size_t(grid.ny + 1), mean);
    for (int j = 0; j <= grid.ny; ++j)
        for (int i = 0; i <= grid.nx; ++i) {
            double value = mean;
            for (Eigen::Index k = 0; k < n; ++k)
                value += weights[k] * kernel(grid.x(i) - points[size_t(k)][0], grid.y(j) - points[size_t(k)][1]);
            grid.at(i, j) = std::clamp(value, z_min, z_max);
        }
}

Mesh height_grid_sheet(const HeightGrid& grid) {
    Mesh sheet;
    for (int j = 0; j <= grid.ny; ++j)
        for (int i = 0; i <= grid.nx; ++i) sheet.vertices.push_back({grid.x(i), grid.y(j), grid.at(i, j)});
    auto vertex = [&](int i, int j) { return uint32_t(j * (grid.nx + 1) + i); };
    for (int j = 0; j < grid.ny; ++j)
        for (int i = 0; i < grid.nx; ++i) {
            sheet.triangles.push_back({vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1)});
            sheet.triangles.push_back({vertex(i, j), vertex(i + 1, j + 1), vertex(i, j + 1)});
        }
    return sheet;
}

}  // namespace fabvdb::surface
