//! Progress reporting and cancellation for long operations. An operation calls
//! `stage(name)` when it enters a phase and `update(fraction)` as it goes; both
//! throw Error(FABVDB_ERR_CANCELLED) once cancellation was asked for, so no
//! partial result escapes. `cancelled()` polls without throwing, for worker
//! threads and OpenVDB interrupters. The user callback is only ever called from
//! the thread that created the Progress, and at most every ~0.2% of a stage.
#pragma once

#include <atomic>
#include <string>
#include <thread>

#include "fabvdb.h"

namespace fabvdb {

class Progress {
public:
    //! Silent and never cancelled: for tests and internal sub-steps.
    Progress();
    //! Reports to `callback` (may be null); `cancel_flag` (may be null) is set
    //! from outside to ask for cancellation.
    Progress(fabvdb_progress_fn callback, void* user, std::atomic<bool>* cancel_flag);

    void stage(const char* name);
    void update(double fraction);
    bool cancelled() const;
    //! Throws Error(FABVDB_ERR_CANCELLED) if cancellation was asked for.
    void check() const;

private:
    fabvdb_progress_fn callback_ = nullptr;
    void* user_ = nullptr;
    std::atomic<bool>* cancel_flag_ = nullptr;
    std::atomic<bool> own_cancel_{false};
    const char* stage_ = "";
    double last_reported_ = -1.0;
    std::thread::id owner_;
};

}  // namespace fabvdb
