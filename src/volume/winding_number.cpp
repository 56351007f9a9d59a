//! Fast generalized winding number (see winding_number.h).
#include "volume/winding_number.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <tbb/parallel_invoke.h>

namespace fabvdb::volume {

namespace {

constexpr uint32_t leaf_size = 8;
// Subtrees over more triangles than this are built in parallel tasks: one
// over 16k triangles takes about a millisecond, well above a task's overhead.
constexpr uint32_t parallel_grain = 1u << 14;
constexpr double inverse_four_pi = 0.25 / M_PI;

// Solid angles of triangles seen from the origin (Van Oosterom & Strackee
// 1983): half of triangle (a, b, c)'s is the argument of the complex number
// denominator + i·det below, positive when the triangle winds
// counter-clockwise seen from the origin's far side. From a point in the
// triangle's plane it is 0 (on the triangle itself ±1/2 would be as right).
// Their sum is the argument of the numbers' product plus 2π per turn the
// product's argument wraps, so one atan2 serves a whole run of triangles.
class SolidAngleSum {
public:
    void add(const double* a, const double* b, const double* c) {
        const double det = a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                           a[2] * (b[0] * c[1] - b[1] * c[0]);
        if (det == 0.0) return;
        const double la = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
        const double lb = std::sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
        const double lc = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
        const double ab = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        const double bc = b[0] * c[0] + b[1] * c[1] + b[2] * c[2];
        const double ca = c[0] * a[0] + c[1] * a[1] + c[2] * a[2];
        const double u = la * lb * lc + ab * lc + bc * la + ca * lb, v = det;
        const double x = re_ * u - im_ * v;
        const double y = re_ * v + im_ * u + 0.0;  // + 0.0: no −0, whose atan2 would read −π
        const double m = std::max(std::abs(x), std::abs(y));
        if (!(m > 0)) return;  // underflow: q on a corner, where the angle means nothing
        // Both arguments in (0, π] and the product's not: their sum passed π.
        // Both in (−π, 0) and the product's in (0, π]: it passed −π.
        const bool upper = upper_half(re_, im_), factor_upper = upper_half(u, v), product_upper = upper_half(x, y);
        if (upper && factor_upper && !product_upper) ++turns_;
        if (im_ < 0 && v < 0 && product_upper) --turns_;
        if (m > 1e100 || m < 1e-100) {
            re_ = x / m;
            im_ = y / m;
        } else {
            re_ = x;
            im_ = y;
        }
    }
    //! The sum of the solid angles added, over 4π.
    double fraction() const { return (std::atan2(im_, re_) + 2.0 * M_PI * turns_) * 2.0 * inverse_four_pi; }

private:
    // Argument in (0, π].
    static bool upper_half(double re, double im) { return im > 0 || (im == 0 && re < 0); }
    double re_ = 1.0, im_ = 0.0;
    long turns_ = 0;
};

// Adds triangles first .. first + count − 1 of `corners` (9 doubles each)
// as seen from q.
void add_triangles(const double* corners, uint32_t first, uint32_t count, const Vec3& q, SolidAngleSum& sum) {
    for (uint32_t i = first; i < first + count; ++i) {
        const double* p = corners + 9 * size_t(i);
        const double a[3] = {p[0] - q[0], p[1] - q[1], p[2] - q[2]};
        const double b[3] = {p[3] - q[0], p[4] - q[1], p[5] - q[2]};
        const double c[3] = {p[6] - q[0], p[7] - q[1], p[8] - q[2]};
        sum.add(a, b, c);
    }
}

// Nodes of the tree over `count` triangles: halving makes its shape depend on
// the count alone.
uint32_t subtree_nodes(uint32_t count) {
    return count <= leaf_size ? 1 : 1 + subtree_nodes(count / 2) + subtree_nodes(count - count / 2);
}

}  // namespace

WindingNumber::WindingNumber(const Mesh& mesh, double accuracy) {
    std::vector<uint32_t> kept;
    kept.reserve(mesh.triangles.size());
    std::vector<double> all_corners;
    all_corners.reserve(mesh.triangles.size() * 9);
    for (const Triangle& t : mesh.triangles) {
        const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
        const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        if (n[0] == 0.0 && n[1] == 0.0 && n[2] == 0.0) continue;
        kept.push_back(uint32_t(all_corners.size() / 9));
        for (const Vec3* p : {&a, &b, &c}) all_corners.insert(all_corners.end(), p->begin(), p->end());
    }
    const uint32_t count = uint32_t(kept.size());
    std::vector<double> centroids(size_t(count) * 3);
    for (uint32_t i = 0; i < count; ++i)
        for (int k = 0; k < 3; ++k)
            centroids[3 * i + k] = (all_corners[9 * i + k] + all_corners[9 * i + 3 + k] + all_corners[9 * i + 6 + k]) / 3.0;
    std::vector<uint32_t> order(count);
    std::iota(order.begin(), order.end(), 0u);
    corners_.swap(all_corners);
    if (count == 0) return;
    nodes_.resize(subtree_nodes(count));
    build(0, count, 0, centroids, order, accuracy);
    std::vector<double> sorted(corners_.size());
    for (uint32_t i = 0; i < count; ++i)
        std::copy_n(corners_.begin() + 9 * size_t(order[i]), 9, sorted.begin() + 9 * size_t(i));
    corners_.swap(sorted);
}

uint32_t WindingNumber::build(uint32_t first, uint32_t count, uint32_t index, const std::vector<double>& centroids,
                              std::vector<uint32_t>& order, double accuracy) {
    double area_sum = 0.0, center[3] = {0, 0, 0}, normal[3] = {0, 0, 0};
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (uint32_t i = first; i < first + count; ++i) {
        const double* p = &corners_[9 * size_t(order[i])];
        const double u[3] = {p[3] - p[0], p[4] - p[1], p[5] - p[2]};
        const double v[3] = {p[6] - p[0], p[7] - p[1], p[8] - p[2]};
        const double n[3] = {0.5 * (u[1] * v[2] - u[2] * v[1]), 0.5 * (u[2] * v[0] - u[0] * v[2]),
                             0.5 * (u[0] * v[1] - u[1] * v[0])};
        const double area = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        area_sum += area;
        for (int k = 0; k < 3; ++k) {
            normal[k] += n[k];
            center[k] += area * centroids[3 * size_t(order[i]) + k];
            lo[k] = std::min(lo[k], centroids[3 * size_t(order[i]) + k]);
            hi[k] = std::max(hi[k], centroids[3 * size_t(order[i]) + k]);
        }
    }
    for (int k = 0; k < 3; ++k) center[k] /= area_sum;
    double radius_squared = 0.0;
    for (uint32_t i = first; i < first + count; ++i) {
        const double* p = &corners_[9 * size_t(order[i])];
        for (int corner = 0; corner < 3; ++corner) {
            const double dx = p[3 * corner] - center[0], dy = p[3 * corner + 1] - center[1],
                         dz = p[3 * corner + 2] - center[2];
            radius_squared = std::max(radius_squared, dx * dx + dy * dy + dz * dz);
        }
    }
    Node node;
    std::copy_n(center, 3, node.center);
    std::copy_n(normal, 3, node.area_normal);
    node.far_squared = accuracy * accuracy * radius_squared;
    if (count <= leaf_size) {
        node.first = first;
        node.count = count;
        nodes_[index] = node;
        return index + 1;
    }
    int axis = 0;
    for (int k = 1; k < 3; ++k)
        if (hi[k] - lo[k] > hi[axis] - lo[axis]) axis = k;
    const uint32_t half = count / 2;
    std::nth_element(order.begin() + first, order.begin() + first + half, order.begin() + first + count,
                     [&](uint32_t a, uint32_t b) { return centroids[3 * size_t(a) + axis] < centroids[3 * size_t(b) + axis]; });
    node.count = 0;
    // The left child is always index + 1, the right one follows the left subtree.
    uint32_t end = 0;
    if (count > parallel_grain) {
        node.first = index + 1 + subtree_nodes(half);
        tbb::parallel_invoke([&] { build(first, half, index + 1, centroids, order, accuracy); },
                             [&] { end = build(first + half, count - half, node.first, centroids, order, accuracy); });
    } else {
        node.first = build(first, half, index + 1, centroids, order, accuracy);
        end = build(first + half, count - half, node.first, centroids, order, accuracy);
    }
    nodes_[index] = node;
    return end;
}

double WindingNumber::exact(const Vec3& q) const {
    SolidAngleSum sum;
    add_triangles(corners_.data(), 0, uint32_t(corners_.size() / 9), q, sum);
    return sum.fraction();
}

double WindingNumber::operator()(const Vec3& q) const {
    if (nodes_.empty()) return 0.0;
    double sum = 0.0;
    SolidAngleSum near;
    uint32_t stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& node = nodes_[stack[--top]];
        const double d[3] = {node.center[0] - q[0], node.center[1] - q[1], node.center[2] - q[2]};
        const double distance_squared = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        if (distance_squared > node.far_squared) {
            const double dot = node.area_normal[0] * d[0] + node.area_normal[1] * d[1] + node.area_normal[2] * d[2];
            sum += dot * inverse_four_pi / (distance_squared * std::sqrt(distance_squared));
        } else if (node.count > 0) {
            add_triangles(corners_.data(), node.first, node.count, q, near);
        } else {
            stack[top++] = node.first;
            stack[top++] = uint32_t(&node - nodes_.data()) + 1;
        }
    }
    return sum + near.fraction();
}

}  // namespace fabvdb::volume
