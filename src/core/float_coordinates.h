//! Coordinates as STL and 3MF files store them: each the nearest
//! single-precision float. Rounding goes through a volatile float, since
//! GCC 12.2 at -O2 and above vectorises {double(float(x)), double(float(y)),
//! ...} into a pair conversion that it then drops as a no-op. Pure.
#pragma once

#include "core/centred_frame.h"
#include "core/mesh.h"

namespace fabvdb {

double nearest_float(double x);
Vec3 nearest_float(const Vec3& p);

//! Whether every coordinate of the mesh is a float already.
bool on_float_grid(const Mesh& mesh);

//! Where a point given in `frame`'s local coordinates lies once its world
//! position is stored as floats, in the same local coordinates.
Vec3 stored_position(const Vec3& local, const CentredFrame& frame);

//! The float step at the largest world coordinate of a box given in
//! `frame`'s local coordinates: storing a point of it as floats moves each
//! coordinate by at most half of it (the step is 2 mm at 25 km).
double float_step_over(const BoundingBox& local, const CentredFrame& frame);

}  // namespace fabvdb
