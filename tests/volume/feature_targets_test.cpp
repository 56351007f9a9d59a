//! feature_targets against the box [0, 10]³, whose twelve edges are sharp
//! (90°) and whose eight vertices are corners, with surface vertices placed by
//! hand: the vertex nearest a corner goes to the corner, one beside an edge to
//! its closest point on the edge; nothing is drawn beyond reach, from the
//! middle of a face, by a vertex whose normal faces away (a wall's far side),
//! or to an edge when the input triangle closest to the vertex faces away (a
//! shell inside another). A vertex of the box's edge where only two collinear
//! sharp edges meet is no corner. A smooth input (a sphere) draws nothing.
#include <gtest/gtest.h>

#include "support/ray_cast.h"
#include "support/shapes.h"
#include "volume/feature_targets.h"

namespace {

using fabvdb::Mesh;
using fabvdb::Vec3;

//! A surface vertex with its outward normal and the normal of the input
//! triangle closest to it.
struct Probe {
    Vec3 position, normal, nearest_input_normal;
};

fabvdb::volume::FeatureTargets targets_of(const std::vector<Probe>& probes, const Mesh& input, double reach) {
    Mesh surface;
    std::vector<Vec3> normals, nearest;
    for (const Probe& p : probes) {
        surface.vertices.push_back(p.position);
        normals.push_back(p.normal);
        nearest.push_back(p.nearest_input_normal);
    }
    return fabvdb::volume::feature_targets(surface, normals, nearest, input, reach);
}

const Mesh box = fabvdb::test::make_box({0, 0, 0}, {10, 10, 10});

//! The box [0, 10]³ with its faces y = 0, y = 10, z = 0 and z = 10 each split
//! at x = 5: the four edges along x have a vertex at x = 5 where two
//! collinear sharp edges meet (and only flat face edges besides).
Mesh box_split_at_x5() {
    Mesh mesh;
    for (double x : {0.0, 5.0, 10.0})
        for (double y : {0.0, 10.0})
            for (double z : {0.0, 10.0}) mesh.vertices.push_back({x, y, z});
    // Vertex (i, y, z) at index 4i + 2·(y > 0) + (z > 0).
    const auto v = [](uint32_t i, uint32_t y, uint32_t z) { return 4 * i + 2 * y + z; };
    const auto quad = [&](uint32_t a, uint32_t b, uint32_t c, uint32_t d) {  // counter-clockwise seen from outside
        mesh.triangles.push_back({a, b, c});
        mesh.triangles.push_back({a, c, d});
    };
    for (uint32_t i = 0; i < 2; ++i) {
        quad(v(i, 0, 0), v(i + 1, 0, 0), v(i + 1, 0, 1), v(i, 0, 1));  // y = 0
        quad(v(i, 1, 0), v(i, 1, 1), v(i + 1, 1, 1), v(i + 1, 1, 0));  // y = 10
        quad(v(i, 0, 0), v(i, 1, 0), v(i + 1, 1, 0), v(i + 1, 0, 0));  // z = 0
        quad(v(i, 0, 1), v(i + 1, 0, 1), v(i + 1, 1, 1), v(i, 1, 1));  // z = 10
    }
    quad(v(0, 0, 0), v(0, 0, 1), v(0, 1, 1), v(0, 1, 0));  // x = 0
    quad(v(2, 0, 0), v(2, 1, 0), v(2, 1, 1), v(2, 0, 1));  // x = 10
    return mesh;
}

void expect_target(const fabvdb::volume::FeatureTargets& targets, size_t v, const Vec3& expected) {
    ASSERT_TRUE(targets.has_target[v]) << "vertex " << v;
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(targets.target[v][k], expected[k], 1e-12) << "vertex " << v;
}

}  // namespace

