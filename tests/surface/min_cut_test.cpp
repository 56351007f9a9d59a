//! min_cut: on small random graphs with small whole capacities (many tied
//! minimum cuts), the source side is the union of the source sides of all
//! minimum cuts, found by trying every labelling; on larger random meshes of
//! nodes, with whole and with real capacities, the labels are those of
//! Boost's boykov_kolmogorov_max_flow (its sink tree), and solving again
//! after capacities change gives what a fresh network gives.
#include <gtest/gtest.h>

#include <random>

// Boost.Graph's edge iterators trip GCC's -Wmaybe-uninitialized (false positive).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <boost/graph/boykov_kolmogorov_max_flow.hpp>
#include <boost/graph/compressed_sparse_row_graph.hpp>
#pragma GCC diagnostic pop

#include "surface/min_cut.h"

namespace {

//! An undirected graph: edges (a, b, capacity) and per-node terminal capacities.
struct Problem {
    size_t nodes = 0;
    std::vector<std::tuple<uint32_t, uint32_t, double>> edges;
    std::vector<double> terminal;
};

//! A random graph: each node joined to `degree` random others, capacities
//! drawn whole from 0..3 or real from [0, 1); terminals likewise, signed.
Problem random_problem(std::mt19937& random, size_t nodes, int degree, bool whole) {
    Problem p;
    p.nodes = nodes;
    std::uniform_int_distribution<uint32_t> node(0, uint32_t(nodes - 1));
    std::uniform_int_distribution<int> small(0, 3), sign(-4, 4);
    std::uniform_real_distribution<double> real(0.0, 1.0);
    for (uint32_t a = 0; a < nodes; ++a)
        for (int k = 0; k < degree; ++k) {
            const uint32_t b = node(random);
            if (b != a) p.edges.emplace_back(a, b, whole ? small(random) : real(random));
        }
    for (size_t i = 0; i < nodes; ++i) {
        const int s = sign(random);
        p.terminal.push_back(s == 0 ? 0.0 : whole ? double(s) : (s > 0 ? 1 : -1) * 2.0 * real(random));
    }
    return p;
}

//! A MinCut of p's arcs in compressed rows (each edge's two arcs sisters)
//! with the edges' capacities, and the first arc of each edge.
struct Network {
    fabvdb::surface::MinCut cut;
    std::vector<uint32_t> arc_of_edge;
};

Network make_network(const Problem& p) {
    std::vector<uint32_t> first(p.nodes + 1, 0);
    for (const auto& [a, b, c] : p.edges) ++first[a + 1], ++first[b + 1];
    for (size_t i = 0; i < p.nodes; ++i) first[i + 1] += first[i];
    std::vector<uint32_t> head(first.back()), sister(first.back()), next(first.begin(), first.end() - 1);
    std::vector<uint32_t> arc_of_edge;
    for (const auto& [a, b, c] : p.edges) {
        const uint32_t ab = next[a]++, ba = next[b]++;
        head[ab] = b;
        head[ba] = a;
        sister[ab] = ba;
        sister[ba] = ab;
        arc_of_edge.push_back(ab);
    }
    Network network{fabvdb::surface::MinCut(first, head, sister), arc_of_edge};
    for (size_t e = 0; e < p.edges.size(); ++e)
        network.cut.set_edge_capacity(arc_of_edge[e], std::get<2>(p.edges[e]));
    return network;
}

std::vector<char> min_cut_labels(const Problem& p) {
    Network network = make_network(p);
    std::vector<char> side;
    network.cut.solve(p.terminal, side);
    return side;
}

double cut_cost(const Problem& p, const std::vector<char>& source_side) {
    double cost = 0;
    for (const auto& [a, b, c] : p.edges)
        if (source_side[a] != source_side[b]) cost += c;
    for (size_t i = 0; i < p.nodes; ++i) {
        if (p.terminal[i] > 0 && !source_side[i]) cost += p.terminal[i];
        if (p.terminal[i] < 0 && source_side[i]) cost -= p.terminal[i];
    }
    return cost;
}

//! Boost's Boykov–Kolmogorov on the same problem; a node is on the source
//! side unless it is in the sink tree (white).
std::vector<char> boost_labels(const Problem& p) {
    using Graph = boost::compressed_sparse_row_graph<boost::directedS>;
    using Edge = boost::graph_traits<Graph>::edge_descriptor;
    const size_t n = p.nodes, source = n, sink = n + 1;
    std::vector<std::pair<size_t, size_t>> arcs;
    std::vector<double> capacity;
    for (size_t i = 0; i < n; ++i) {
        const double c = std::abs(p.terminal[i]);
        arcs.emplace_back(p.terminal[i] > 0 ? source : i, p.terminal[i] > 0 ? i : sink);
        capacity.push_back(c);
        arcs.emplace_back(p.terminal[i] > 0 ? i : sink, p.terminal[i] > 0 ? source : i);
        capacity.push_back(0.0);
    }
    for (const auto& [a, b, c] : p.edges) {
        arcs.emplace_back(a, b);
        capacity.push_back(c);
        arcs.emplace_back(b, a);
        capacity.push_back(c);
    }
    // Sort the arcs by their tail for the graph, keeping each one's partner.
    std::vector<size_t> order(arcs.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](size_t x, size_t y) { return arcs[x].first < arcs[y].first; });
    std::vector<size_t> position(arcs.size());
    std::vector<std::pair<size_t, size_t>> sorted;
    std::vector<double> sorted_capacity;
    for (size_t k = 0; k < order.size(); ++k) {
        position[order[k]] = k;
        sorted.push_back(arcs[order[k]]);
        sorted_capacity.push_back(capacity[order[k]]);
    }
    Graph graph(boost::edges_are_sorted, sorted.begin(), sorted.end(), n + 2);
    std::vector<Edge> reverse(sorted.size());
    for (size_t k = 0; k < order.size(); ++k) {
        const size_t partner = position[order[k] ^ 1];
        reverse[k] = Edge(sorted[partner].first, partner);
    }
    std::vector<double> residual(sorted.size());
    std::vector<boost::default_color_type> color(n + 2);
    std::vector<long> distance(n + 2, 0);
    std::vector<Edge> predecessor(n + 2);
    const auto edge_index = boost::get(boost::edge_index, graph);
    const auto vertex_index = boost::get(boost::vertex_index, graph);
    boost::boykov_kolmogorov_max_flow(graph, boost::make_iterator_property_map(sorted_capacity.begin(), edge_index),
                                      boost::make_iterator_property_map(residual.begin(), edge_index),
                                      boost::make_iterator_property_map(reverse.begin(), edge_index),
                                      boost::make_iterator_property_map(predecessor.begin(), vertex_index),
                                      boost::make_iterator_property_map(color.begin(), vertex_index),
                                      boost::make_iterator_property_map(distance.begin(), vertex_index),
                                      vertex_index, source, sink);
    std::vector<char> side(n);
    for (size_t i = 0; i < n; ++i) side[i] = color[i] != boost::white_color;
    return side;
}

