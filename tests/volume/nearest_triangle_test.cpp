// Nearest triangle from hints: on a box, answers worked out by hand from the
// hints of the 27 voxels around a point (the best one wins; -1, inactive,
// out-of-range and farther hints are ignored), the descent from an edge or
// corner point over one and two rings, none without a usable hint, and on a
// sphere with OpenVDB's closest-polygon grid the same distance as a brute
// force over all triangles. A query at a voxel's centre sees the hint of the
// next voxel (the centre maps to its own voxel, whatever the rounding).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <openvdb/openvdb.h>
#include <openvdb/tools/MeshToVolume.h>

#include "support/shapes.h"
#include "volume/nearest_triangle.h"

namespace {

using fabvdb::Mesh;
using fabvdb::test::make_box;
using fabvdb::volume::NearestTriangle;
using fabvdb::volume::TriangleFeature;
using openvdb::Coord;
using openvdb::Vec3d;

// make_box({0,0,0}, {2,2,2}): triangles 0, 1 at z = 0; 2 = (0,0,2)(2,0,2)(2,2,2)
// and 3 = (0,0,2)(2,2,2)(0,2,2) at z = 2; 4, 5 at y = 0; 6, 7 at y = 2;
// 8 = (0,0,0)(0,0,2)(0,2,2) and 9 at x = 0; 10 = (2,0,0)(2,2,0)(2,2,2) and 11 at x = 2.
struct BoxFixture : testing::Test {
    Mesh box = make_box({0, 0, 0}, {2, 2, 2});
    openvdb::Int32Grid::Ptr hints = openvdb::Int32Grid::create(-1);  // unit voxels
    BoxFixture() { openvdb::initialize(); }
    void hint(const Coord& ijk, int triangle) { hints->tree().setValue(ijk, triangle); }
};

void expect_point(const Vec3d& actual, const Vec3d& expected) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(actual[k], expected[k], 1e-12) << "coordinate " << k;
}

TEST_F(BoxFixture, AHintInTheVoxelOrANeighbourIsFound) {
    const Vec3d p(0.3, 0.4, 3.0);  // above triangle 3
    const NearestTriangle search(box, *hints);
    for (const Coord offset : {Coord(0, 0, 0), Coord(1, 1, 1), Coord(-1, 0, 1), Coord(0, -1, -1)}) {
        hints->clear();
        hint(Coord(0, 0, 3) + offset, 3);  // p's voxel (the one whose centre is nearest) is (0, 0, 3)
        NearestTriangle::Query query(search, false);
        const auto result = query(p);
        ASSERT_TRUE(result.found()) << offset;
        EXPECT_EQ(result.triangle, 3u);
        EXPECT_EQ(result.feature, TriangleFeature::face);
        EXPECT_NEAR(result.distance, 1.0, 1e-12);
        expect_point(result.point, {0.3, 0.4, 2.0});
    }
}

TEST_F(BoxFixture, NoUsableHintFindsNothing) {
    const Vec3d p(0.3, 0.4, 3.0);
    const NearestTriangle search(box, *hints);
    const auto none = [&] {
        NearestTriangle::Query query(search);
        const auto result = query(p);
        EXPECT_FALSE(result.found());
        EXPECT_EQ(result.distance, std::numeric_limits<double>::infinity());
    };
    none();                   // an empty grid
    hint(Coord(2, 0, 3), 3);  // two voxels from p's voxel (0, 0, 3)
    hint(Coord(0, -2, 3), 3);
    none();
    hints->clear();
    hint(Coord(0, 0, 3), -1);  // an active "none"
    hint(Coord(0, 0, 2), 12);  // past the last triangle
    hint(Coord(0, 1, 3), 1000000);
    none();
    hints->tree().setValueOff(Coord(0, 1, 2), 3);  // inactive
    none();
}

TEST_F(BoxFixture, TheNearestOfTheHintsWins) {
    const Vec3d p(0.3, 0.4, 3.0);
    hint(Coord(-1, 0, 2), 0);  // the bottom: 3 away
    hint(Coord(0, 0, 2), 10);  // x = 2: from (2, 0.4, 2), sqrt(1.7² + 1)
    hint(Coord(1, 1, 4), 3);   // 1 away
    hint(Coord(-1, 1, 3), 6);  // y = 2: from (0.3, 2, 2), sqrt(1.6² + 1)
    const NearestTriangle search(box, *hints);
    NearestTriangle::Query query(search, false);
    const auto result = query(p);
    EXPECT_EQ(result.triangle, 3u);
    EXPECT_NEAR(result.distance, 1.0, 1e-12);
    // Without the best, the next best.
    hints->tree().setValueOff(Coord(1, 1, 4));
    const auto next = query(p);
    EXPECT_EQ(next.triangle, 6u);
    EXPECT_NEAR(next.distance, std::sqrt(2.56 + 1.0), 1e-12);
    expect_point(next.point, {0.3, 2.0, 2.0});
}

