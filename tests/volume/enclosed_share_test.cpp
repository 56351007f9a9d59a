// The share of a surface that encloses volume: all of a closed sphere (also
// stored twice, or crossing another), most of a sphere with a hole, almost
// none of an open sheet, a hemispherical bowl (a single range scan of a
// ball), a soup of unrelated triangles or a bowl wound five times over.
#include <gtest/gtest.h>

#include "support/defect_shapes.h"
#include "support/shapes.h"
#include "volume/enclosed_share.h"
#include "volume/winding_number.h"

namespace {

using fabvdb::Mesh;

double share_of(const Mesh& mesh) {
    const fabvdb::volume::WindingNumber winding(mesh);
    return fabvdb::volume::enclosed_share(mesh, winding);
}

// The triangles of a sphere of radius 10 whose centroids satisfy `keep`.
template <class Keep>
Mesh sphere_part(const Keep& keep) {
    Mesh sphere = fabvdb::test::make_sphere({1, 2, 3}, 10.0, 4);
    Mesh part;
    part.vertices = sphere.vertices;
    for (const fabvdb::Triangle& t : sphere.triangles) {
        double z = 0.0;
        for (uint32_t v : t) z += (sphere.vertices[v][2] - 3.0) / 3.0;
        if (keep(z)) part.triangles.push_back(t);
    }
    return part;
}

TEST(EnclosedShare, ClosedSurfacesEncloseAll) {
    EXPECT_GE(share_of(fabvdb::test::make_sphere({1, 2, 3}, 10.0, 4)), 0.999);
    EXPECT_GE(share_of(fabvdb::test::make_torus({0, 0, 0}, 20.0, 2.0, 64, 16)), 0.999);
    // Far from the origin and in metres: the same.
    EXPECT_GE(share_of(fabvdb::test::make_sphere({2e7, -3e7, 1e6}, 10.0, 3)), 0.999);
    EXPECT_GE(share_of(fabvdb::test::make_sphere({0, 0, 0}, 0.02, 3)), 0.999);
}

// w = 2 inside a sphere stored twice, and where two spheres overlap.
TEST(EnclosedShare, OverlappingAndRepeatedClosedShellsEncloseAll) {
    const Mesh sphere = fabvdb::test::make_sphere({1, 2, 3}, 10.0, 4);
    const Mesh twice = fabvdb::test::merged(sphere, sphere);
    const Mesh crossing = fabvdb::test::merged(sphere, fabvdb::test::make_sphere({8, 2, 3}, 10.0, 4));
    EXPECT_GE(share_of(twice), 0.999);
    EXPECT_GE(share_of(crossing), 0.999);
}

TEST(EnclosedShare, ScanWithAHoleEnclosesMost) {
    const Mesh open_bottom = sphere_part([](double z) { return z > -8.0; });
    EXPECT_GT(share_of(open_bottom), 0.5);
}

TEST(EnclosedShare, SheetsBowlsAndSoupsEncloseNothing) {
    Mesh sheet;
    const int n = 20;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) sheet.vertices.push_back({double(i), double(j), 0.1 * ((i * j) % 3)});
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const uint32_t a = uint32_t(j * (n + 1) + i), b = a + 1, c = a + uint32_t(n + 1), d = c + 1;
            sheet.triangles.push_back({a, b, d});
            sheet.triangles.push_back({a, d, c});
        }
    EXPECT_LT(share_of(sheet), 0.05);

    const Mesh bowl = sphere_part([](double z) { return z < 0.0; });
    EXPECT_LT(share_of(bowl), 0.05);

    EXPECT_LT(share_of(fabvdb::test::make_triangle_soup(100, 100.0, 3.0, 18)), 0.05);
    // Larger triangles that cross each other: still far under the share of a solid.
    EXPECT_LT(share_of(fabvdb::test::make_triangle_soup(100, 100.0, 15.0, 7)), 0.05);

    // The same bowl stored five times: w = ±2.5 beside it, past 0.9 but
    // nowhere near 1 nor whole (as in a tangle of inconsistently wound pieces).
    Mesh five = bowl;
    for (int copy = 1; copy < 5; ++copy) five = fabvdb::test::merged(five, bowl);
    EXPECT_LT(share_of(five), 0.05);
}

}  // namespace
