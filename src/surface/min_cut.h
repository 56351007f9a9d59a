//! min_cut: a minimum s–t cut of a graph of nodes joined by arcs in
//! compressed rows, each node also tied to the source (positive terminal
//! capacity) or to the sink (negative), by the Boykov–Kolmogorov algorithm
//! (PAMI 26(9), 2004: augmenting paths found by growing a search tree from
//! each terminal, the trees kept and repaired after each augmentation).
//! Takes the arcs once (each arc's reverse, its sister, given) and their
//! capacities, which may change between solves; each solve takes the terminal
//! capacities. Guarantees: the sink side is the set of nodes that can still
//! reach the sink in the residual graph, the same set for every maximum flow,
//! so the labels do not depend on the order in which paths are found (the
//! same labels as Boost's boykov_kolmogorov_max_flow, whose sink tree it is).
//! Costs: memory linear in nodes and arcs, reused over solves (a solve
//! allocates only the labels it returns). Written for the parting lines'
//! networks (a node per part-surface triangle, three arcs each), on which
//! the studio's cut edits take about half the time they took with Boost's
//! generic implementation.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace fabvdb::surface {

class MinCut {
public:
    //! The arcs of node i are first_arc[i] .. first_arc[i + 1] (first_arc has
    //! one entry more than there are nodes), arc a goes to head[a], and
    //! sister[a] is the arc back (sister[sister[a]] == a). Capacities start at 0.
    MinCut(std::vector<uint32_t> first_arc, std::vector<uint32_t> head, std::vector<uint32_t> sister);

    size_t node_count() const { return first_arc_.size() - 1; }

    //! Sets the capacity of arc a and of its sister (an undirected edge), ≥ 0.
    void set_edge_capacity(uint32_t a, double capacity) { capacity_[a] = capacity_[sister_[a]] = capacity; }

    //! A maximum flow for the terminal capacities terminal[i] (> 0: from the
    //! source, < 0: to the sink, 0: none); source_side[i] = 1 unless node i
    //! lies on the sink side of the minimum cut. source_side is resized.
    void solve(const std::vector<double>& terminal, std::vector<char>& source_side);

private:
    enum Tree : uint8_t { no_tree, source_tree, sink_tree };
    static constexpr uint32_t no_parent = UINT32_MAX;        //!< free node or orphan
    static constexpr uint32_t terminal_parent = UINT32_MAX - 1;  //!< tied to its tree's terminal

    void activate(uint32_t node);
    uint32_t next_active();
    void make_orphan(uint32_t node);
    void augment(uint32_t from, uint32_t to, uint32_t arc);
    void adopt_orphans();

    const std::vector<uint32_t> first_arc_, head_, sister_;
    std::vector<double> capacity_, residual_;  //!< per arc
    std::vector<double> excess_;               //!< per node: what is left of its terminal capacity
    std::vector<uint8_t> tree_, active_;
    std::vector<uint32_t> parent_;             //!< per node: the arc to its parent in its tree
    std::vector<uint32_t> stamp_, distance_;   //!< the distance heuristic of the adoption
    std::vector<uint32_t> queue_, orphans_;    //!< active nodes (a ring), orphans (a stack)
    size_t queue_first_ = 0, queue_size_ = 0;
    uint32_t clock_ = 0;
};

}  // namespace fabvdb::surface