TEST(FeatureTargets, CornerAndEdgeDrawTheirNearestVertices) {
    const auto targets = targets_of({{{0.3, 0.3, 0.3}, {-1, -1, -1}, {0, 0, -1}},
                                     {{0.6, 0.3, 0.3}, {0, -1, -1}, {0, -1, 0}},
                                     {{5.2, 0.2, 0.3}, {0, -1, -1}, {0, -1, 0}},
                                     {{10.2, 4.1, 9.8}, {1, 0, 1}, {0, 0, 1}}},
                                    box, 1.0);
    expect_target(targets, 0, {0, 0, 0});
    expect_target(targets, 1, {0.6, 0, 0});
    expect_target(targets, 2, {5.2, 0, 0});
    expect_target(targets, 3, {10, 4.1, 10});
}

TEST(FeatureTargets, NothingBeyondReachOrInTheMiddleOfAFace) {
    const auto targets = targets_of({{{5, 1.5, 0}, {0, -1, -1}, {0, 0, -1}},
                                     {{5, 5, -0.2}, {0, 0, -1}, {0, 0, -1}},
                                     {{1.2, 1.2, 1.2}, {-1, -1, -1}, {0, 0, -1}}},
                                    box, 1.0);
    for (size_t v = 0; v < 3; ++v) EXPECT_FALSE(targets.has_target[v]) << "vertex " << v;
}

TEST(FeatureTargets, VertexFacingAwayIsNotDrawn) {
    // Beside the edge and the corner, but facing into the box (the far side of a wall).
    const auto targets = targets_of({{{5, 0.2, 0.3}, {0, 1, 1}, {0, -1, 0}},
                                     {{0.3, 0.3, 0.3}, {1, 1, 1}, {0, 0, -1}}},
                                    box, 1.0);
    EXPECT_FALSE(targets.has_target[0]);
    EXPECT_FALSE(targets.has_target[1]);
}

TEST(FeatureTargets, EdgeIgnoresAVertexWhoseClosestInputTriangleFacesAway) {
    // Facing the edge's triangles, but closest to an input triangle facing +y
    // (another shell's): the edge leaves it; a corner does not ask.
    const auto targets = targets_of({{{5, 0.2, 0.3}, {0, -1, -1}, {0, 1, 0}},
                                     {{0.3, 0.3, 0.3}, {-1, -1, -1}, {0, 1, 0}}},
                                    box, 1.0);
    EXPECT_FALSE(targets.has_target[0]);
    expect_target(targets, 1, {0, 0, 0});
}

TEST(FeatureTargets, CollinearSharpEdgesMakeNoCorner) {
    const Mesh split = box_split_at_x5();
    ASSERT_TRUE(fabvdb::test::closed_two_manifold(split));
    ASSERT_NEAR(fabvdb::test::mesh_volume(split), 1000.0, 1e-9);
    const auto targets = targets_of({{{5.3, 0.2, 0.2}, {0, -1, -1}, {0, -1, 0}},
                                     {{0.3, 0.2, 0.2}, {-1, -1, -1}, {0, -1, 0}}},
                                    split, 1.0);
    expect_target(targets, 0, {5.3, 0, 0});  // onto the edge, not to (5, 0, 0)
    expect_target(targets, 1, {0, 0, 0});
}

TEST(FeatureTargets, SmoothInputDrawsNothing) {
    // Neighbouring faces of a level-3 icosphere turn by a few degrees.
    const Mesh sphere = fabvdb::test::make_sphere({0, 0, 0}, 10, 3);
    std::vector<Probe> probes;
    for (size_t v = 0; v < sphere.vertices.size(); v += 7) {
        const Vec3& p = sphere.vertices[v];
        probes.push_back({{1.02 * p[0], 1.02 * p[1], 1.02 * p[2]}, p, {p[0] / 10, p[1] / 10, p[2] / 10}});
    }
    const auto targets = targets_of(probes, sphere, 1.0);
    for (size_t v = 0; v < probes.size(); ++v) EXPECT_FALSE(targets.has_target[v]) << "vertex " << v;
}
