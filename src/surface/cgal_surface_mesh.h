//! A triangle mesh as CGAL's Surface_mesh (EPICK points) and back, for the
//! steps that hand a mesh to CGAL's Polygon Mesh Processing. The conversion
//! keeps every vertex and triangle in order; it fails (returns nothing)
//! when the triangles do not make an oriented 2-manifold, with or without
//! boundary (CGAL's is_polygon_soup_a_polygon_mesh), or when a face coming
//! back is not a triangle. Pure; linear in the mesh.
#pragma once

#include <optional>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include "core/mesh.h"

namespace fabvdb::surface {

using CgalSurfaceMesh = CGAL::Surface_mesh<CGAL::Epick::Point_3>;

std::optional<CgalSurfaceMesh> to_cgal_surface_mesh(const Mesh& mesh);

std::optional<Mesh> from_cgal_surface_mesh(const CgalSurfaceMesh& surface);

}  // namespace fabvdb::surface
