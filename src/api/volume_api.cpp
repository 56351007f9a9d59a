//! C API: volume handles (level sets).
#include "api/guard.h"
#include "api/volume_handle.h"

extern "C" {

void fabvdb_volume_free(fabvdb_volume* volume) { delete volume; }

}  // extern "C"
