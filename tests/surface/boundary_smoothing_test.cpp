//! boundary_smoothing: a sphere cut into two parts by a boundary that zigzags
//! around the equator (z = ±0.15 r, six waves). The straight boundary is the
//! equator, where both parts are moldable along ±z, so smoothing must lower
//! the energy E = Σ E_P + w_l·E_smooth every accepted iteration, straighten
//! the boundary (E_smooth towards −1, the boundary vertices' heights towards
//! 0) and keep each part one connected piece covering its triangles.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "shell_shapes.h"
#include "surface/boundary_smoothing.h"
#include "surface/coarse_decomposition.h"
#include "surface/moldability_terms.h"

namespace {

using fabvdb::Vec3;

//! The mean |z| of the vertices shared by triangles of both parts.
double boundary_amplitude(const fabvdb::surface::Shell& shell, const std::vector<int>& part_of_triangle) {
    std::vector<int> first(shell.outer.vertices.size(), -1);
    std::vector<char> boundary(shell.outer.vertices.size(), 0);
    for (size_t t = 0; t < shell.triangle_count(); ++t)
        for (uint32_t v : shell.outer.triangles[t]) {
            if (first[v] < 0) first[v] = part_of_triangle[t];
            else if (first[v] != part_of_triangle[t]) boundary[v] = 1;
        }
    double sum = 0;
    size_t count = 0;
    for (size_t v = 0; v < boundary.size(); ++v)
        if (boundary[v]) {
            sum += std::abs(shell.outer.vertices[v][2]);
            ++count;
        }
    return count ? sum / double(count) : 0.0;
}

}  // namespace

TEST(BoundarySmoothing, ZigzagAroundTheEquatorStraightens) {
    const double radius = 20.0;
    fabvdb::surface::Shell shell = fabvdb::test::shell_of(fabvdb::test::make_sphere({0, 0, 0}, radius, 3), 1.0);
    fabvdb::Progress progress;
    fabvdb::surface::MoldabilityTerms terms = fabvdb::surface::compute_moldability_terms(shell, 0.0, progress);

    fabvdb::surface::Decomposition decomposition;
    decomposition.part_of_triangle.resize(shell.triangle_count());
    for (size_t t = 0; t < shell.triangle_count(); ++t) {
        Vec3 c{0, 0, 0};
        for (uint32_t v : shell.outer.triangles[t])
            for (int k = 0; k < 3; ++k) c[k] += shell.outer.vertices[v][k] / 3;
        const double wave = 0.15 * radius * std::sin(6 * std::atan2(c[1], c[0]));
        decomposition.part_of_triangle[t] = c[2] > wave ? 0 : 1;
    }
    const std::vector<int> directions{fabvdb::test::nearest_direction(terms.directions.directions, {0, 0, 1}),
                                      fabvdb::test::nearest_direction(terms.directions.directions, {0, 0, -1})};
    fabvdb::surface::DecompositionOptions options;
    options.gamma = 1.0;  // the γ rule does not hold any iteration back here
    options.smoothing_iterations = 10;
    decomposition.parts = fabvdb::surface::parting_lines(shell, terms, decomposition.part_of_triangle, directions,
                                                         options.weights);
    const double amplitude_before = boundary_amplitude(shell, decomposition.part_of_triangle);
    ASSERT_GT(amplitude_before, 0.05 * radius);

    const nlohmann::json record =
        fabvdb::surface::smooth_boundaries(shell, terms, decomposition, options, nullptr, progress);

    const int iterations = record["iterations"];
    EXPECT_GE(iterations, 1);
    const std::vector<double> smoothness = record["smoothness"];
    const std::vector<double> moldability = record["moldability_energy"];
    ASSERT_EQ(smoothness.size(), size_t(iterations) + 1);
    ASSERT_EQ(moldability.size(), smoothness.size());
    for (size_t i = 1; i < smoothness.size(); ++i)
        EXPECT_LT(moldability[i] + options.smoothness_weight * smoothness[i],
                  moldability[i - 1] + options.smoothness_weight * smoothness[i - 1]);
    EXPECT_LT(smoothness.back(), smoothness.front());
    EXPECT_GE(smoothness.back(), -1.0);
    EXPECT_GT(int(record["vertices_moved"]), 0);

    // The boundary vertices came closer to the equator (the triangles stay
    // in their parts: the vertices move, the labels do not).
    EXPECT_LT(boundary_amplitude(shell, decomposition.part_of_triangle), amplitude_before);
    EXPECT_EQ(fabvdb::test::connected_pieces(shell, decomposition.part_of_triangle, 0), 1);
    EXPECT_EQ(fabvdb::test::connected_pieces(shell, decomposition.part_of_triangle, 1), 1);
    // Every vertex still lies on the sphere it started on (moves slide on S_low).
    for (const Vec3& v : shell.outer.vertices)
        EXPECT_NEAR(std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]), radius, 0.02 * radius);
}
