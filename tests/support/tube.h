//! A closed tube or pin around the z axis for the thickness tests: known
//! wall thickness (r1 − r0) or diameter (2·r1 when r0 is 0).
#pragma once

#include "core/mesh.h"

namespace fabvdb::test {

//! A closed tube around the z axis from radius r0 to r1 (r0 = 0: a solid
//! pin of diameter 2·r1), z from 0 to `height`, `n` segments around;
//! outward-oriented.
Mesh make_tube(double r0, double r1, double height, int n);

}  // namespace fabvdb::test
