//! Winding numbers of a band leaf by groups of voxels (see leaf_winding.h).
#include "volume/leaf_winding.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace fabvdb::volume {

namespace {

constexpr int leaf_dim = int(FloatLeaf::DIM);
constexpr int leaf_size = int(FloatLeaf::SIZE);
// The tree's approximation error stays under this (winding_number_test).
constexpr double margin = 0.02;
// A group this large is sampled a second time, at least 4 voxels away.
constexpr int large_group = 32, apart_squared = 16;
// Face and edge neighbours, the half with a later offset.
constexpr int forward[9][3] = {{0, 0, 1}, {0, 1, -1}, {0, 1, 0}, {0, 1, 1}, {1, -1, 0},
                               {1, 0, -1}, {1, 0, 0}, {1, 0, 1}, {1, 1, 0}};

openvdb::Coord position(int offset) { return openvdb::Coord(offset >> 6, (offset >> 3) & 7, offset & 7); }

// The neighbour of `offset` `sign` × forward[s] away in the leaf, or -1.
int neighbour(int offset, int s, int sign) {
    const openvdb::Coord q =
        position(offset).offsetBy(sign * forward[s][0], sign * forward[s][1], sign * forward[s][2]);
    for (int k = 0; k < 3; ++k)
        if (q[k] < 0 || q[k] >= leaf_dim) return -1;
    return (q[0] << 6) | (q[1] << 3) | q[2];
}

double link_length(int s, double voxel) {
    return voxel * std::sqrt(double(forward[s][0] * forward[s][0] + forward[s][1] * forward[s][1] +
                                    forward[s][2] * forward[s][2]));
}

// The leaf's members in groups joined by `linked(a, b, s)`, with the largest
// number of links between a group's sample and any of its voxels.
class Groups {
public:
    template <class Linked>
    Groups(const FloatLeaf::NodeMaskType& members, const Linked& linked) : members_(members) {
        for (auto it = members.beginOn(); it; ++it) parent_[it.pos()] = int16_t(it.pos());
        for (auto it = members.beginOn(); it; ++it)
            for (int s = 0; s < 9; ++s) {
                const int a = int(it.pos()), b = neighbour(a, s, 1);
                if (b < 0 || !members.isOn(b) || !linked(a, b, s)) continue;
                const int ra = root(a), rb = root(b);
                if (ra != rb) parent_[rb] = int16_t(ra);
            }
    }
    int root(int i) {
        while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
        return i;
    }
    // Links from `start` to the farthest voxel of its group, by breadth-first search.
    template <class Linked>
    int depth(int start, const Linked& linked) const {
        int16_t queue[leaf_size], hops[leaf_size];
        bool seen[leaf_size] = {};
        int head = 0, tail = 0, deepest = 0;
        queue[tail++] = int16_t(start);
        hops[start] = 0;
        seen[start] = true;
        while (head < tail) {
            const int a = queue[head++];
            deepest = std::max(deepest, int(hops[a]));
            for (int s = 0; s < 9; ++s)
                for (int sign : {1, -1}) {
                    const int b = neighbour(a, s, sign);
                    if (b < 0 || seen[b] || !members_.isOn(b) || !(sign > 0 ? linked(a, b, s) : linked(b, a, s)))
                        continue;
                    seen[b] = true;
                    hops[b] = int16_t(hops[a] + 1);
                    queue[tail++] = int16_t(b);
                }
        }
        return deepest;
    }

private:
    const FloatLeaf::NodeMaskType& members_;
    int16_t parent_[leaf_size];
};

Vec3 world_position(const openvdb::math::Transform& transform, const openvdb::Coord& ijk) {
    const openvdb::Vec3d p = transform.indexToWorld(ijk);
    return {p[0], p[1], p[2]};
}

// w at a leaf's voxels: the first few from walks of the tree, the rest
// through the field of the leaf's box (winding_number.h), made once a leaf
// needs more evaluations than its lattice costs, where it pays.
class LeafWinding {
public:
    LeafWinding(const WindingNumber& winding, const FloatLeaf& leaf, const openvdb::math::Transform& transform)
        : winding_(winding), leaf_(leaf), transform_(transform) {}
    float operator()(int offset) {
        const Vec3 q = world_position(transform_, leaf_.offsetToGlobalCoord(offset));
        if (++evaluations_ == walks_before_field + 1) {
            const Vec3 lo = world_position(transform_, leaf_.origin());
            const Vec3 hi = world_position(transform_, leaf_.origin().offsetBy(leaf_dim - 1));
            field_ = winding_.box_field({lo, hi});
        }
        return float(field_ ? winding_(q, *field_) : winding_(q));
    }

private:
    static constexpr int walks_before_field = 16;
    const WindingNumber& winding_;
    const FloatLeaf& leaf_;
    const openvdb::math::Transform& transform_;
    int evaluations_ = 0;
    std::optional<WindingNumber::BoxField> field_;
};

// (1/2 - w) / |∇w| at `offset` by central differences (one-sided at the
// leaf's faces), clamped to ±background.
float value_from_winding(const float* w, int offset, double voxel, float background) {
    const int coordinate[3] = {offset >> 6, (offset >> 3) & 7, offset & 7}, stride[3] = {64, 8, 1};
    double gradient_squared = 0.0;
    for (int axis = 0; axis < 3; ++axis) {
        const int lo = coordinate[axis] > 0 ? -1 : 0, hi = coordinate[axis] < leaf_dim - 1 ? 1 : 0;
        const double g = (w[offset + hi * stride[axis]] - w[offset + lo * stride[axis]]) / ((hi - lo) * voxel);
        gradient_squared += g * g;
    }
    const double value = (inside_winding - w[offset]) / std::max(std::sqrt(gradient_squared), 1e-12);
    return float(std::clamp(value, -double(background), double(background)));
}

}  // namespace

