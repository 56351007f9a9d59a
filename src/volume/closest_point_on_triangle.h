//! The point of a triangle closest to a given point, and the feature it lies
//! on (a corner, an edge or the face's interior), found by the Voronoi region
//! of the point (barycentric dot products, no square roots). Exact up to
//! double rounding; a degenerate triangle gives one of its closest points.
#pragma once

#include <openvdb/openvdb.h>

namespace fabvdb::volume {

//! Corners 0, 1, 2; edges 01, 12, 20; the face.
enum class TriangleFeature { corner0, corner1, corner2, edge01, edge12, edge20, face };

struct TrianglePoint {
    openvdb::Vec3d point;
    TriangleFeature feature;
};

TrianglePoint closest_point_on_triangle(const openvdb::Vec3d& p, const openvdb::Vec3d& a, const openvdb::Vec3d& b,
                                        const openvdb::Vec3d& c);

}  // namespace fabvdb::volume
