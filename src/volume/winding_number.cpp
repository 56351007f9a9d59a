//! Fast generalized winding number (see winding_number.h).
#include "volume/winding_number.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <tbb/parallel_invoke.h>

#include "core/vec3_ops.h"

namespace fabvdb::volume {

namespace {

constexpr uint32_t leaf_size = 8;
// Triangles longer than this many times the median triangle's longest edge
// (and than the bounding-box diagonal / min_pieces_across) are held as
// pieces, longer ones where more than max_pieces would be made.
constexpr double long_triangle = 2.0;
constexpr double min_pieces_across = 256.0;
// A node's expansion goes into a box's lattice when its centre lies farther
// than this many half-diagonals from the box's centre (triquadratic
// interpolation errs by about 1.5 / reach³ of the node's share there; at 4
// the lattice's finer nodes still err less than the walk: winding_number_test).
constexpr double box_far_reach = 4.0;
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

// Triangle (a, b, c) cut by longest-edge bisection into pieces with no edge
// longer than √piece_squared (same orientation, so their solid angles add up
// to the triangle's): visit(p, q, r) for each piece.
template <class Visit>
void for_each_piece(const Vec3& a, const Vec3& b, const Vec3& c, double piece_squared, Visit&& visit) {
    const Vec3* p[3] = {&a, &b, &c};
    int longest = 0;
    double longest_squared = 0.0;
    for (int e = 0; e < 3; ++e) {
        const Vec3 d = *p[(e + 1) % 3] - *p[e];
        if (dot(d, d) > longest_squared) longest_squared = dot(d, d), longest = e;
    }
    if (longest_squared <= piece_squared) return visit(a, b, c);
    const Vec3 &from = *p[longest], &to = *p[(longest + 1) % 3], &apex = *p[(longest + 2) % 3];
    const Vec3 middle = 0.5 * (from + to);
    for_each_piece(from, middle, apex, piece_squared, visit);
    for_each_piece(middle, to, apex, piece_squared, visit);
}

// The far field of a node at q, times 4π: its moments about its centre
// contracted with the derivatives of the kernel (x − q) / |x − q|³ at the
// centre, r = centre − q (orders 0, 1 and 2 of the Taylor expansion in x).
double far_field(const double* area_normal, const float* m, const float* s, const double* r, double r_squared) {
    const double inverse_3 = 1.0 / (r_squared * std::sqrt(r_squared));
    const double inverse_5 = inverse_3 / r_squared, inverse_7 = inverse_5 / r_squared;
    const double order_0 = (area_normal[0] * r[0] + area_normal[1] * r[1] + area_normal[2] * r[2]) * inverse_3;
    double trace = 0.0, rmr = 0.0;
    for (int i = 0; i < 3; ++i) {
        trace += m[4 * i];
        rmr += r[i] * (m[3 * i] * r[0] + m[3 * i + 1] * r[1] + m[3 * i + 2] * r[2]);
    }
    const double order_1 = trace * inverse_3 - 3.0 * rmr * inverse_5;
    // Per component i of n, S_i = the symmetric matrix xx xy xz yy yz zz:
    // diagonal = Σ_i (S_i r)_i, traces = Σ_i r_i tr S_i, cubic = Σ_i r_i rᵀ S_i r.
    double diagonal = 0.0, traces = 0.0, cubic = 0.0;
    for (int i = 0; i < 3; ++i) {
        const float* q = s + 6 * i;
        const double sr[3] = {q[0] * r[0] + q[1] * r[1] + q[2] * r[2], q[1] * r[0] + q[3] * r[1] + q[4] * r[2],
                              q[2] * r[0] + q[4] * r[1] + q[5] * r[2]};
        diagonal += sr[i];
        traces += r[i] * (q[0] + q[3] + q[5]);
        cubic += r[i] * (r[0] * sr[0] + r[1] * sr[1] + r[2] * sr[2]);
    }
    const double order_2 = 0.5 * (-3.0 * (2.0 * diagonal + traces) * inverse_5 + 15.0 * cubic * inverse_7);
    return order_0 + order_1 + order_2;
}


// Half the cross product of a triangle's edges (9 doubles: its corners).
void area_vector(const double* p, double n[3]) {
    const double u[3] = {p[3] - p[0], p[4] - p[1], p[5] - p[2]};
    const double v[3] = {p[6] - p[0], p[7] - p[1], p[8] - p[2]};
    n[0] = 0.5 * (u[1] * v[2] - u[2] * v[1]);
    n[1] = 0.5 * (u[2] * v[0] - u[0] * v[2]);
    n[2] = 0.5 * (u[0] * v[1] - u[1] * v[0]);
}

// The pairs (j, k) of a symmetric 3 × 3 matrix's entries xx xy xz yy yz zz.
constexpr int moment_pair[6][2] = {{0, 0}, {0, 1}, {0, 2}, {1, 1}, {1, 2}, {2, 2}};

}  // namespace

WindingNumber::WindingNumber(const Mesh& mesh, double accuracy, size_t max_pieces) {
    const auto has_area = [&](const Triangle& t) {
        const Vec3 n = cross(mesh.vertices[t[1]] - mesh.vertices[t[0]], mesh.vertices[t[2]] - mesh.vertices[t[0]]);
        return n[0] != 0.0 || n[1] != 0.0 || n[2] != 0.0;
    };
    std::vector<double> longest_squared;
    longest_squared.reserve(mesh.triangles.size());
    for (const Triangle& t : mesh.triangles) {
        if (!has_area(t)) continue;
        const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
        longest_squared.push_back(std::max({dot(b - a, b - a), dot(c - b, c - b), dot(a - c, a - c)}));
    }
    if (longest_squared.empty()) return;
    std::nth_element(longest_squared.begin(), longest_squared.begin() + longest_squared.size() / 2,
                     longest_squared.end());
    const double median = std::sqrt(longest_squared[longest_squared.size() / 2]);
    const size_t budget = std::max(max_pieces, longest_squared.size());
    double piece = budget > longest_squared.size()
                       ? std::max(long_triangle * median, bounding_box(mesh).diagonal() / min_pieces_across)
                       : HUGE_VAL;
    const auto pieces = [&](double length) {
        size_t count = 0;
        for (const Triangle& t : mesh.triangles)
            if (has_area(t))
                for_each_piece(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]], length * length,
                               [&](const Vec3&, const Vec3&, const Vec3&) { ++count; });
        return count;
    };
    while (piece < HUGE_VAL && pieces(piece) > budget) piece *= 1.25;
    std::vector<double> all_corners;
    all_corners.reserve(std::min(budget, 2 * longest_squared.size()) * 9);
    for (const Triangle& t : mesh.triangles)
        if (has_area(t))
            for_each_piece(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]], piece * piece,
                           [&](const Vec3& a, const Vec3& b, const Vec3& c) {
                               for (const Vec3* corner : {&a, &b, &c})
                                   all_corners.insert(all_corners.end(), corner->begin(), corner->end());
                           });
    const uint32_t count = uint32_t(all_corners.size() / 9);
    std::vector<double> centroids(size_t(count) * 3);
    for (uint32_t i = 0; i < count; ++i)
        for (int k = 0; k < 3; ++k)
            centroids[3 * i + k] = (all_corners[9 * i + k] + all_corners[9 * i + 3 + k] + all_corners[9 * i + 6 + k]) / 3.0;
    std::vector<uint32_t> order(count);
    std::iota(order.begin(), order.end(), 0u);
    corners_.swap(all_corners);
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
        double n[3];
        area_vector(p, n);
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
    Node node{};
    std::copy_n(center, 3, node.center);
    std::copy_n(normal, 3, node.area_normal);
    node.far_squared = accuracy * accuracy * radius_squared;
    if (count <= leaf_size) {
        leaf_moments(first, count, centroids, order, node);
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
    add_child_moments(nodes_[index + 1], node);
    add_child_moments(nodes_[node.first], node);
    nodes_[index] = node;
    return end;
}

