//! MinCut: the two search trees grown from a FIFO ring of active nodes, the
//! augmentation along the path through the arc that joins them, and the
//! adoption of orphans with the distance-and-timestamp heuristic of the
//! paper (a new parent is the one of least distance to the terminal among
//! those whose origin is the terminal).
#include "surface/min_cut.h"

#include <algorithm>

namespace fabvdb::surface {

MinCut::MinCut(std::vector<uint32_t> first_arc, std::vector<uint32_t> head, std::vector<uint32_t> sister)
    : first_arc_(std::move(first_arc)), head_(std::move(head)), sister_(std::move(sister)) {
    const size_t n = node_count(), m = head_.size();
    capacity_.assign(m, 0.0);
    residual_.assign(m, 0.0);
    excess_.assign(n, 0.0);
    tree_.assign(n, no_tree);
    active_.assign(n, 0);
    parent_.assign(n, no_parent);
    stamp_.assign(n, 0);
    distance_.assign(n, 0);
    queue_.assign(n, 0);
    orphans_.reserve(n);
}

void MinCut::activate(uint32_t node) {
    if (active_[node]) return;
    active_[node] = 1;
    queue_[(queue_first_ + queue_size_++) % queue_.size()] = node;
}

uint32_t MinCut::next_active() {
    while (queue_size_ > 0) {
        const uint32_t node = queue_[queue_first_];
        queue_first_ = (queue_first_ + 1) % queue_.size();
        --queue_size_;
        active_[node] = 0;
        if (tree_[node] != no_tree) return node;
    }
    return no_parent;
}

void MinCut::make_orphan(uint32_t node) {
    parent_[node] = no_parent;
    orphans_.push_back(node);
}

void MinCut::solve(const std::vector<double>& terminal, std::vector<char>& source_side) {
    const size_t n = node_count();
    residual_ = capacity_;
    queue_first_ = queue_size_ = 0;
    orphans_.clear();
    clock_ = 0;
    for (size_t i = 0; i < n; ++i) {
        excess_[i] = terminal[i];
        active_[i] = 0;
        stamp_[i] = 0;
        distance_[i] = 1;
        if (terminal[i] != 0) {
            tree_[i] = terminal[i] > 0 ? source_tree : sink_tree;
            parent_[i] = terminal_parent;
            activate(uint32_t(i));
        } else {
            tree_[i] = no_tree;
            parent_[i] = no_parent;
        }
    }
    // `at` is scanned again after each path through it, until it finds none.
    uint32_t at = no_parent;
    for (;;) {
        if (at == no_parent || tree_[at] == no_tree) {
            at = next_active();
            if (at == no_parent) break;
        }
        const bool from_source = tree_[at] == source_tree;
        uint32_t bridge = no_parent, other = no_parent;
        for (uint32_t a = first_arc_[at]; a < first_arc_[at + 1]; ++a) {
            // The arc the tree would grow along: at→q in the source tree, q→at in the sink tree.
            if ((from_source ? residual_[a] : residual_[sister_[a]]) <= 0) continue;
            const uint32_t q = head_[a];
            if (tree_[q] == no_tree) {
                tree_[q] = tree_[at];
                parent_[q] = sister_[a];
                stamp_[q] = stamp_[at];
                distance_[q] = distance_[at] + 1;
                activate(q);
            } else if (tree_[q] != tree_[at]) {
                bridge = a;
                other = q;
                break;
            } else if (stamp_[q] <= stamp_[at] && distance_[q] > distance_[at]) {
                // q is nearer its terminal through at.
                parent_[q] = sister_[a];
                stamp_[q] = stamp_[at];
                distance_[q] = distance_[at] + 1;
            }
        }
        if (bridge == no_parent) {
            at = no_parent;
            continue;
        }
        ++clock_;
        if (from_source)
            augment(at, other, bridge);
        else
            augment(other, at, sister_[bridge]);
        adopt_orphans();
    }
    source_side.resize(n);
    for (size_t i = 0; i < n; ++i) source_side[i] = tree_[i] != sink_tree;
}

void MinCut::augment(uint32_t from, uint32_t to, uint32_t arc) {
    // The bottleneck: the bridge, the source tree's arcs parent→x, the sink
    // tree's arcs x→parent, and the two terminals' excesses.
    double flow = residual_[arc];
    uint32_t x = from;
    for (; parent_[x] != terminal_parent; x = head_[parent_[x]]) flow = std::min(flow, residual_[sister_[parent_[x]]]);
    flow = std::min(flow, excess_[x]);
    for (x = to; parent_[x] != terminal_parent; x = head_[parent_[x]]) flow = std::min(flow, residual_[parent_[x]]);
    flow = std::min(flow, -excess_[x]);
    residual_[arc] -= flow;
    residual_[sister_[arc]] += flow;
    for (x = from;;) {
        const uint32_t up = parent_[x];
        if (up == terminal_parent) break;
        residual_[sister_[up]] -= flow;
        residual_[up] += flow;
        const uint32_t next = head_[up];
        if (residual_[sister_[up]] <= 0) make_orphan(x);
        x = next;
    }
    excess_[x] -= flow;
    if (excess_[x] <= 0) make_orphan(x);
    for (x = to;;) {
        const uint32_t up = parent_[x];
        if (up == terminal_parent) break;
        residual_[up] -= flow;
        residual_[sister_[up]] += flow;
        const uint32_t next = head_[up];
        if (residual_[up] <= 0) make_orphan(x);
        x = next;
    }
    excess_[x] += flow;
    if (excess_[x] >= 0) make_orphan(x);
}

void MinCut::adopt_orphans() {
    constexpr uint32_t unreachable = UINT32_MAX;
    while (!orphans_.empty()) {
        const uint32_t x = orphans_.back();
        orphans_.pop_back();
        const uint8_t side = tree_[x];
        const bool source = side == source_tree;
        uint32_t best_arc = no_parent, best_distance = unreachable;
        for (uint32_t a = first_arc_[x]; a < first_arc_[x + 1]; ++a) {
            const uint32_t q = head_[a];
            // A parent q must be able to pass flow on: q→x in the source tree, x→q in the sink tree.
            if (tree_[q] != side || (source ? residual_[sister_[a]] : residual_[a]) <= 0) continue;
            // Follow q's parents to a node already measured this round, to the terminal or to an orphan.
            uint32_t d = 0, y = q;
            for (;;) {
                if (stamp_[y] == clock_) {
                    d += distance_[y];
                    break;
                }
                const uint32_t up = parent_[y];
                ++d;
                if (up == terminal_parent) {
                    stamp_[y] = clock_;
                    distance_[y] = 1;
                    break;
                }
                if (up == no_parent) {
                    d = unreachable;
                    break;
                }
                y = head_[up];
            }
            if (d == unreachable) continue;
            if (d < best_distance) {
                best_distance = d;
                best_arc = a;
            }
            for (y = q; stamp_[y] != clock_; y = head_[parent_[y]]) {
                stamp_[y] = clock_;
                distance_[y] = d--;
            }
        }
        if (best_arc != no_parent) {
            parent_[x] = best_arc;
            stamp_[x] = clock_;
            distance_[x] = best_distance + 1;
            continue;
        }
        // No parent: x leaves its tree; the neighbours that could grow into
        // it again become active, and its children orphans.
        for (uint32_t a = first_arc_[x]; a < first_arc_[x + 1]; ++a) {
            const uint32_t q = head_[a];
            if (tree_[q] != side) continue;
            if ((source ? residual_[sister_[a]] : residual_[a]) > 0) activate(q);
            const uint32_t up = parent_[q];
            if (up != no_parent && up != terminal_parent && head_[up] == x) make_orphan(q);
        }
        tree_[x] = no_tree;
    }
}

}  // namespace fabvdb::surface
