// cluster_cavity_patches: on a 10 mm box with one patch per triangle, exact
// areas, centroids, sites, inward normals and neighbours (edges 10, 10, 10√2);
// a whole box in one bin as one patch; two boxes as two cavities, even in one
// bin; on an icosphere, the guarantees against brute force (every triangle
// placed, areas, centroids, sites, inward normals, connected patches,
// symmetric borders); an empty mesh and a zero count refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <vector>

#include "core/error.h"
#include "powder/cavity_patches.h"
#include "support/check_vec3.h"
#include "support/shapes.h"

namespace {

using fabvdb::Mesh;
using fabvdb::Vec3;
using fabvdb::powder::CavityPatches;
using fabvdb::powder::cluster_cavity_patches;

Vec3 centre(const Mesh& mesh, size_t t) {
    Vec3 c{0, 0, 0};
    for (uint32_t v : mesh.triangles[t])
        for (int k = 0; k < 3; ++k) c[k] += mesh.vertices[v][k] / 3.0;
    return c;
}

using fabvdb::test::dot;
using fabvdb::test::norm;
using fabvdb::test::sub;

//! Per pair of triangles sharing an edge (smaller index first), the edge's length.
std::map<std::pair<uint32_t, uint32_t>, double> shared_edges(const Mesh& mesh) {
    std::map<std::pair<uint32_t, uint32_t>, std::vector<uint32_t>> of_edge;
    for (uint32_t t = 0; t < mesh.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            uint32_t a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
            of_edge[{std::min(a, b), std::max(a, b)}].push_back(t);
        }
    std::map<std::pair<uint32_t, uint32_t>, double> pairs;
    for (const auto& [edge, triangles] : of_edge) {
        EXPECT_EQ(triangles.size(), 2u) << "the test meshes are closed";
        if (triangles.size() != 2) continue;
        pairs[{std::min(triangles[0], triangles[1]), std::max(triangles[0], triangles[1])}] +=
            std::sqrt(fabvdb::squared_distance(mesh.vertices[edge.first], mesh.vertices[edge.second]));
    }
    return pairs;
}

//! Borders between patches from the triangles' shared edges.
std::map<std::pair<uint32_t, uint32_t>, double> expected_borders(const Mesh& mesh, const CavityPatches& patches) {
    std::map<std::pair<uint32_t, uint32_t>, double> borders;
    for (const auto& [pair, length] : shared_edges(mesh)) {
        const uint32_t a = patches.patch_of_triangle[pair.first], b = patches.patch_of_triangle[pair.second];
        if (a == b) continue;
        borders[{a, b}] += length;
        borders[{b, a}] += length;
    }
    return borders;
}

void expect_borders(const Mesh& mesh, const CavityPatches& patches) {
    const auto expected = expected_borders(mesh, patches);
    std::map<std::pair<uint32_t, uint32_t>, double> listed;
    ASSERT_EQ(patches.neighbours.size(), patches.size());
    for (uint32_t p = 0; p < patches.size(); ++p)
        for (const auto& neighbour : patches.neighbours[p]) {
            EXPECT_NE(neighbour.patch, p);
            EXPECT_EQ(listed.count({p, neighbour.patch}), 0u) << "listed twice: " << p << "–" << neighbour.patch;
            listed[{p, neighbour.patch}] = neighbour.shared_length;
        }
    ASSERT_EQ(listed.size(), expected.size());
    for (const auto& [pair, length] : expected) {
        ASSERT_TRUE(listed.count(pair)) << pair.first << "–" << pair.second;
        EXPECT_NEAR(listed.at(pair), length, 1e-9) << pair.first << "–" << pair.second;
    }
}

fabvdb_status refusal(const Mesh& mesh, size_t count) {
    try {
        cluster_cavity_patches(mesh, count);
    } catch (const fabvdb::Error& e) {
        return e.status();
    }
    return FABVDB_OK;
}

}  // namespace

TEST(CavityPatches, RefusesAnEmptySurfaceAndAZeroCount) {
    EXPECT_EQ(refusal(Mesh{}, 10), FABVDB_ERR_BAD_INPUT);
    EXPECT_EQ(refusal(fabvdb::test::make_box({0, 0, 0}, {1, 1, 1}), 0), FABVDB_ERR_INVALID_ARGUMENT);
}

