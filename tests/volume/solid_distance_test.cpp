// Signed distance of a clean solid with its nearest triangles, checked voxel
// by voxel against code that shares nothing with it: CGAL's AABB tree for
// the distance and Side_of_triangle_mesh (ray casting) for the sign.
#include "volume/solid_distance.h"

#include <gtest/gtest.h>

#include <CGAL/Side_of_triangle_mesh.h>

#include <algorithm>
#include <atomic>
#include <cmath>

#include "core/error.h"
#include "io/mesh_io.h"
#include "support/cgal_mesh.h"
#include "support/shapes.h"

namespace fabvdb::volume {
namespace {

using test::cgal::Kernel;
using test::cgal::Point;
using test::cgal::SurfaceMesh;
using test::cgal::Tree;
using test::cgal::Triangle3;

struct Figures {
    size_t voxels = 0, band_voxels = 0, wrong_sign = 0;
    double band_error = 0;        // largest |stored - true| within a voxel of the surface, mm
    double too_deep = 0;          // largest true - |stored| inside (the stored one too small), mm
    double too_shallow = 0;       // largest |stored| - true inside, mm
    double index_error = 0;       // largest |stored| - distance to the stored triangle, mm
    double deepest_reached = 0;   // mm
};

Figures measure(const Mesh& mesh, const SolidDistance& solid, double voxel) {
    const std::vector<Triangle3> triangles = test::cgal::triangles_of(mesh);
    Tree tree(triangles.begin(), triangles.end());
    tree.accelerate_distance_queries();
    const SurfaceMesh surface = test::cgal::surface_mesh_of(mesh);
    const CGAL::Side_of_triangle_mesh<SurfaceMesh, Kernel> side(surface);

    Figures figures;
    const auto index = solid.closest_triangle->getConstAccessor();
    for (auto it = solid.distance->cbeginValueOn(); it; ++it) {
        const openvdb::Vec3d w = solid.distance->indexToWorld(it.getCoord());
        const Point p(w[0], w[1], w[2]);
        const double truth = std::sqrt(tree.squared_distance(p));
        const double stored = std::abs(*it);
        ++figures.voxels;
        if (truth > 1e-3 * voxel) {
            const bool inside = side(p) == CGAL::ON_BOUNDED_SIDE;
            if (inside != (*it < 0)) ++figures.wrong_sign;
        }
        if (truth <= voxel) {
            ++figures.band_voxels;
            figures.band_error = std::max(figures.band_error, std::abs(stored - truth));
        } else {
            figures.too_deep = std::max(figures.too_deep, truth - stored);
            figures.too_shallow = std::max(figures.too_shallow, stored - truth);
        }
        figures.deepest_reached = std::max(figures.deepest_reached, *it < 0 ? truth : 0.0);
        int32_t t = -1;
        EXPECT_TRUE(index.probeValue(it.getCoord(), t)) << "no nearest triangle at an active voxel";
        if (t >= 0 && size_t(t) < triangles.size())
            figures.index_error = std::max(figures.index_error,
                                           std::abs(stored - std::sqrt(CGAL::squared_distance(p, triangles[t]))));
        else
            ADD_FAILURE() << "nearest triangle " << t << " out of range";
    }
    return figures;
}

Mesh read_fitted(const std::string& name, double size) {
    Progress progress;
    Mesh mesh = io::read_mesh(FABVDB_SHARED_DATA "/meshes/" + name, progress);
    const BoundingBox box = bounding_box(mesh);
    const double scale =
        size / std::max({box.max[0] - box.min[0], box.max[1] - box.min[1], box.max[2] - box.min[2]});
    for (Vec3& v : mesh.vertices)
        for (double& x : v) x *= scale;
    return mesh;
}

void expect_accurate(const Mesh& mesh, double voxel, double depth, const std::string& what) {
    Progress progress;
    const SolidDistance solid = solid_distance(mesh, voxel, depth, progress);
    const Figures f = measure(mesh, solid, voxel);
    EXPECT_GT(f.band_voxels, 100u) << what;
    EXPECT_EQ(f.wrong_sign, 0u) << what;
    EXPECT_LT(f.band_error, 1e-4 * voxel) << what;        // exact near the surface (float storage)
    EXPECT_LT(f.too_deep, 1e-4 * voxel) << what;          // a triangle's distance is never below the true one
    EXPECT_LT(f.too_shallow, 0.25 * voxel) << what;       // propagation: measured at most 0.18 voxel
    EXPECT_LT(f.index_error, 1e-4 * voxel) << what;       // the value is the distance to the stored triangle
    EXPECT_GT(f.deepest_reached, depth) << what;
}

TEST(SolidDistance, TorusIsExactNearTheSurfaceAndCloseInside) {
    // A torus: convex and saddle regions, and an inside thinner than the depth.
    expect_accurate(test::make_torus({0, 0, 0}, 20.0, 8.0, 96, 48), 0.75, 5.0, "torus");
}

TEST(SolidDistance, SharedMeshesAreExactNearTheSurfaceAndCloseInside) {
    // Sharp creases and triangles far smaller than a voxel (armadillo), and a
    // thin CAD part (rocker-arm).
    for (const char* name : {"armadillo_86k.obj", "rocker-arm.obj", "kitten.obj"})
        expect_accurate(read_fitted(name, 40.0), 0.5, 2.5, name);
}

TEST(SolidDistance, AVoidKeepsItsOwnSideInside) {
    // A box with an inward-facing box inside: the void between is outside.
    const Mesh hollow_box = test::merged(test::make_box({0, 0, 0}, {30, 30, 30}),
                                         test::flipped(test::make_box({6, 6, 6}, {24, 24, 24})));
    Progress progress;
    const SolidDistance solid = solid_distance(hollow_box, 0.7, 2.0, progress);
    const Figures f = measure(hollow_box, solid, 0.7);
    EXPECT_EQ(f.wrong_sign, 0u);
    EXPECT_LT(f.band_error, 1e-4);
    // The void's centre is far from the band: its inactive value says outside.
    EXPECT_GT(solid.distance->getConstAccessor().getValue(solid.distance->transform().worldToIndexNodeCentered(
                  openvdb::Vec3d(15, 15, 15))),
              0.0f);
    // The wall's middle (3 mm deep) is inside.
    EXPECT_LT(solid.distance->getConstAccessor().getValue(
                  solid.distance->transform().worldToIndexNodeCentered(openvdb::Vec3d(15, 15, 3))),
              0.0f);
}

TEST(SolidDistance, CancelledGivesNoGrid) {
    const Mesh sphere = test::make_sphere({0, 0, 0}, 20, 4);
    std::atomic<bool> cancel{true};
    Progress progress(nullptr, nullptr, &cancel);
    try {
        solid_distance(sphere, 0.5, 3.0, progress);
        ADD_FAILURE() << "not cancelled";
    } catch (const Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_CANCELLED);
    }
}

TEST(SolidDistance, BadParameters) {
    const Mesh sphere = test::make_sphere({0, 0, 0}, 20, 3);
    Progress progress;
    for (const auto& [voxel, depth] : {std::pair{0.0, 1.0}, std::pair{-1.0, 1.0}, std::pair{0.5, -1.0}}) {
        try {
            solid_distance(sphere, voxel, depth, progress);
            ADD_FAILURE() << voxel << " " << depth;
        } catch (const Error& e) {
            EXPECT_EQ(e.status(), FABVDB_ERR_INVALID_ARGUMENT);
        }
    }
}

}  // namespace
}  // namespace fabvdb::volume
