//! Whether two triangles cross (see triangles_cross.h).
//!
//! Floating-point filters (certain_sign.h) in front of CGAL's exact
//! predicates settle most pairs: a pair certainly on two sides of a plane of
//! one triangle, or of a plane through an edge of one along its normal, is
//! apart; an edge certainly beside the other triangle misses it.
#include "volume/triangles_cross.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include "core/vec3_ops.h"
#include "volume/certain_sign.h"

namespace fabvdb::volume {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;

// The plane through three points, for the side of points.
class TrianglePlane {
public:
    TrianglePlane(const std::vector<Vec3>& v, const Triangle& t) : TrianglePlane(v[t[0]], v[t[1]], v[t[2]]) {}
    TrianglePlane(const Vec3& a, const Vec3& b, const Vec3& c) : origin_(a) {
        const Vec3 ab = b - origin_, ac = c - origin_;
        normal_ = cross(ab, ac);
        scale_squared_ = dot(ab, ab) * dot(ac, ac);
    }
    int certain_side(const Vec3& p) const {
        const Vec3 d = p - origin_;
        return certain_sign(dot(normal_, d), scale_squared_ * dot(d, d));
    }
    // Whether the points lie certainly strictly on one side.
    template <class... Points>
    bool certainly_one_side(const Vec3& first, const Points&... others) const {
        const int side = certain_side(first);
        return side != 0 && ((certain_side(others) == side) && ...);
    }

private:
    Vec3 origin_;
    Vec3 normal_;
    double scale_squared_;
};

// Whether a plane through an edge of triangle a and along its normal
// certainly has a's third corner strictly on one side and all of b strictly
// on the other. The plane passes through the edge's ends and a third point
// off them (the edge's start moved along the computed normal), so the edge
// lies on it exactly whatever the rounding of that point. Separates
// coplanar triangles, which the planes of the triangles themselves cannot.
bool edge_plane_separates(const std::vector<Vec3>& v, const Triangle& a, const Triangle& b) {
    const Vec3 normal = cross(v[a[1]] - v[a[0]], v[a[2]] - v[a[0]]);
    for (int k = 0; k < 3; ++k) {
        const Vec3& start = v[a[k]];
        const Vec3 above = start + normal;
        const TrianglePlane plane(start, v[a[(k + 1) % 3]], above);
        const int third = plane.certain_side(v[a[(k + 2) % 3]]);
        if (third != 0 && plane.certainly_one_side(v[b[0]], v[b[1]], v[b[2]]) && plane.certain_side(v[b[0]]) == -third)
            return true;
    }
    return false;
}

// Whether segment pq certainly misses the triangle (v, a, b): both its ends
// lie strictly on one side of the triangle's plane or, seen along its normal,
// strictly beyond the line through v and a or the one through v and b.
bool segment_certainly_misses(const Vec3& v, const Vec3& a, const Vec3& b, const Vec3& p, const Vec3& q) {
    const Vec3 va = a - v, vb = b - v, vp = p - v, vq = q - v;
    const double la = dot(va, va), lb = dot(vb, vb), lp = dot(vp, vp), lq = dot(vq, vq);
    const Vec3 normal = cross(va, vb);
    const int side_p = certain_sign(dot(normal, vp), la * lb * lp);
    if (side_p != 0 && certain_sign(dot(normal, vq), la * lb * lq) == side_p) return true;
    const Vec3 toward_b = cross(normal, va), toward_a = cross(vb, normal);
    return (certain_sign(dot(toward_b, vp), la * la * lb * lp) < 0 &&
            certain_sign(dot(toward_b, vq), la * la * lb * lq) < 0) ||
           (certain_sign(dot(toward_a, vp), lb * lb * la * lp) < 0 &&
            certain_sign(dot(toward_a, vq), lb * lb * la * lq) < 0);
}

}  // namespace

bool triangles_cross(const Mesh& mesh, const std::vector<char>& embedded, const Triangle& a, const Triangle& b) {
    const auto& v = mesh.vertices;
    const auto point = [&](uint32_t i) { return Point(v[i][0], v[i][1], v[i][2]); };
    int shared = 0, a_shared[3] = {}, b_shared[3] = {};
    bool at_embedded_fan = false;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (a[i] == b[j]) {
                ++shared;
                a_shared[i] = b_shared[j] = 1;
                at_embedded_fan = at_embedded_fan || embedded[a[i]];
            }
    if (shared >= 3) return true;
    if (at_embedded_fan) return false;
    if (shared == 2) {
        int i = 0, j = 0;
        while (a_shared[i]) ++i;
        while (b_shared[j]) ++j;
        const uint32_t u = a[(i + 1) % 3], w = a[(i + 2) % 3], p = a[i], q = b[j];
        // Run along the shared edge in opposite directions with normals that
        // agree: either not coplanar or on opposite sides, so not crossing.
        if (b[(j + 1) % 3] == w) {
            const Vec3 edge = v[w] - v[u], to_p = v[p] - v[u], to_q = v[q] - v[u];
            const double agreement = dot(cross(edge, to_p), cross(to_q, edge));
            const double edge_squared = dot(edge, edge);
            if (certain_sign(agreement, edge_squared * edge_squared * dot(to_p, to_p) * dot(to_q, to_q)) > 0)
                return false;
        }
        const Point pu = point(u), pw = point(w), pp = point(p), pq = point(q);
        return CGAL::coplanar(pu, pw, pp, pq) && CGAL::coplanar_orientation(pu, pw, pp, pq) == CGAL::POSITIVE;
    }
    const Kernel::Triangle_3 ta(point(a[0]), point(a[1]), point(a[2])), tb(point(b[0]), point(b[1]), point(b[2]));
    if (shared == 0) {
        if (TrianglePlane(v, a).certainly_one_side(v[b[0]], v[b[1]], v[b[2]]) ||
            TrianglePlane(v, b).certainly_one_side(v[a[0]], v[a[1]], v[a[2]]) || edge_plane_separates(v, a, b) ||
            edge_plane_separates(v, b, a))
            return false;
        return CGAL::do_intersect(ta, tb);
    }
    int i = 0, j = 0;
    while (!a_shared[i]) ++i;
    while (!b_shared[j]) ++j;
    const uint32_t a1 = a[(i + 1) % 3], a2 = a[(i + 2) % 3], b1 = b[(j + 1) % 3], b2 = b[(j + 2) % 3];
    const Vec3& corner = v[a[i]];
    const bool b_edge_misses = segment_certainly_misses(corner, v[a1], v[a2], v[b1], v[b2]);
    const bool a_edge_misses = segment_certainly_misses(corner, v[b1], v[b2], v[a1], v[a2]);
    return (!b_edge_misses && CGAL::do_intersect(ta, Kernel::Segment_3(point(b1), point(b2)))) ||
           (!a_edge_misses && CGAL::do_intersect(tb, Kernel::Segment_3(point(a1), point(a2))));
}

}  // namespace fabvdb::volume