TEST_F(BoxFixture, DescentFromAnEdgePointReachesTheNearestFace) {
    // p is nearest to triangle 10 at (2, 1.2, 0.8), 1 away; the only hint,
    // triangle 2 on the top, is nearest at (2, 1.2, 2) on its edge x = 2.
    const Vec3d p(3.0, 1.2, 0.8);
    hint(Coord(3, 1, 1), 2);
    const NearestTriangle search(box, *hints);
    NearestTriangle::Query hints_only(search, false);
    const auto first = hints_only(p);
    EXPECT_EQ(first.triangle, 2u);
    EXPECT_NE(first.feature, TriangleFeature::face);
    EXPECT_NEAR(first.distance, std::sqrt(1.0 + 1.44), 1e-12);
    expect_point(first.point, {2.0, 1.2, 2.0});
    NearestTriangle::Query descending(search);
    const auto result = descending(p);
    EXPECT_EQ(result.triangle, 10u);
    EXPECT_EQ(result.feature, TriangleFeature::face);
    EXPECT_NEAR(result.distance, 1.0, 1e-12);
    expect_point(result.point, {2.0, 1.2, 0.8});
}

TEST_F(BoxFixture, DescentGoesOnOverASecondRing) {
    // p is nearest to triangle 3 at (0.5, 1.5, 2). The hint, triangle 4 at
    // y = 0, is nearest at (1.75, 0, 1.75) on its diagonal (1.97 away); the
    // triangles on its corners are nearest at triangle 8's edge (0, 1.5, 2)
    // (1.118 away), whose corners reach triangle 3.
    const Vec3d p(0.5, 1.5, 3.0);
    hint(Coord(1, 2, 3), 4);
    const NearestTriangle search(box, *hints);
    NearestTriangle::Query hints_only(search, false);
    EXPECT_NEAR(hints_only(p).distance, std::sqrt(1.25 * 1.25 + 1.5 * 1.5 + 1.25 * 1.25), 1e-12);
    NearestTriangle::Query descending(search);
    const auto result = descending(p);
    EXPECT_EQ(result.triangle, 3u);
    EXPECT_EQ(result.feature, TriangleFeature::face);
    EXPECT_NEAR(result.distance, 1.0, 1e-12);
    expect_point(result.point, {0.5, 1.5, 2.0});
}

TEST_F(BoxFixture, NoDescentFromAFacePoint) {
    // The hint, the bottom triangle 0, is nearest at a face point (3 away):
    // the answer stays there although triangle 3 is 1 away (the documented limit).
    const Vec3d p(0.3, 0.4, 3.0);
    hint(Coord(1, 1, 3), 0);
    const NearestTriangle search(box, *hints);
    NearestTriangle::Query query(search);
    const auto result = query(p);
    EXPECT_EQ(result.triangle, 0u);
    EXPECT_EQ(result.feature, TriangleFeature::face);
    EXPECT_NEAR(result.distance, 3.0, 1e-12);
}

TEST_F(BoxFixture, HintsAddedBetweenQueriesAreSeen) {
    const Vec3d p(0.3, 0.4, 3.0);
    hint(Coord(-20, -20, -20), 0);  // somewhere else, so the tree is not empty
    const NearestTriangle search(box, *hints);
    NearestTriangle::Query query(search);
    EXPECT_FALSE(query(p).found());
    hint(Coord(1, 1, 3), 3);
    const auto result = query(p);
    EXPECT_TRUE(result.found());
    EXPECT_EQ(result.triangle, 3u);
}

TEST_F(BoxFixture, PointsOnAVoxelGridFollowTheTransform) {
    // Half-size voxels: p = (0.5, 0.7, 3.0) is in voxel (1, 1, 6).
    hints->setTransform(openvdb::math::Transform::createLinearTransform(0.5));
    hint(Coord(1, 1, 6), 3);
    const NearestTriangle search(box, *hints);
    NearestTriangle::Query query(search);
    EXPECT_EQ(query({0.5, 0.7, 3.0}).triangle, 3u);
    EXPECT_FALSE(query({0.5, 0.7, 4.0}).found());  // voxel (1, 1, 8)
}

