//! parting_line: on a sphere, with the whole sphere one part and the parting
//! direction +z, the graph cut puts the upper hemisphere in M⁺ (top mold) and
//! the lower in M⁻, each one connected piece, and the part is moldable (no
//! overhang or overlap beyond the band of triangles at the equator). Along
//! +x the cut turns with the direction. best_parting_line finds an axis for
//! which the sphere is as moldable, and over all 81 axes exactly the lowest
//! of their parting lines (a half sphere: sides, an inner surface). A part's network kept while vertices move
//! relabels as a parting line computed from scratch on the moved shell.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <queue>

#include "shell_shapes.h"
#include "surface/moldability_terms.h"
#include "surface/parting_line.h"

namespace {

using fabvdb::Vec3;

//! Edge-connected pieces of the outer triangles of `molding` with upper == side.
int pieces(const fabvdb::surface::PartMolding& molding, char side) {
    const auto& surface = molding.surface;
    std::vector<char> seen(surface.size(), 0);
    int count = 0;
    for (size_t start = 0; start < surface.size(); ++start) {
        if (seen[start] || surface.kind[start] != fabvdb::surface::PartSurface::outer || molding.upper[start] != side)
            continue;
        ++count;
        std::queue<uint32_t> queue;
        queue.push(uint32_t(start));
        seen[start] = 1;
        while (!queue.empty()) {
            const uint32_t t = queue.front();
            queue.pop();
            for (uint32_t u : surface.adjacent(t))
                if (!seen[u] && surface.kind[u] == fabvdb::surface::PartSurface::outer && molding.upper[u] == side) {
                    seen[u] = 1;
                    queue.push(u);
                }
        }
    }
    return count;
}

struct Sphere {
    fabvdb::surface::Shell shell = fabvdb::test::shell_of(fabvdb::test::make_sphere({0, 0, 0}, 20.0, 3), 1.0);
    fabvdb::Progress progress;
    fabvdb::surface::MoldabilityTerms terms = fabvdb::surface::compute_moldability_terms(shell, 0.0, progress);
    std::vector<int> one_part = std::vector<int>(shell.triangle_count(), 0);
};

void expect_split_along(const Sphere& sphere, const fabvdb::surface::PartMolding& molding, const Vec3& d) {
    const auto& surface = molding.surface;
    size_t outer = 0;
    for (size_t i = 0; i < surface.size(); ++i) {
        if (surface.kind[i] != fabvdb::surface::PartSurface::outer) continue;
        ++outer;
        const Vec3& n = sphere.shell.normal[surface.source[i]];
        const double up = n[0] * d[0] + n[1] * d[1] + n[2] * d[2];
        if (up > 0.15) EXPECT_TRUE(molding.upper[i]) << "triangle " << surface.source[i] << " n·d " << up;
        if (up < -0.15) EXPECT_FALSE(molding.upper[i]) << "triangle " << surface.source[i] << " n·d " << up;
    }
    EXPECT_EQ(outer, sphere.shell.triangle_count());
    EXPECT_EQ(pieces(molding, 1), 1);
    EXPECT_EQ(pieces(molding, 0), 1);
}

}  // namespace

TEST(PartingLine, SphereSplitsAtItsEquator) {
    const Sphere sphere;
    const int up = fabvdb::test::nearest_direction(sphere.terms.directions.directions, {0, 0, 1});
    const fabvdb::surface::PartMolding molding =
        fabvdb::surface::parting_line(sphere.shell, sphere.terms, sphere.one_part, 0, up, {});
    EXPECT_EQ(molding.direction, up);
    expect_split_along(sphere, molding, sphere.terms.directions.directions[up]);
    // A sphere is a double height field along any axis: what energy is left
    // comes from the triangles the equator passes through, a thin band.
    double area = 0;
    for (double a : sphere.shell.area) area += a;
    EXPECT_LT(molding.energy.total, 0.01 * area);
    EXPECT_GE(molding.energy.overhang, 0.0);
    EXPECT_GE(molding.energy.overlap, 0.0);
}

TEST(PartingLine, TheCutTurnsWithTheDirection) {
    const Sphere sphere;
    const int side = fabvdb::test::nearest_direction(sphere.terms.directions.directions, {1, 0, 0});
    const fabvdb::surface::PartMolding molding =
        fabvdb::surface::parting_line(sphere.shell, sphere.terms, sphere.one_part, 0, side, {});
    expect_split_along(sphere, molding, sphere.terms.directions.directions[side]);
}