void WindingNumber::leaf_moments(uint32_t first, uint32_t count, const std::vector<double>& centroids,
                                 const std::vector<uint32_t>& order, Node& node) const {
    // Σ n ⊗ (c − centre), and Σ n_i × the mean of (x − centre)(x − centre)ᵀ
    // over the triangle, which is (c − centre)(c − centre)ᵀ + Σ over its
    // corners (v − c)(v − c)ᵀ / 12.
    double first_moment[9] = {}, second_moment[18] = {};
    for (uint32_t i = first; i < first + count; ++i) {
        const double* p = &corners_[9 * size_t(order[i])];
        const double* c = &centroids[3 * size_t(order[i])];
        double n[3];
        area_vector(p, n);
        const double d[3] = {c[0] - node.center[0], c[1] - node.center[1], c[2] - node.center[2]};
        double mean[6];
        for (int e = 0; e < 6; ++e) {
            const int j = moment_pair[e][0], k = moment_pair[e][1];
            double spread = 0.0;
            for (int corner = 0; corner < 3; ++corner) spread += (p[3 * corner + j] - c[j]) * (p[3 * corner + k] - c[k]);
            mean[e] = d[j] * d[k] + spread / 12.0;
        }
        for (int a = 0; a < 3; ++a) {
            for (int j = 0; j < 3; ++j) first_moment[3 * a + j] += n[a] * d[j];
            for (int e = 0; e < 6; ++e) second_moment[6 * a + e] += n[a] * mean[e];
        }
    }
    std::copy_n(first_moment, 9, node.first_moment);
    std::copy_n(second_moment, 18, node.second_moment);
}

