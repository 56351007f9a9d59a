//! How closely cast parts reproduce their input: the distance from the
//! input surface to the nearest part surface, sampled at every vertex and,
//! on each triangle with an edge longer than `spacing`, on a barycentric grid
//! of that spacing, so a large triangle is measured inside too. Gives the
//! largest distance and the area-weighted mean (each triangle's area split
//! evenly over its samples, a vertex taking its share from every triangle
//! around it), overall and per part (the part each sample is nearest to).
//! Input surface that the input's own solid encloses (the inner faces of
//! overlapping shells, the walls of a slit narrower than 0.3 mm) has no
//! surface of the solid to reproduce: a sample more than spacing / 2 from the
//! parts whose generalized winding number is at least 1/2, of one sign,
//! 0.05 × spacing behind it and in front of it (along its triangle's normal,
//! a vertex's area-weighted normal), or at a quarter, half, three quarters
//! or all of 0.3 mm in front, is left out.
//! Costs one AABB tree over the parts and one over the input
//! (surface_distance.h), one winding-number tree over the input
//! (volume/winding_number.h) and a query per sample: about area / spacing² +
//! vertices; per sample farther than spacing / 2 from the parts, a winding
//! number in front, a nearest-point query on the input where that is open,
//! up to four more winding numbers where other input surface comes within
//! 0.3 mm in front, and one behind where the front is solid.
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
    size_t enclosed_samples = 0;      //!< samples left out as enclosed by the input's solid
};

//! `parts`: at least one with triangles. `spacing` > 0, mm.
InputToParts input_to_parts_distance(const Mesh& input, const std::vector<const Mesh*>& parts, double spacing,
                                     Progress& progress);

}  // namespace fabvdb::surface
