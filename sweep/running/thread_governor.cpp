#include "sweep/running/thread_governor.hpp"

#include <algorithm>

namespace wirepack::sweep {

int ThreadGovernor::next(int allowed) {
  allowed = std::max(1, allowed);
  if (allowed != allowed_) {
    // A new allowance (a run starts, a sweep frees cores): one window on 1 thread sets the
    // reference, then the next probes all allowed threads, which a losing probe cannot cost
    // more than about that window.
    allowed_ = allowed;
    choice_ = 1;
    probing_ = false;
    wait_ = kFirstProbe;
    since_probe_ = 0;
    last_at_choice_ = -1;
    ref_at_choice_ = -1;
  }
  if (allowed_ == 1) return window_threads_ = 1;
  // Probe the other choice once a window at the choice has been timed and the wait is over.
  probing_ = since_probe_ >= wait_ && last_at_choice_ > 0;
  window_threads_ = probing_ ? (choice_ == 1 ? allowed_ : 1) : choice_;
  return window_threads_;
}

void ThreadGovernor::record(double seconds_per_step) {
  if (allowed_ <= 1 || !(seconds_per_step > 0)) return;
  if (!probing_) {
    last_at_choice_ = seconds_per_step;
    ++since_probe_;
    if (ref_at_choice_ <= 0) {
      ref_at_choice_ = seconds_per_step;
    } else if (seconds_per_step > kSlowdown * ref_at_choice_) {
      since_probe_ = wait_;  // the machine changed under the choice: probe the other now
    }
    return;
  }
  // The probe against the window just before it (adjacent windows: nearly the same state).
  ++probes_;
  probing_ = false;
  since_probe_ = 0;
  // Up to all threads when they take < kMargin of one's time; back to one when the threads
  // take more than kKeep of its time (per step, the probe against the choice's last window).
  const bool better = window_threads_ > 1 ? seconds_per_step < kMargin * last_at_choice_
                                          : kKeep * seconds_per_step <= last_at_choice_;
  if (better) {
    choice_ = window_threads_;
    wait_ = kAfterSwitch;
    last_at_choice_ = seconds_per_step;
    ++switches_;
  } else {
    wait_ = std::min(2 * wait_, kLongestWait);
  }
  ref_at_choice_ = last_at_choice_;  // the choice as measured now
}

}  // namespace wirepack::sweep
