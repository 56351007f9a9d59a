//! region_growing: hand-worked cases on a sphere. Grown from seeds at the
//! poles with the directions ±z, the cost −n·d sends every triangle to the
//! region whose direction it faces, so the regions are the two hemispheres,
//! each edge-connected, and the directions stay at ±z (Σ −n·d over a
//! hemisphere is least for its own pole). The reported cost is that sum,
//! −Σ|n_z| over the triangles: about −N/2, since |n_z| averages 1/2 over a
//! sphere.
//! One seed grows over the whole sphere. A thin-feature segment is one
//! element and lands whole in one region.
#include <gtest/gtest.h>

#include <cmath>

#include "shell_shapes.h"
#include "surface/elements.h"
#include "surface/moldability_terms.h"
#include "surface/region_growing.h"

namespace {

using fabvdb::Vec3;

struct Sphere {
    explicit Sphere(fabvdb::surface::Shell s) : shell(std::move(s)) {
        terms = fabvdb::surface::compute_moldability_terms(shell, 0.0, progress);
        elements = fabvdb::surface::make_elements(shell, {}, std::vector<char>(shell.triangle_count(), 1));
    }
    fabvdb::surface::Shell shell;
    fabvdb::Progress progress;
    fabvdb::surface::MoldabilityTerms terms;
    fabvdb::surface::Elements elements;

    //! The element of the triangle whose normal is nearest `d`.
    int element_facing(const Vec3& d) const {
        size_t best = 0;
        double best_dot = -2;
        for (size_t t = 0; t < shell.triangle_count(); ++t) {
            const Vec3& n = shell.normal[t];
            const double dot = n[0] * d[0] + n[1] * d[1] + n[2] * d[2];
            if (dot > best_dot) {
                best_dot = dot;
                best = t;
            }
        }
        return elements.element_of_triangle[best];
    }
    int direction(const Vec3& d) const { return fabvdb::test::nearest_direction(terms.directions.directions, d); }
};

fabvdb::surface::Shell sphere_shell() {
    return fabvdb::test::shell_of(fabvdb::test::make_sphere({0, 0, 0}, 20.0, 3), 1.0);
}

}  // namespace

TEST(RegionGrowing, PolesGrowIntoHemispheres) {
    Sphere sphere(sphere_shell());
    const fabvdb::surface::Regions regions = fabvdb::surface::grow_regions(
        sphere.shell, sphere.terms, sphere.elements, {sphere.element_facing({0, 0, 1}), sphere.element_facing({0, 0, -1})},
        {sphere.direction({0, 0, 1}), sphere.direction({0, 0, -1})}, 1e6, 20, sphere.progress);
    ASSERT_EQ(regions.direction.size(), 2u);
    const Vec3& top = sphere.terms.directions.directions[regions.direction[0]];
    const Vec3& bottom = sphere.terms.directions.directions[regions.direction[1]];
    EXPECT_GT(top[2], 0.99);
    EXPECT_LT(bottom[2], -0.99);
    double cost = 0;
    for (size_t t = 0; t < sphere.shell.triangle_count(); ++t) {
        const Vec3& n = sphere.shell.normal[t];
        const int region = regions.region_of_triangle[t];
        ASSERT_TRUE(region == 0 || region == 1);
        if (n[2] > 0.1) EXPECT_EQ(region, 0) << "triangle " << t << " n_z " << n[2];
        if (n[2] < -0.1) EXPECT_EQ(region, 1) << "triangle " << t << " n_z " << n[2];
        const Vec3& d = region == 0 ? top : bottom;
        cost -= n[0] * d[0] + n[1] * d[1] + n[2] * d[2];
    }
    EXPECT_EQ(fabvdb::test::connected_pieces(sphere.shell, regions.region_of_triangle, 0), 1);
    EXPECT_EQ(fabvdb::test::connected_pieces(sphere.shell, regions.region_of_triangle, 1), 1);
    ASSERT_FALSE(regions.cost_per_iteration.empty());
    EXPECT_GE(regions.iterations, 1);
    const double half = 0.5 * double(sphere.shell.triangle_count());
    EXPECT_NEAR(cost, -half, 0.03 * half);
    EXPECT_NEAR(regions.cost_per_iteration.back(), cost, 1e-9 * half);
}

TEST(RegionGrowing, OneSeedTakesTheWholeSphere) {
    Sphere sphere(sphere_shell());
    const fabvdb::surface::Regions regions =
        fabvdb::surface::grow_regions(sphere.shell, sphere.terms, sphere.elements, {sphere.element_facing({1, 0, 0})},
                                      {sphere.direction({1, 0, 0})}, 1e6, 5, sphere.progress);
    for (int region : regions.region_of_triangle) EXPECT_EQ(region, 0);
}

TEST(RegionGrowing, ThinSegmentStaysWhole) {
    // The triangles with 0 < n_z < 0.5 and n_x > 0 form one thin-feature
    // segment: one element, which straddles nothing but must end in a single
    // region even though half of it faces neither pole strongly.
    fabvdb::surface::Shell shell = sphere_shell();
    std::vector<uint32_t> segment;
    for (size_t t = 0; t < shell.triangle_count(); ++t)
        if (shell.normal[t][2] > -0.3 && shell.normal[t][2] < 0.3 && shell.normal[t][0] > 0.5) {
            shell.thin_segment[t] = 0;
            segment.push_back(uint32_t(t));
        }
    ASSERT_GT(segment.size(), 4u);
    Sphere sphere(std::move(shell));
    EXPECT_EQ(sphere.elements.triangles.size(), sphere.shell.triangle_count() - segment.size() + 1);
    const fabvdb::surface::Regions regions = fabvdb::surface::grow_regions(
        sphere.shell, sphere.terms, sphere.elements, {sphere.element_facing({0, 0, 1}), sphere.element_facing({0, 0, -1})},
        {sphere.direction({0, 0, 1}), sphere.direction({0, 0, -1})}, 1e6, 20, sphere.progress);
    const int region = regions.region_of_triangle[segment.front()];
    EXPECT_GE(region, 0);
    for (uint32_t t : segment) EXPECT_EQ(regions.region_of_triangle[t], region);
}
