//! Progress: forwards stages and fractions to the user's callback, and turns a
//! cancel request (flag or callback's non-zero return) into Error(CANCELLED).
#include "core/progress.h"

#include <algorithm>

#include "core/error.h"

namespace fabvdb {

Progress::Progress() : owner_(std::this_thread::get_id()) {}

Progress::Progress(fabvdb_progress_fn callback, void* user, std::atomic<bool>* cancel_flag)
    : callback_(callback), user_(user), cancel_flag_(cancel_flag), owner_(std::this_thread::get_id()) {}

void Progress::stage(const char* name) {
    stage_ = name;
    last_reported_ = -1.0;
    update(0.0);
}

void Progress::update(double fraction) {
    check();
    if (!callback_ || std::this_thread::get_id() != owner_) return;
    fraction = std::clamp(fraction, 0.0, 1.0);
    if (fraction < 1.0 && last_reported_ >= 0.0 && fraction - last_reported_ < 0.002) return;
    last_reported_ = fraction;
    if (callback_(user_, stage_, fraction) != 0) own_cancel_ = true;
    check();
}

bool Progress::cancelled() const {
    return own_cancel_.load(std::memory_order_relaxed) ||
           (cancel_flag_ && cancel_flag_->load(std::memory_order_relaxed));
}

void Progress::check() const {
    if (cancelled()) throw Error(FABVDB_ERR_CANCELLED, std::string("cancelled during ") + stage_);
}

}  // namespace fabvdb
