//! The vertices of a mesh whose fan of triangles is embedded: seen along the
//! sum of their normals, the triangles around the vertex each turn the same
//! way (certainly, by a floating-point filter) and wind once around it, so
//! each projects one to one into its own angular sector. Two triangles of
//! such a fan meet only along what they share, so a pairwise crossing test
//! need not test the pairs that share an embedded vertex, or an edge at one.
//! A fan of fewer than 3 or more than 64 triangles, one not closed into a
//! single cycle, or one the filter is unsure of is not embedded. Pure;
//! linear in the triangles; parallel (TBB).
#pragma once

#include <vector>

#include "core/mesh.h"

namespace fabvdb::volume {

//! Per vertex, whether its fan is embedded; computed for the vertices of the
//! `candidates` triangles only (per triangle; empty: all), the others 0.
std::vector<char> embedded_fans(const Mesh& mesh, const std::vector<char>& candidates = {});

}  // namespace fabvdb::volume