TEST(CavityPatches, SmallCellsMakeEachTriangleOfABoxAPatch) {
    // Area 600 over 600 patches: cells of 1 mm, and the twelve triangle
    // centres (thirds of 10 on the faces) all fall in different cells.
    const Mesh box = fabvdb::test::make_box({0, 0, 0}, {10, 10, 10});
    const CavityPatches patches = cluster_cavity_patches(box, 600);
    ASSERT_EQ(patches.size(), 12u);
    EXPECT_EQ(patches.cavity_count, 1u);
    ASSERT_EQ(patches.patch_of_triangle.size(), 12u);
    std::set<uint32_t> distinct(patches.patch_of_triangle.begin(), patches.patch_of_triangle.end());
    EXPECT_EQ(distinct.size(), 12u);
    for (size_t t = 0; t < 12; ++t) {
        const uint32_t p = patches.patch_of_triangle[t];
        ASSERT_LT(p, 12u);
        EXPECT_NEAR(patches.area[p], 50.0, 1e-9);
        EXPECT_EQ(patches.cavity[p], 0u);
        const Vec3 c = centre(box, t);
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(patches.centroid[p][k], c[k], 1e-9);
            EXPECT_NEAR(patches.site[p][k], c[k], 1e-9);
        }
        // Inward: the unit axis pointing from the face towards the box's middle.
        Vec3 inward{0, 0, 0};
        for (int k = 0; k < 3; ++k) {
            if (c[k] == 0.0) inward[k] = 1.0;
            if (c[k] == 10.0) inward[k] = -1.0;
        }
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(patches.normal[p][k], inward[k], 1e-12) << "triangle " << t;
        // Two sides of 10 shared with the neighbouring faces, the diagonal with the face's other half.
        ASSERT_EQ(patches.neighbours[p].size(), 3u);
        std::vector<double> lengths;
        for (const auto& neighbour : patches.neighbours[p]) lengths.push_back(neighbour.shared_length);
        std::sort(lengths.begin(), lengths.end());
        EXPECT_NEAR(lengths[0], 10.0, 1e-9);
        EXPECT_NEAR(lengths[1], 10.0, 1e-9);
        EXPECT_NEAR(lengths[2], 10.0 * std::sqrt(2.0), 1e-9);
    }
    expect_borders(box, patches);
}

TEST(CavityPatches, ABoxInOneCellIsOnePatch) {
    // Area 384, one patch: a cell of √384 ≈ 19.6 holds the whole box [1, 9]³.
    const Mesh box = fabvdb::test::make_box({1, 1, 1}, {9, 9, 9});
    const CavityPatches patches = cluster_cavity_patches(box, 1);
    ASSERT_EQ(patches.size(), 1u);
    EXPECT_NEAR(patches.area[0], 384.0, 1e-9);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(patches.centroid[0][k], 5.0, 1e-9);
    // The site is a triangle centre, on a face.
    const Vec3& site = patches.site[0];
    EXPECT_TRUE(std::count_if(site.begin(), site.end(), [](double x) { return x == 1.0 || x == 9.0; }) == 1)
        << site[0] << " " << site[1] << " " << site[2];
    // A closed patch's area-weighted normal vanishes; it still gets a unit one.
    EXPECT_NEAR(dot(patches.normal[0], patches.normal[0]), 1.0, 1e-12);
    EXPECT_TRUE(patches.neighbours[0].empty());
}

TEST(CavityPatches, SeparateSurfacesAreSeparateCavitiesEvenInOneCell) {
    const Mesh a = fabvdb::test::make_box({0, 0, 0}, {1, 1, 1});
    const Mesh b = fabvdb::test::make_box({1.5, 0, 0}, {2.5, 1, 1});
    const Mesh both = fabvdb::test::merged(a, b);
    // One patch asked for: a cell of √12 ≈ 3.5 holds both boxes, split by connection.
    CavityPatches patches = cluster_cavity_patches(both, 1);
    EXPECT_EQ(patches.cavity_count, 2u);
    ASSERT_EQ(patches.size(), 2u);
    EXPECT_NE(patches.patch_of_triangle[0], patches.patch_of_triangle[12]);
    for (size_t t = 0; t < 24; ++t)
        EXPECT_EQ(patches.patch_of_triangle[t], patches.patch_of_triangle[t < 12 ? 0 : 12]) << "triangle " << t;
    EXPECT_NE(patches.cavity[0], patches.cavity[1]);
    for (int p = 0; p < 2; ++p) EXPECT_NEAR(patches.area[size_t(p)], 6.0, 1e-9);
    EXPECT_NEAR(patches.centroid[patches.patch_of_triangle[0]][0], 0.5, 1e-9);
    EXPECT_NEAR(patches.centroid[patches.patch_of_triangle[12]][0], 2.0, 1e-9);
    // Finer: many patches, none straddling or bordering across the boxes.
    patches = cluster_cavity_patches(both, 40);
    EXPECT_EQ(patches.cavity_count, 2u);
    for (size_t t = 0; t < 24; ++t)
        EXPECT_EQ(patches.cavity[patches.patch_of_triangle[t]], patches.cavity[patches.patch_of_triangle[t < 12 ? 0 : 12]]);
    for (uint32_t p = 0; p < patches.size(); ++p)
        for (const auto& neighbour : patches.neighbours[p]) EXPECT_EQ(patches.cavity[neighbour.patch], patches.cavity[p]);
    expect_borders(both, patches);
}

