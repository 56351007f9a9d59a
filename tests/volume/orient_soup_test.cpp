// orient_soup on boxes whose right orientation is known: unwelded soups with
// triangles flipped at random come back welded, closed, consistent and
// outward (volume +1); inverted shells turn outward; a cavity wall given
// inward inside an outer box stays inward (volume 27 − 1), one that pokes out
// of it does not; duplicate, degenerate triangles and unused vertices go;
// the triangles keep their corners; a cancelled call throws.
#include "volume/orient_soup.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <random>
#include <set>

#include "core/error.h"
#include "support/ray_cast.h"
#include "support/shapes.h"

namespace fabvdb::volume {
namespace {

using test::flipped;
using test::make_box;
using test::merged;
using test::mesh_volume;
using test::unwelded;

// The triangles as unordered sets of corner positions, with multiplicity.
std::multiset<std::array<Vec3, 3>> corner_sets(const Mesh& mesh) {
    std::multiset<std::array<Vec3, 3>> sets;
    for (const Triangle& t : mesh.triangles) {
        std::array<Vec3, 3> corners = {mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]};
        std::sort(corners.begin(), corners.end());
        sets.insert(corners);
    }
    return sets;
}

Mesh oriented(const Mesh& mesh) {
    Progress progress;
    return orient_soup(mesh, progress);
}

TEST(OrientSoup, ScrambledBoxComesBackOutward) {
    const Mesh box = make_box({0, 0, 0}, {1, 1, 1});
    std::mt19937 random(3);
    for (int round = 0; round < 8; ++round) {
        Mesh soup = unwelded(box);
        for (Triangle& t : soup.triangles)
            if (random() % 2) std::swap(t[1], t[2]);
        const Mesh result = oriented(soup);
        EXPECT_EQ(result.vertices.size(), 8u) << "round " << round;
        ASSERT_EQ(result.triangles.size(), 12u) << "round " << round;
        EXPECT_TRUE(test::closed_two_manifold(result)) << "round " << round;
        EXPECT_NEAR(mesh_volume(result), 1.0, 1e-12) << "round " << round;
        EXPECT_EQ(corner_sets(result), corner_sets(box)) << "round " << round;
    }
}

TEST(OrientSoup, InvertedShellsTurnOutward) {
    // Two separate boxes, one inverted: both count as solids.
    const Mesh boxes = merged(make_box({0, 0, 0}, {1, 1, 1}), flipped(make_box({3, 0, 0}, {5, 2, 2})));
    const Mesh result = oriented(boxes);
    EXPECT_TRUE(test::closed_two_manifold(result));
    EXPECT_NEAR(mesh_volume(result), 1.0 + 8.0, 1e-12);
    // A wholly inverted sphere.
    const Mesh sphere = test::make_sphere({1, 2, 3}, 2.0, 2);
    EXPECT_NEAR(mesh_volume(oriented(flipped(sphere))), mesh_volume(sphere), 1e-9);
    EXPECT_GT(mesh_volume(sphere), 0.0);
}

TEST(OrientSoup, CavityWallGivenInwardStaysInward) {
    // A hollow box: the outer wall outward, the cavity wall inward.
    const Mesh hollow = merged(make_box({0, 0, 0}, {3, 3, 3}), flipped(make_box({1, 1, 1}, {2, 2, 2})));
    Mesh result = oriented(hollow);
    EXPECT_TRUE(test::closed_two_manifold(result));
    EXPECT_NEAR(mesh_volume(result), 27.0 - 1.0, 1e-12);
    // The same as an unwelded soup with a minority (4 of 12) of the cavity's
    // triangles and some of the outer wall's flipped: the majority decides.
    Mesh soup = unwelded(hollow);
    for (size_t t : {0, 3, 7, 12, 17, 20, 23}) std::swap(soup.triangles[t][1], soup.triangles[t][2]);
    result = oriented(soup);
    EXPECT_TRUE(test::closed_two_manifold(result));
    EXPECT_NEAR(mesh_volume(result), 26.0, 1e-12);
}

TEST(OrientSoup, InwardShellNotInsideTheSolidTurnsOutward) {
    // The inverted box pokes out of the outer one: an inverted solid of its
    // own, so outward (the volumes add up).
    const Mesh poking = merged(make_box({0, 0, 0}, {3, 3, 3}), flipped(make_box({2, 1, 1}, {4, 2, 2})));
    EXPECT_NEAR(mesh_volume(oriented(poking)), 27.0 + 2.0, 1e-12);
    // Only an inward shell, no solid around it: outward.
    EXPECT_NEAR(mesh_volume(oriented(flipped(make_box({1, 1, 1}, {2, 2, 2})))), 1.0, 1e-12);
}

TEST(OrientSoup, InputStoredInsideOutKeepsItsCavities) {
    // A hollow box turned wholly inside out (most of its area inward) is
    // read turned round: the outer wall outward, the cavity's wall, given
    // outward, inward again — the same hollow box.
    const Mesh hollow = merged(make_box({0, 0, 0}, {3, 3, 3}), flipped(make_box({1, 1, 1}, {2, 2, 2})));
    EXPECT_NEAR(mesh_volume(oriented(flipped(hollow))), 27.0 - 1.0, 1e-12);
    // Mirrored (x negated, the triangles as they were): the same.
    Mesh mirrored = hollow;
    for (Vec3& p : mirrored.vertices) p[0] = -p[0];
    EXPECT_NEAR(mesh_volume(oriented(mirrored)), 27.0 - 1.0, 1e-12);
}

TEST(OrientSoup, DropsDuplicatesDegeneratesAndUnusedVertices) {
    Mesh mesh = make_box({0, 0, 0}, {2, 1, 1});
    mesh.triangles.push_back(mesh.triangles[4]);                                         // duplicate
    mesh.triangles.push_back({mesh.triangles[6][2], mesh.triangles[6][1], mesh.triangles[6][0]});  // reversed duplicate
    mesh.triangles.push_back({0, 0, 1});                                                 // repeated index
    mesh.vertices.push_back({5, 5, 5});                                                  // unused
    mesh.vertices.push_back({0, 0, 0});                                                  // a copy of vertex 0
    mesh.triangles.push_back({0, 9, 1});                                                 // zero area through the copy
    const Mesh result = oriented(mesh);
    EXPECT_EQ(result.vertices.size(), 8u);
    EXPECT_EQ(result.triangles.size(), 12u);
    EXPECT_TRUE(test::closed_two_manifold(result));
    EXPECT_NEAR(mesh_volume(result), 2.0, 1e-12);
}

TEST(OrientSoup, EmptyInputGivesEmptyOutput) {
    const Mesh result = oriented(Mesh{});
    EXPECT_TRUE(result.vertices.empty());
    EXPECT_TRUE(result.triangles.empty());
}

TEST(OrientSoup, CancelledThrows) {
    std::atomic<bool> cancel{true};
    Progress progress(nullptr, nullptr, &cancel);
    try {
        orient_soup(make_box({0, 0, 0}, {1, 1, 1}), progress);
        ADD_FAILURE() << "not cancelled";
    } catch (const Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_CANCELLED);
    }
}

}  // namespace
}  // namespace fabvdb::volume
