//! Closest point on a triangle (see closest_point_on_triangle.h).
#include "volume/closest_point_on_triangle.h"

namespace fabvdb::volume {

TrianglePoint closest_point_on_triangle(const openvdb::Vec3d& p, const openvdb::Vec3d& a, const openvdb::Vec3d& b,
                                        const openvdb::Vec3d& c) {
    const openvdb::Vec3d ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0 && d2 <= 0) return {a, TriangleFeature::corner0};
    const openvdb::Vec3d bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0 && d4 <= d3) return {b, TriangleFeature::corner1};
    const double vc = d1 * d4 - d3 * d2;
    // Each edge's case needs the edge to have a length (d1 − d3 = |ab|²,
    // d2 − d6 = |ac|², (d4 − d3) + (d5 − d6) = |bc|²): a degenerate
    // triangle's zero-length edge falls through to its other edges.
    if (vc <= 0 && d1 >= 0 && d3 <= 0 && d1 - d3 > 0) return {a + ab * (d1 / (d1 - d3)), TriangleFeature::edge01};
    const openvdb::Vec3d cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0 && d5 <= d6) return {c, TriangleFeature::corner2};
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0 && d2 - d6 > 0) return {a + ac * (d2 / (d2 - d6)), TriangleFeature::edge20};
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0 && (d4 - d3) + (d5 - d6) > 0)
        return {b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))), TriangleFeature::edge12};
    const double denominator = 1.0 / (va + vb + vc);
    return {a + ab * (vb * denominator) + ac * (vc * denominator), TriangleFeature::face};
}

}  // namespace fabvdb::volume
