//! Regions where no drain hole may open: spheres, or the inside of a closed
//! mesh. `read_keep_out` takes a JSON file ({"spheres": [{"center": [x,y,z],
//! "radius": r}, ...]} or a bare array of such spheres) or a mesh file
//! (any format io reads), turned into a level set at `voxel_size` whose band
//! reaches `reach` mm out (the largest margin `touches` is asked about;
//! farther points read as far). Error(BAD_INPUT) names the file and the
//! defect; Error(IO) if unreadable.
#pragma once

#include <string>
#include <vector>

#include <openvdb/openvdb.h>

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::powder {

struct KeepOutSphere {
    Vec3 center{0, 0, 0};
    double radius = 0.0;
};

struct KeepOut {
    std::vector<KeepOutSphere> spheres;
    openvdb::FloatGrid::Ptr region;  //!< level set of a keep-out mesh, or null

    //! Whether a disc of radius `margin` around `point` reaches into the
    //! region (exact for margins up to the region's band; a point beyond the
    //! band is far from it).
    bool touches(const Vec3& point, double margin) const;
    bool empty() const { return spheres.empty() && !region; }
};

KeepOut read_keep_out(const std::string& path, double voxel_size, double reach, Progress& progress);

}  // namespace fabvdb::powder