TEST(PartingLine, BestAxisOfASphereIsAsGoodAsAny) {
    Sphere sphere;
    const int up = fabvdb::test::nearest_direction(sphere.terms.directions.directions, {0, 0, 1});
    const double along_z =
        fabvdb::surface::parting_line(sphere.shell, sphere.terms, sphere.one_part, 0, up, {}).energy.total;
    const fabvdb::surface::PartMolding best = fabvdb::surface::best_parting_line(
        sphere.shell, sphere.terms, sphere.one_part, 0, {}, {}, sphere.progress, 81);
    EXPECT_LE(best.energy.total, along_z + 1e-12);
    expect_split_along(sphere, best, sphere.terms.directions.directions[best.direction]);
}

TEST(PartingLine, BestOfAllAxesIsTheArgminOfTheirPartingLines) {
    // A half sphere (a part with sides and an inner surface, so the fix-up
    // has components to join): checking all 81 axes gives exactly the
    // lowest of their parting lines.
    Sphere sphere;
    std::vector<int> halves(sphere.shell.triangle_count());
    for (size_t t = 0; t < halves.size(); ++t) halves[t] = sphere.shell.normal[t][0] + 0.3 * sphere.shell.normal[t][2] > 0;
    const fabvdb::surface::PartMolding best =
        fabvdb::surface::best_parting_line(sphere.shell, sphere.terms, halves, 1, {}, {}, sphere.progress, 81);
    double lowest = 1e300;
    for (size_t d = 0; d < sphere.terms.directions.directions.size(); ++d) {
        if (sphere.terms.axes[size_t(sphere.terms.axis_of_direction[d])] != sphere.terms.directions.directions[d])
            continue;
        const fabvdb::surface::PartMolding one =
            fabvdb::surface::parting_line(sphere.shell, sphere.terms, halves, 1, int(d), {});
        lowest = std::min(lowest, one.energy.total);
        if (int(d) == best.direction) EXPECT_EQ(one.upper, best.upper);
    }
    EXPECT_EQ(best.energy.total, lowest);
}

TEST(PartingLine, AKeptNetworkFollowsMovedVertices) {
    Sphere sphere;
    std::vector<int> halves(sphere.shell.triangle_count());
    for (size_t t = 0; t < halves.size(); ++t) {
        double z = 0;
        for (uint32_t v : sphere.shell.outer.triangles[t]) z += sphere.shell.outer.vertices[v][2] / 3;
        halves[t] = z > 3.0 ? 0 : 1;
    }
    const int side = fabvdb::test::nearest_direction(sphere.terms.directions.directions, {1, 0, 0.3});
    fabvdb::surface::PartMolding kept =
        fabvdb::surface::parting_line(sphere.shell, sphere.terms, halves, 0, side, {});
    fabvdb::surface::PartNetwork network(kept.surface);
    // A dent across the boundary: the vertices with 0 < z < 12 pulled in.
    fabvdb::Mesh mesh = sphere.shell.outer;
    for (Vec3& p : mesh.vertices)
        if (p[2] > 0 && p[2] < 12) p = {0.8 * p[0], 0.8 * p[1], p[2]};
    const fabvdb::surface::Shell moved_shell = fabvdb::test::shell_of(mesh, 1.0);
    ASSERT_EQ(moved_shell.unit_scale, sphere.shell.unit_scale);
    std::vector<char> moved(mesh.vertices.size(), 0);
    size_t count = 0;
    for (size_t v = 0; v < moved.size(); ++v) {
        moved[v] = moved_shell.outer.vertices[v] != sphere.shell.outer.vertices[v] ||
                   moved_shell.inner[v] != sphere.shell.inner[v];
        count += moved[v];
    }
    ASSERT_GT(count, 50u);
    network.update(fabvdb::surface::update_part_surface(moved_shell, moved, kept.surface));
    network.relabel(moved_shell, sphere.terms, {}, kept);
    const fabvdb::surface::PartMolding fresh =
        fabvdb::surface::parting_line(moved_shell, sphere.terms, halves, 0, side, {});
    ASSERT_EQ(kept.surface.size(), fresh.surface.size());
    for (size_t i = 0; i < fresh.surface.size(); ++i) {
        EXPECT_EQ(kept.surface.normal[i], fresh.surface.normal[i]) << "surface triangle " << i;
        EXPECT_EQ(kept.surface.area[i], fresh.surface.area[i]) << "surface triangle " << i;
    }
    EXPECT_EQ(kept.upper, fresh.upper);
    EXPECT_EQ(kept.energy.total, fresh.energy.total);
    // The move changed the labelling: a stale network would not pass the above.
    const fabvdb::surface::PartMolding before =
        fabvdb::surface::parting_line(sphere.shell, sphere.terms, halves, 0, side, {});
    EXPECT_NE(before.energy.total, fresh.energy.total);
}
