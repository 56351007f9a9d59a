//! The adapter that lets OpenVDB tools poll fabvdb's cancellation: an
//! `openvdb::util::NullInterrupter` whose `wasInterrupted()` asks the
//! Progress (thread-safe, never throws). Callers pass it to every OpenVDB tool
//! that takes an interrupter, then call `progress.check()` afterwards so a
//! cancelled tool's partial result is never used.
#pragma once

#include <openvdb/util/NullInterrupter.h>

#include "core/progress.h"

namespace fabvdb::volume {

class ProgressInterrupter final : public openvdb::util::NullInterrupter {
public:
    explicit ProgressInterrupter(const Progress& progress) : progress_(progress) {}
    bool wasInterrupted(int /*percent*/ = -1) override { return progress_.cancelled(); }

private:
    const Progress& progress_;
};

}  // namespace fabvdb::volume
