//! The functional features of a two-piece mold around one part, or several
//! parts side by side along X (thesis §3.6.3), in the frame where the
//! parting direction is +Z and +Y is up when the mold stands for pouring: a
//! gate at the lowest point of each part's parting line, runners from them
//! down below the parts and along to one sprue that leaves the block's top
//! (+Y) face, vents from the highest and locally highest points of the
//! parting lines to the same face, and registration keys (pins on the bottom
//! piece, holes with clearance in the top) near the block's corners. Channels
//! are grid cells along the parting surface; keys are closed prisms. Sizes
//! scale with the block margin. Pure function.
#pragma once

#include <array>
#include <vector>

#include "surface/parting_surface.h"

namespace fabvdb::surface {

struct MoldFeatureSizes {
    double runner_half_width = 0;
    double vent_half_width = 0;
    double runner_clearance = 0;  //!< runner distance from the part's shadow
    double key_radius = 0;
    double key_height = 0;
    double key_clearance = 0;     //!< hole radius and depth beyond the pin
};

//! Sizes for a block margin (mm): runner ⌀ margin/5, vents a third of that,
//! pins ⌀ margin/5 standing margin/5 high, 0.2 mm clearance.
MoldFeatureSizes mold_feature_sizes(double margin);

struct MoldFeatures {
    std::vector<Vec3> gates;  //!< one per parting line
    std::vector<Vec3> vents;
    std::vector<char> channel_cells;  //!< runner, sprue and vents, over the grid's cells
    std::vector<std::array<double, 2>> key_centers;
    Mesh pins;   //!< closed prisms to unite with the bottom piece
    Mesh holes;  //!< closed prisms to subtract from the top piece
};

//! `parting_lines`: points on each part's parting line (frame coordinates),
//! the parts side by side along X; `surface`: the parting surface over a grid
//! that extends one cell beyond the block on every side; `block_lo/hi`: the
//! block; `part_lo/hi`: the bounding box of all the parts.
MoldFeatures place_mold_features(const std::vector<std::vector<Vec3>>& parting_lines, const HeightGrid& surface,
                                 const Vec3& block_lo, const Vec3& block_hi, const Vec3& part_lo,
                                 const Vec3& part_hi, const MoldFeatureSizes& sizes);

//! A closed prism with `sides` sides approximating a vertical cylinder.
Mesh vertical_prism(double center_x, double center_y, double radius, double z0, double z1, int sides);

}  // namespace fabvdb::surface
