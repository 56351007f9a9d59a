//! The volume handle of the C API: a box around an OpenVDB level set (signed
//! distance, negative inside, narrow band). Kept apart from context.h so that
//! only the API files that deal with volumes include OpenVDB.
#pragma once

#include <string>

#include <openvdb/openvdb.h>

struct fabvdb_volume {
    openvdb::FloatGrid::Ptr grid;
    //! What messages call it: the file it was read from, or the mesh it was
    //! made from, else "volume".
    std::string name = "volume";
};
