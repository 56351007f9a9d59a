//! Bound on the winding number's gradient from the boundary edges (see winding_gradient_bound.h).
#include "volume/winding_gradient_bound.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/vec3_ops.h"

namespace fabvdb::volume {

namespace {

constexpr uint32_t edges_per_leaf = 8;
constexpr double inverse_four_pi = 0.25 / M_PI;

double squared_distance(const BoundingBox& a, const BoundingBox& b) {
    double sum = 0.0;
    for (int k = 0; k < 3; ++k) {
        const double gap = std::max({a.min[k] - b.max[k], b.min[k] - a.max[k], 0.0});
        sum += gap * gap;
    }
    return sum;
}

BoundingBox segment_box(const Vec3& a, const Vec3& b) {
    BoundingBox box;
    for (int k = 0; k < 3; ++k) {
        box.min[k] = std::min(a[k], b[k]);
        box.max[k] = std::max(a[k], b[k]);
    }
    return box;
}

}  // namespace

WindingGradientBound::WindingGradientBound(const Mesh& welded, const EdgeTable& edges) {
    std::vector<char> has_area(welded.triangles.size());
    for (size_t t = 0; t < welded.triangles.size(); ++t) {
        const Triangle& tri = welded.triangles[t];
        const Vec3 &a = welded.vertices[tri[0]], &b = welded.vertices[tri[1]], &c = welded.vertices[tri[2]];
        const Vec3 n = cross(b - a, c - a);
        has_area[t] = n[0] != 0.0 || n[1] != 0.0 || n[2] != 0.0;
    }
    // Position ids order as positions do: the edges come in the order of
    // their (lower, higher) end points.
    for (size_t e = 0; e < edges.edge_count(); ++e) {
        int uses = 0;
        for (size_t u = edges.begin[e]; u < edges.begin[e + 1]; ++u)
            if (has_area[edges.uses[u].triangle]) uses += edges.uses[u].forward ? 1 : -1;
        if (uses != 0) {
            const EdgeUse& use = edges.uses[edges.begin[e]];
            const Vec3 &a = welded.vertices[use.lo], &b = welded.vertices[use.hi];
            edges_.push_back({a, b, std::abs(uses) * norm(b - a)});
        }
    }
    if (!edges_.empty()) {
        nodes_.reserve(2 * edges_.size() / edges_per_leaf + 2);
        build(0, uint32_t(edges_.size()));
    }
}

uint32_t WindingGradientBound::build(uint32_t first, uint32_t count) {
    const uint32_t index = uint32_t(nodes_.size());
    nodes_.push_back(Node{});
    Node node{segment_box(edges_[first].a, edges_[first].b), 0.0, first, count};
    for (uint32_t i = first; i < first + count; ++i) {
        node.box.add(edges_[i].a);
        node.box.add(edges_[i].b);
        node.weight += edges_[i].weight;
    }
    if (count <= edges_per_leaf) {
        nodes_[index] = node;
        return index;
    }
    int axis = 0;
    for (int k = 1; k < 3; ++k)
        if (node.box.max[k] - node.box.min[k] > node.box.max[axis] - node.box.min[axis]) axis = k;
    const uint32_t half = count / 2;
    std::nth_element(edges_.begin() + first, edges_.begin() + first + half, edges_.begin() + first + count,
                     [axis](const Edge& x, const Edge& y) { return x.a[axis] + x.b[axis] < y.a[axis] + y.b[axis]; });
    node.count = 0;
    nodes_[index] = node;
    build(first, half);  // the left child is always index + 1
    nodes_[index].first = build(first + half, count - half);
    return index;
}

double WindingGradientBound::operator()(const BoundingBox& box, double cap) const {
    if (nodes_.empty()) return 0.0;
    double sum = 0.0;
    uint32_t stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0 && sum < cap) {
        const Node& node = nodes_[stack[--top]];
        const double node_distance_squared = squared_distance(node.box, box);
        // A node whose box is at least its own diagonal away is bounded as a
        // whole: every edge in it is at least that far from the query box.
        const Vec3 extent = node.box.max - node.box.min;
        if (node_distance_squared > 0.0 && node_distance_squared >= dot(extent, extent)) {
            sum += node.weight * inverse_four_pi / node_distance_squared;
        } else if (node.count > 0) {
            for (uint32_t i = node.first; i < node.first + node.count; ++i) {
                const double d2 = squared_distance(segment_box(edges_[i].a, edges_[i].b), box);
                if (d2 == 0.0) return std::numeric_limits<double>::infinity();
                sum += edges_[i].weight * inverse_four_pi / d2;
            }
        } else {
            stack[top++] = node.first;
            stack[top++] = uint32_t(&node - nodes_.data()) + 1;
        }
    }
    return sum;
}

}  // namespace fabvdb::volume
