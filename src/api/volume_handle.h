//! The volume handle of the C API: a box around an OpenVDB level set (signed
//! distance, negative inside, narrow band). Kept apart from context.h so that
//! only the API files that deal with volumes include OpenVDB.
#pragma once

#include <openvdb/openvdb.h>

struct fabvdb_volume {
    openvdb::FloatGrid::Ptr grid;
};
