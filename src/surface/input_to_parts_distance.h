//! How closely cast parts reproduce their input: the distance from the
//! input surface to the nearest part surface, sampled at every vertex and,
//! on each triangle with an edge longer than `spacing`, on a barycentric grid
//! of that spacing, so a large triangle is measured inside too. Gives the
//! largest distance and the area-weighted mean (each triangle's area split
//! evenly over its samples, a vertex taking its share from every triangle
//! around it), overall and per part (the part each sample is nearest to).
//! Costs one AABB tree over the parts (surface_distance.h) and a query per
//! sample: about area / spacing² + vertices.
#pragma once

#include <vector>

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::surface {

struct InputToParts {
    double max = 0;                   //!< mm
    double mean = 0;                  //!< mm, area-weighted
    std::vector<double> part_max;     //!< mm, over the samples nearest to each part
    std::vector<double> part_mean;    //!< mm, area-weighted, likewise (0: no sample nearest to it)
};

//! `parts`: at least one with triangles. `spacing` > 0, mm.
InputToParts input_to_parts_distance(const Mesh& input, const std::vector<const Mesh*>& parts, double spacing,
                                     Progress& progress);

}  // namespace fabvdb::surface