//! Distance from p to triangle abc by minimising over a fine barycentric
//! grid, then over the edges exactly: a method of its own.
double brute_distance(const Vec3d& p, const Vec3d& a, const Vec3d& b, const Vec3d& c) {
    const auto segment = [&](const Vec3d& u, const Vec3d& v) {
        const Vec3d d = v - u;
        const double t = std::clamp((p - u).dot(d) / d.lengthSqr(), 0.0, 1.0);
        return (u + d * t - p).length();
    };
    double best = std::min({segment(a, b), segment(b, c), segment(c, a)});
    // Inside: the plane's distance if the projection is inside (same-side tests).
    Vec3d n = (b - a).cross(c - a);
    n.normalize();
    const Vec3d q = p - n * (p - a).dot(n);
    const auto side = [&](const Vec3d& u, const Vec3d& v) { return (v - u).cross(q - u).dot(n) >= 0; };
    if (side(a, b) && side(b, c) && side(c, a)) best = std::min(best, std::abs((p - a).dot(n)));
    return best;
}

TEST(NearestTriangle, OnASphereWithOpenVdbHintsItIsTheBruteForceDistance) {
    openvdb::initialize();
    const Mesh sphere = fabvdb::test::make_sphere({0.1, 0.2, -0.1}, 2.0, 3);  // 1280 triangles
    const double voxel = 0.2;
    std::vector<openvdb::Vec3s> points;
    std::vector<openvdb::Vec3I> triangles;
    const auto transform = openvdb::math::Transform::createLinearTransform(voxel);
    for (const auto& v : sphere.vertices) points.emplace_back(transform->worldToIndex(Vec3d(v[0], v[1], v[2])));
    for (const auto& t : sphere.triangles) triangles.emplace_back(t[0], t[1], t[2]);
    openvdb::tools::QuadAndTriangleDataAdapter<openvdb::Vec3s, openvdb::Vec3I> adapter(points, triangles);
    openvdb::util::NullInterrupter interrupter;
    openvdb::Int32Grid hints(-1);
    hints.setTransform(transform);
    openvdb::tools::meshToVolume<openvdb::FloatGrid>(interrupter, adapter, *transform, 3.0f, 3.0f, 0, &hints);
    ASSERT_GT(hints.activeVoxelCount(), 1000u);

    const NearestTriangle search(sphere, hints);
    NearestTriangle::Query query(search);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    int checked = 0;
    while (checked < 300) {
        Vec3d direction(unit(random), unit(random), unit(random));
        if (direction.length() < 0.1 || direction.length() > 1.0) continue;
        direction.normalize();
        const Vec3d p = Vec3d(0.1, 0.2, -0.1) + direction * (2.0 + 0.4 * unit(random));  // within 2 voxels
        const auto result = query(p);
        ASSERT_TRUE(result.found()) << p;
        double best = std::numeric_limits<double>::infinity();
        for (const auto& t : sphere.triangles) {
            const auto vertex = [&](uint32_t i) { return Vec3d(sphere.vertices[i][0], sphere.vertices[i][1], sphere.vertices[i][2]); };
            best = std::min(best, brute_distance(p, vertex(t[0]), vertex(t[1]), vertex(t[2])));
        }
        ASSERT_NEAR(result.distance, best, 1e-9) << p;
        // The point is on the triangle found, at that distance.
        EXPECT_NEAR((result.point - p).length(), result.distance, 1e-12);
        const auto& t = sphere.triangles[result.triangle];
        const auto vertex = [&](uint32_t i) { return Vec3d(sphere.vertices[i][0], sphere.vertices[i][1], sphere.vertices[i][2]); };
        EXPECT_NEAR(brute_distance(result.point, vertex(t[0]), vertex(t[1]), vertex(t[2])), 0.0, 1e-9);
        ++checked;
    }
}

TEST(NearestTriangle, AHintInTheNextVoxelOfAVoxelCentreIsSeen) {
    openvdb::initialize();
    const fabvdb::Mesh box = fabvdb::test::make_box({-10, -1, -1}, {-9, 1, 1});
    openvdb::Int32Grid hints(-1);
    hints.setTransform(openvdb::math::Transform::createLinearTransform(0.1));
    const NearestTriangle search(box, hints);
    NearestTriangle::Query query(search, false);
    int missed = 0;
    for (int x = -100; x < 0; ++x) {
        hints.clear();
        hints.tree().setValue(Coord(x + 1, 0, 0), 0);  // the voxel next to the queried one
        const auto result = query(hints.indexToWorld(Coord(x, 0, 0)));
        if (!result.found()) {
            ++missed;
            ADD_FAILURE() << "voxel centre (" << x << ", 0, 0): the hint at (" << x + 1 << ", 0, 0) was not seen";
            if (missed >= 3) break;
        }
    }
    EXPECT_EQ(missed, 0);
}

}  // namespace