bool band_leaf_winding(const FloatLeaf& leaf, const WindingNumber& winding, const openvdb::math::Transform& transform,
                       double gradient_bound, float* w) {
    const double voxel = transform.voxelSize()[0];
    const float* values = leaf.buffer().data();
    double lengths[9];
    for (int s = 0; s < 9; ++s) lengths[s] = link_length(s, voxel) * (1.0 + 1e-3);
    const auto linked = [&](int a, int b, int s) { return double(values[a]) + double(values[b]) > lengths[s]; };
    const auto& active = leaf.getValueMask();
    Groups groups(active, linked);

    // Per group root: its voxel farthest from the surface, where the tree is
    // most accurate, and for a large group the farthest of those 4 voxels away.
    int16_t farthest[leaf_size], second[leaf_size], size[leaf_size] = {};
    for (auto it = active.beginOn(); it; ++it) {
        const int r = groups.root(int(it.pos()));
        if (size[r]++ == 0 || values[it.pos()] > values[farthest[r]]) farthest[r] = int16_t(it.pos());
        second[r] = -1;
    }
    for (auto it = active.beginOn(); it; ++it) {
        const int r = groups.root(int(it.pos()));
        if (size[r] < large_group) continue;
        const openvdb::Coord d = position(int(it.pos())) - position(farthest[r]);
        if (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] < apart_squared) continue;
        if (second[r] < 0 || values[it.pos()] > values[second[r]]) second[r] = int16_t(it.pos());
    }
    LeafWinding evaluate(winding, leaf, transform);
    float group_w[leaf_size];
    bool per_voxel[leaf_size];
    bool exact = true;
    for (auto it = active.beginOn(); it; ++it) {
        const int offset = int(it.pos());
        if (groups.root(offset) != offset) continue;
        group_w[offset] = evaluate(farthest[offset]);
        per_voxel[offset] = false;
        if (size[offset] == 1) continue;
        const double reach = gradient_bound > 0.0
                                 ? gradient_bound * std::sqrt(2.0) * voxel * groups.depth(farthest[offset], linked)
                                 : 0.0;
        const bool inside = group_w[offset] >= inside_winding;
        per_voxel[offset] = std::abs(group_w[offset] - inside_winding) <= margin + reach ||
                            (second[offset] >= 0 && (evaluate(second[offset]) >= inside_winding) != inside);
        exact = exact && per_voxel[offset];
    }
    for (auto it = active.beginOn(); it; ++it) {
        const int r = groups.root(int(it.pos()));
        w[it.pos()] = per_voxel[r] && int(it.pos()) != farthest[r] ? evaluate(int(it.pos())) : group_w[r];
    }
    return exact;
}

void off_band_leaf_values(FloatLeaf& leaf, const WindingNumber& winding, const openvdb::math::Transform& transform,
                          double gradient_bound, float background, bool band_exact, float* w) {
    const double voxel = transform.voxelSize()[0];
    FloatLeaf::NodeMaskType off_band = leaf.getValueMask();
    off_band.toggle();
    if (off_band.isOff()) return;
    const auto linked = [](int, int, int) { return true; };
    Groups groups(off_band, linked);
    LeafWinding evaluate(winding, leaf, transform);
    // A central difference of w is at most the bound per axis, so a voxel
    // whose w lies farther than sqrt(3) × bound × background from 1/2 is
    // clamped.
    const double clamped_beyond = std::sqrt(3.0) * gradient_bound * double(background);
    bool all_clamped = true;
    float group_w[leaf_size];
    for (auto it = off_band.beginOn(); it && all_clamped; ++it) {
        const int offset = int(it.pos());
        if (groups.root(offset) != offset) continue;
        group_w[offset] = evaluate(offset);
        const double reach =
            gradient_bound > 0.0 ? gradient_bound * std::sqrt(2.0) * voxel * groups.depth(offset, linked) : 0.0;
        all_clamped = std::abs(group_w[offset] - inside_winding) > margin + reach + clamped_beyond;
    }
    if (all_clamped) {
        for (auto it = off_band.beginOn(); it; ++it)
            leaf.setValueOn(it.pos(), group_w[groups.root(int(it.pos()))] < inside_winding ? background : -background);
        return;
    }
    for (int offset = 0; offset < leaf_size; ++offset)
        if (off_band.isOn(offset) || !band_exact) w[offset] = evaluate(offset);
    for (auto it = off_band.beginOn(); it; ++it)
        leaf.setValueOn(it.pos(), value_from_winding(w, int(it.pos()), voxel, background));
}

}  // namespace fabvdb::volume