TEST(CavityPatches, OnASphereEveryGuaranteeHolds) {
    const Vec3 middle{2, -1, 3};
    const Mesh sphere = fabvdb::test::make_sphere(middle, 10.0, 3);
    const size_t target = 100;
    const CavityPatches patches = cluster_cavity_patches(sphere, target);
    const size_t n = patches.size();
    // About the count asked for: bins of one patch's area, some cut in pieces.
    EXPECT_GE(n, target / 2);
    EXPECT_LE(n, 4 * target);
    EXPECT_EQ(patches.cavity_count, 1u);
    ASSERT_EQ(patches.patch_of_triangle.size(), sphere.triangles.size());
    ASSERT_EQ(patches.centroid.size(), n);
    ASSERT_EQ(patches.site.size(), n);
    ASSERT_EQ(patches.normal.size(), n);
    ASSERT_EQ(patches.cavity.size(), n);

    std::vector<double> area(n, 0.0);
    std::vector<Vec3> centroid(n, Vec3{0, 0, 0});
    std::vector<std::vector<uint32_t>> members(n);
    double total = 0;
    for (uint32_t t = 0; t < sphere.triangles.size(); ++t) {
        const uint32_t p = patches.patch_of_triangle[t];
        ASSERT_LT(p, n);
        const double a = fabvdb::triangle_area(sphere, sphere.triangles[t]);
        const Vec3 c = centre(sphere, t);
        area[p] += a;
        total += a;
        for (int k = 0; k < 3; ++k) centroid[p][k] += a * c[k];
        members[p].push_back(t);
    }
    double patch_total = 0;
    const auto neighbours_of_triangles = shared_edges(sphere);
    for (uint32_t p = 0; p < n; ++p) {
        ASSERT_FALSE(members[p].empty()) << "patch " << p << " has no triangle";
        EXPECT_EQ(patches.cavity[p], 0u);
        EXPECT_NEAR(patches.area[p], area[p], 1e-9);
        patch_total += patches.area[p];
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(patches.centroid[p][k], centroid[p][k] / area[p], 1e-9);
        // Unit, and into the sphere: against the way from the middle to the patch.
        const Vec3& normal = patches.normal[p];
        EXPECT_NEAR(dot(normal, normal), 1.0, 1e-9);
        const Vec3 out = sub(patches.centroid[p], middle);
        const double r = norm(out);
        EXPECT_LT(dot(normal, out) / r, -0.9) << "patch " << p;
        // The site is the centre of a patch triangle nearest its centroid (ties either way).
        double nearest = HUGE_VAL;
        for (uint32_t t : members[p])
            nearest = std::min(nearest, fabvdb::squared_distance(centre(sphere, t), patches.centroid[p]));
        bool site_found = false;
        for (uint32_t t : members[p])
            site_found |= fabvdb::squared_distance(centre(sphere, t), patches.site[p]) < 1e-18 &&
                          fabvdb::squared_distance(centre(sphere, t), patches.centroid[p]) < nearest + 1e-9;
        EXPECT_TRUE(site_found) << "patch " << p;
        // Edge-connected: a walk over shared edges inside the patch reaches all of it.
        std::set<uint32_t> reached{members[p][0]}, frontier{members[p][0]};
        while (!frontier.empty()) {
            std::set<uint32_t> next;
            for (const auto& [pair, length] : neighbours_of_triangles) {
                (void)length;
                if (patches.patch_of_triangle[pair.first] != p || patches.patch_of_triangle[pair.second] != p) continue;
                if (frontier.count(pair.first) && !reached.count(pair.second)) next.insert(pair.second);
                if (frontier.count(pair.second) && !reached.count(pair.first)) next.insert(pair.first);
            }
            reached.insert(next.begin(), next.end());
            frontier = next;
        }
        EXPECT_EQ(reached.size(), members[p].size()) << "patch " << p << " is in pieces";
    }
    EXPECT_NEAR(patch_total, total, 1e-9 * total);
    expect_borders(sphere, patches);
}
