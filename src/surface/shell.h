//! The atomic elements of the mold decomposition (thesis §3.4.2): the closed
//! low-resolution outer surface S_low, one inner vertex per outer vertex
//! (the map f_V, so each outer triangle t and its inner image form a prism),
//! and the thin-feature segments that are cast solid. `make_shell` checks that
//! S_low is a closed edge-manifold oriented surface and derives normals, areas
//! and the triangle adjacency every later step uses.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/mesh.h"

namespace fabvdb::surface {

struct Shell {
    Mesh outer;                     //!< S_low, millimetres, outward-oriented
    std::vector<Vec3> inner;        //!< f_V: inner vertex of each outer vertex
    std::vector<int> thin_segment;  //!< per triangle: thin-feature segment id, or -1
    double thickness = 0;           //!< ω in millimetres
    bool solid = false;             //!< prisms reach the medial surface: parts are cast solid, with no core
    double unit_scale = 1;          //!< 1 / largest bbox extent: lengths × unit_scale = unit-cube lengths
    //! The full-resolution input S_low was made from, and per input triangle
    //! the S_low triangle nearest to it (nearest_outer_triangles.h): what
    //! undercut depths are measured on (undercut_depth.h). Empty for a shell
    //! made without an input: measured on S_low.
    Mesh input;
    std::vector<uint32_t> input_nearest;

    // Derived by make_shell.
    std::vector<Vec3> normal;                 //!< unit outward normal per outer triangle
    std::vector<double> area;                 //!< area per outer triangle, unit-cube units
    std::vector<std::array<int, 3>> neighbor; //!< triangle across edge (v[k], v[k+1])
    size_t triangle_count() const { return outer.triangles.size(); }
};

//! Builds a Shell; throws Error(BAD_INPUT) naming `what` if `outer` has an edge
//! that is not shared by exactly two oppositely oriented triangles, or if
//! `inner` / `thin_segment` do not match its sizes.
Shell make_shell(Mesh outer, std::vector<Vec3> inner, std::vector<int> thin_segment, double thickness,
                 const std::string& what);

}  // namespace fabvdb::surface