TEST(MinCut, SourceSideIsTheUnionOfAllMinimumCutsSourceSides) {
    std::mt19937 random(7);
    for (int trial = 0; trial < 300; ++trial) {
        const Problem p = random_problem(random, 3 + size_t(trial % 10), 2, true);
        double least = 1e300;
        std::vector<char> union_of_minima(p.nodes, 0), labels(p.nodes);
        for (uint32_t mask = 0; mask < (1u << p.nodes); ++mask) {
            for (size_t i = 0; i < p.nodes; ++i) labels[i] = (mask >> i) & 1;
            const double cost = cut_cost(p, labels);
            if (cost < least) {
                least = cost;
                union_of_minima.assign(p.nodes, 0);
            }
            if (cost == least)
                for (size_t i = 0; i < p.nodes; ++i) union_of_minima[i] |= labels[i];
        }
        const std::vector<char> found = min_cut_labels(p);
        EXPECT_EQ(cut_cost(p, found), least) << "trial " << trial;
        EXPECT_EQ(found, union_of_minima) << "trial " << trial;
    }
}

TEST(MinCut, LabelsAreBoostsOnLargerGraphs) {
    std::mt19937 random(11);
    for (int trial = 0; trial < 40; ++trial) {
        const bool whole = trial % 2 == 0;
        const Problem p = random_problem(random, 500 + 100 * size_t(trial), 3, whole);
        const std::vector<char> found = min_cut_labels(p), reference = boost_labels(p);
        EXPECT_EQ(found, reference) << "trial " << trial << (whole ? " (whole capacities)" : " (real capacities)");
        EXPECT_NEAR(cut_cost(p, found), cut_cost(p, reference), 1e-9);
    }
}

TEST(MinCut, SolvingAgainAfterChangesGivesAFreshNetworksLabels) {
    std::mt19937 random(13);
    Problem p = random_problem(random, 2000, 3, false);
    Network kept = make_network(p);
    std::vector<char> side;
    kept.cut.solve(p.terminal, side);
    std::uniform_real_distribution<double> real(0.0, 1.0);
    for (int round = 0; round < 5; ++round) {
        // New capacities on a tenth of the edges, set on the kept network, and new terminals.
        for (size_t e = 0; e < p.edges.size(); ++e)
            if (real(random) < 0.1) {
                std::get<2>(p.edges[e]) = real(random);
                kept.cut.set_edge_capacity(kept.arc_of_edge[e], std::get<2>(p.edges[e]));
            }
        for (double& t : p.terminal) t = (real(random) - 0.5) * 2.0;
        kept.cut.solve(p.terminal, side);
        EXPECT_EQ(side, min_cut_labels(p)) << "round " << round;
        EXPECT_EQ(side, boost_labels(p)) << "round " << round;
    }
}

}  // namespace