void WindingNumber::add_child_moments(const Node& child, Node& node) {
    // The child's moments moved from its centre to the node's: with
    // s = child centre − node centre, M += M_c + N_c ⊗ s and
    // Q_ijk += Q_c,ijk + M_c,ij s_k + M_c,ik s_j + N_c,i s_j s_k.
    const double s[3] = {child.center[0] - node.center[0], child.center[1] - node.center[1],
                         child.center[2] - node.center[2]};
    for (int a = 0; a < 3; ++a) {
        const double* n = child.area_normal;
        const float* m = child.first_moment + 3 * a;
        for (int j = 0; j < 3; ++j) node.first_moment[3 * a + j] += float(m[j] + n[a] * s[j]);
        for (int e = 0; e < 6; ++e) {
            const int j = moment_pair[e][0], k = moment_pair[e][1];
            node.second_moment[6 * a + e] +=
                float(child.second_moment[6 * a + e] + m[j] * s[k] + m[k] * s[j] + n[a] * s[j] * s[k]);
        }
    }
}

double WindingNumber::exact(const Vec3& q) const {
    SolidAngleSum sum;
    add_triangles(corners_.data(), 0, uint32_t(corners_.size() / 9), q, sum);
    return sum.fraction();
}

double WindingNumber::walk(const Vec3& q, const uint32_t* roots, size_t count) const {
    double sum = 0.0;
    SolidAngleSum near;
    uint32_t stack[128];
    for (size_t root = 0; root < count; ++root) {
        int top = 0;
        stack[top++] = roots[root];
        while (top > 0) {
            const Node& node = nodes_[stack[--top]];
            const double d[3] = {node.center[0] - q[0], node.center[1] - q[1], node.center[2] - q[2]};
            const double distance_squared = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
            if (distance_squared > node.far_squared) {
                sum += far_field(node.area_normal, node.first_moment, node.second_moment, d, distance_squared);
            } else if (node.count > 0) {
                add_triangles(corners_.data(), node.first, node.count, q, near);
            } else {
                stack[top++] = node.first;
                stack[top++] = uint32_t(&node - nodes_.data()) + 1;
            }
        }
    }
    return sum * inverse_four_pi + near.fraction();
}

double WindingNumber::operator()(const Vec3& q) const {
    if (nodes_.empty()) return 0.0;
    const uint32_t root = 0;
    return walk(q, &root, 1);
}

std::optional<WindingNumber::BoxField> WindingNumber::box_field(const BoundingBox& box) const {
    if (nodes_.empty()) return std::nullopt;
    BoxField field;
    field.lo = box.min;
    for (int k = 0; k < 3; ++k) field.step[k] = box.max[k] > box.min[k] ? 0.5 * (box.max[k] - box.min[k]) : 1.0;
    const Vec3 centre = 0.5 * (box.min + box.max);
    const double reach = box_far_reach * 0.5 * norm(box.max - box.min);
    std::vector<uint32_t> far;
    std::vector<uint32_t> stack{0};
    while (!stack.empty()) {
        const uint32_t index = stack.back();
        stack.pop_back();
        const Node& node = nodes_[index];
        double to_box = 0.0, to_centre = 0.0;
        for (int k = 0; k < 3; ++k) {
            const double outside = std::max({box.min[k] - node.center[k], node.center[k] - box.max[k], 0.0});
            to_box += outside * outside;
            to_centre += (node.center[k] - centre[k]) * (node.center[k] - centre[k]);
        }
        if (to_box > node.far_squared && to_centre > reach * reach) far.push_back(index);
        else if (node.count > 0 || to_box > node.far_squared) field.near.push_back(index);
        else {
            stack.push_back(node.first);
            stack.push_back(index + 1);
        }
    }
    if (field.near.size() > far.size()) return std::nullopt;
    for (int point = 0; point < 27; ++point) {
        const Vec3 q{field.lo[0] + field.step[0] * (point / 9), field.lo[1] + field.step[1] * (point / 3 % 3),
                     field.lo[2] + field.step[2] * (point % 3)};
        double sum = 0.0;
        for (const uint32_t index : far) {
            const Node& node = nodes_[index];
            const double d[3] = {node.center[0] - q[0], node.center[1] - q[1], node.center[2] - q[2]};
            sum += far_field(node.area_normal, node.first_moment, node.second_moment, d,
                             d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        }
        field.lattice[point] = sum * inverse_four_pi;
    }
    return field;
}

double WindingNumber::operator()(const Vec3& q, const BoxField& field) const {
    // Lagrange weights of the lattice's three planes per axis, at u in [0, 2].
    double weight[3][3];
    for (int k = 0; k < 3; ++k) {
        const double u = (q[k] - field.lo[k]) / field.step[k];
        weight[k][0] = 0.5 * (u - 1.0) * (u - 2.0);
        weight[k][1] = -u * (u - 2.0);
        weight[k][2] = 0.5 * u * (u - 1.0);
    }
    double far = 0.0;
    for (int point = 0; point < 27; ++point)
        far += weight[0][point / 9] * weight[1][point / 3 % 3] * weight[2][point % 3] * field.lattice[point];
    return far + walk(q, field.near.data(), field.near.size());
}

}  // namespace fabvdb::volume
