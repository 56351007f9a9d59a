// The closed surface of one part of a decomposition, on a box shell whose
// inner vertices sit halfway to the centre: a whole shell as one part is its
// outer and inner triangles (the core's wall), a solid whole part its outer
// triangles alone, and a half with a boundary gets side quads so that its
// surface is closed — every directed edge once and its reverse once — with
// the adjacency of those matched edges, areas in unit-cube units and unit
// normals facing out of the material; updating it after a vertex moved gives
// the surface built again.
#include "surface/part_surface.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "support/check_vec3.h"
#include "support/shapes.h"
#include "core/vec3_ops.h"
#include "surface/shell.h"

namespace fabvdb::surface {
namespace {

// A 2 mm cube (unit scale 1/2) with inner vertices halfway to its centre.
Shell box_shell(bool solid) {
    const Mesh outer = test::make_box({-1, -1, -1}, {1, 1, 1});
    std::vector<Vec3> inner;
    for (const Vec3& p : outer.vertices) inner.push_back({0.5 * p[0], 0.5 * p[1], 0.5 * p[2]});
    Shell shell = make_shell(outer, inner, std::vector<int>(outer.triangles.size(), -1), 0.5, "box");
    shell.solid = solid;
    return shell;
}

// Every directed edge of the surface once, its reverse once.
bool closed(const PartSurface& s) {
    std::map<std::pair<uint32_t, uint32_t>, int> directed;
    for (const auto& c : s.corners)
        for (int k = 0; k < 3; ++k) ++directed[{c[k], c[(k + 1) % 3]}];
    for (const auto& [edge, count] : directed) {
        const auto reverse = directed.find({edge.second, edge.first});
        if (count != 1 || reverse == directed.end() || reverse->second != 1) return false;
    }
    return true;
}

size_t count(const PartSurface& s, PartSurface::Kind kind) {
    size_t n = 0;
    for (PartSurface::Kind k : s.kind) n += k == kind;
    return n;
}

// Signed volume of the surface by the divergence theorem, in mm³.
double volume(const Shell& shell, const PartSurface& s) {
    double six = 0;
    for (const auto& c : s.corners) {
        const Vec3 &a = corner_position(shell, c[0]), &b = corner_position(shell, c[1]),
                   &d = corner_position(shell, c[2]);
        six += test::dot(a, test::cross(b, d));
    }
    return six / 6.0;
}

TEST(PartSurface, AWholeShellIsItsOuterAndInnerWalls) {
    const Shell shell = box_shell(false);
    const PartSurface s = part_surface(shell, std::vector<int>(12, 0), 0);
    EXPECT_EQ(count(s, PartSurface::outer), 12u);
    EXPECT_EQ(count(s, PartSurface::inner), 12u);
    EXPECT_EQ(count(s, PartSurface::side), 0u);
    EXPECT_TRUE(closed(s));
    // The material between the 2 mm cube and the 1 mm core: 8 − 1 mm³.
    EXPECT_NEAR(volume(shell, s), 7.0, 1e-12);
}

TEST(PartSurface, ASolidWholePartIsItsOuterTrianglesAlone) {
    const Shell shell = box_shell(true);
    const PartSurface s = part_surface(shell, std::vector<int>(12, 0), 0);
    EXPECT_EQ(s.size(), 12u);
    EXPECT_EQ(count(s, PartSurface::outer), 12u);
    EXPECT_TRUE(closed(s));
    EXPECT_NEAR(volume(shell, s), 8.0, 1e-12);
}

TEST(PartSurface, AHalfGetsSideQuadsAlongItsBoundary) {
    for (bool solid : {false, true}) {
        const Shell shell = box_shell(solid);
        // The triangles whose centroid is above z = 0 (the top face, half of
        // each side face's triangles) against the rest.
        std::vector<int> part_of_triangle;
        for (const Triangle& t : shell.outer.triangles) {
            double z = 0;
            for (uint32_t v : t) z += shell.outer.vertices[v][2] / 3.0;
            part_of_triangle.push_back(z > 0 ? 0 : 1);
        }
        double both = 0;
        for (int part : {0, 1}) {
            const PartSurface s = part_surface(shell, part_of_triangle, part);
            SCOPED_TRACE(testing::Message() << "solid " << solid << ", part " << part);
            EXPECT_EQ(count(s, PartSurface::inner), count(s, PartSurface::outer));
            EXPECT_GT(count(s, PartSurface::side), 0u);
            EXPECT_EQ(count(s, PartSurface::side) % 2, 0u);  // two triangles per boundary edge
            EXPECT_TRUE(closed(s));
            const double v = volume(shell, s);
            EXPECT_GT(v, 0.0);
            both += v;
            // Each triangle's neighbours share an edge with it, the other way round.
            ASSERT_EQ(s.adjacency_start.size(), s.size() + 1);
            for (size_t i = 0; i < s.size(); ++i) {
                EXPECT_GE(s.adjacent(i).size(), 3u) << i;
                EXPECT_NEAR(std::sqrt(s.normal[i][0] * s.normal[i][0] + s.normal[i][1] * s.normal[i][1] +
                                      s.normal[i][2] * s.normal[i][2]),
                            1.0, 1e-12);
            }
        }
        // The two halves make up the shell between the cube and the core.
        EXPECT_NEAR(both, 7.0, 1e-12);
    }
}

TEST(PartSurface, AreasAreInUnitCubeUnits) {
    const Shell shell = box_shell(true);
    const PartSurface s = part_surface(shell, std::vector<int>(12, 0), 0);
    double area = 0;
    for (double a : s.area) area += a;
    // Six 2 mm faces, 24 mm², at unit scale 1/2: 6 unit-cube units.
    EXPECT_NEAR(area, 6.0, 1e-12);
}

TEST(PartSurface, UpdatingAfterAMoveEqualsBuildingAgain) {
    Shell shell = box_shell(false);
    std::vector<int> part_of_triangle;
    for (const Triangle& t : shell.outer.triangles) {
        double z = 0;
        for (uint32_t v : t) z += shell.outer.vertices[v][2] / 3.0;
        part_of_triangle.push_back(z > 0 ? 0 : 1);
    }
    PartSurface updated = part_surface(shell, part_of_triangle, 0);
    // One top corner pulled in (outer and inner), the box's extent kept by the others.
    const uint32_t v = shell.outer.triangles[0][0];
    std::vector<char> moved(shell.outer.vertices.size(), 0);
    moved[v] = 1;
    shell.outer.vertices[v] = 0.8 * shell.outer.vertices[v];
    shell.inner[v] = 0.7 * shell.inner[v];
    for (size_t t = 0; t < shell.triangle_count(); ++t) {
        const Triangle& f = shell.outer.triangles[t];
        const Vec3 c = cross(shell.outer.vertices[f[1]] - shell.outer.vertices[f[0]],
                             shell.outer.vertices[f[2]] - shell.outer.vertices[f[0]]);
        shell.normal[t] = normalized(c);
    }
    const std::vector<uint32_t> changed = update_part_surface(shell, moved, updated);
    const PartSurface fresh = part_surface(shell, part_of_triangle, 0);
    ASSERT_EQ(updated.size(), fresh.size());
    size_t differ = 0;
    for (size_t i = 0; i < fresh.size(); ++i) {
        EXPECT_EQ(updated.normal[i], fresh.normal[i]) << i;
        EXPECT_EQ(updated.area[i], fresh.area[i]) << i;
        const bool listed = std::find(changed.begin(), changed.end(), uint32_t(i)) != changed.end();
        const auto& c = fresh.corners[i];
        const size_t n = shell.outer.vertices.size();
        const bool on_v = c[0] % n == v || c[1] % n == v || c[2] % n == v;
        EXPECT_EQ(listed, on_v) << i;
        differ += on_v;
    }
    EXPECT_GT(differ, 4u);
}

}  // namespace
}  // namespace fabvdb::surface
