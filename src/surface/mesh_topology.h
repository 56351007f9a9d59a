//! Combinatorial topology of a triangle mesh on its vertex indices as stored
//! (no welding: weld_vertices.h does that first when wanted), from its edge
//! table (volume/edge_table.h). Edges are unordered vertex pairs; an edge
//! used by one triangle is a boundary edge, by three or more a non-manifold
//! edge. Pure functions on the mesh.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/mesh.h"
#include "volume/edge_table.h"

namespace fabvdb::surface {

using volume::build_edge_table;
using volume::EdgeTable;
using volume::EdgeUse;

//! The component (0-based, numbered in order of first triangle) of every
//! triangle, where triangles sharing a vertex are in the same component;
//! `component_count` receives the number of components.
std::vector<uint32_t> triangle_components(const Mesh& mesh, size_t& component_count);

//! The vertices of each boundary loop: boundary edges (used by one triangle)
//! connected through shared vertices, so loops that touch at a vertex are
//! one. Loops in order of their least vertex, each loop's vertices ascending.
std::vector<std::vector<uint32_t>> boundary_loops(const Mesh& mesh, const EdgeTable& edges);

//! The figures `fabvdb info` reports about topology (README "fabvdb info").
struct TopologySummary {
    size_t referenced_vertices = 0;
    size_t unreferenced_vertices = 0;
    size_t edges = 0;
    size_t boundary_edges = 0;       // used by exactly one triangle
    size_t boundary_loops = 0;       // groups of boundary edges connected through shared vertices
    size_t non_manifold_edges = 0;   // used by three or more triangles
    size_t non_manifold_vertices = 0;  // whose triangles do not form one fan (edge-connected around it)
    size_t inconsistent_edges = 0;   // used by exactly two triangles that run along it the same way
    size_t components = 0;
    std::vector<uint32_t> triangle_component;  // as triangle_components()
    std::vector<bool> component_closed;        // per component: no boundary nor non-manifold edge
    //! No boundary and no non-manifold edge (and at least one triangle).
    bool closed = false;
    //! Sum of the components' genera from the Euler characteristic, only for a
    //! closed mesh without non-manifold vertices whose characteristic is even.
    std::optional<long long> genus;
};

TopologySummary summarize_topology(const Mesh& mesh);

}  // namespace fabvdb::surface
