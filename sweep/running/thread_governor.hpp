#pragma once
// How many threads one run's force loops use, window by window of steps. A run may use up to
// `allowed` threads (its --threads, or the idle cores a sweep gives it), but more threads are not
// always faster: each step forks and joins about twenty short parallel loops, so when another
// process holds a core the threads wait at every join for a descheduled partner. Measured on the
// 2-core VM with one core busy: a 0.6 s rigid run took over 10 min with 2 threads. The governor
// starts on 1 thread, times the windows at its current choice and, now and then, one window at
// the other choice
// (1 thread, or all allowed); it keeps the faster and probes again after an interval that
// doubles while the choice holds. A probe is cut short once it has taken as long as a whole
// window at the choice (it has lost), so a probe costs at most about one window. More threads
// must earn their cores: they are taken when 10 % faster than one and given back once they are
// no longer 5 % faster (the band between is the hysteresis against timing noise; on an idle
// 2-core VM a symmetric 10 % band kept 2 threads all through a long run where they gained
// nothing measurable). The choice is also watched between probes: a window at the choice that
// takes kSlowdown times the choice's reference (its time when last chosen or confirmed) is cut
// short and followed by a probe at once, since the interval between probes, counted in windows,
// grows to 512 of them and a window on threads whose partner lost its core is ~10-50x slower
// (measured: a Fig. 4 run on 2 threads went from 24 s to ~230 s per unit l once another run took
// the second core, for over 10 min). The result of a run does not depend on its thread count
// (bitwise), so this changes only its wall time and CPU time.
#include <cstdint>

namespace wirepack::sweep {

class ThreadGovernor {
 public:
  static constexpr int kWindowSteps = 64;   // steps per window
  static constexpr int kFirstProbe = 1;     // windows at all allowed threads before the first probe
  static constexpr int kAfterSwitch = 4;    // windows before the probe after a switch
  static constexpr int kLongestWait = 512;  // the probe interval stops doubling here [windows]
  static constexpr double kMargin = 0.9;    // more threads are taken when < 90 % of 1's time
  static constexpr double kKeep = 0.95;     // and kept while < 95 % of it (else given back)
  static constexpr double kSlowdown = 2.0;  // a window at the choice this much slower: probe now

  // Threads for the next window, given how many are allowed now (>= 1).
  int next(int allowed);
  // The wall time of the window just run, per step [s].
  void record(double seconds_per_step);
  // Whether the window being run is to be cut short: a probe once `elapsed_s` of its steps
  // exceed a whole window's time at the choice; a window at the choice once they exceed
  // kSlowdown windows at its reference. The caller then ends the window (and records its time
  // per step so far) at once.
  bool lost(double elapsed_s) const {
    if (probing_) return elapsed_s > kWindowSteps * last_at_choice_;
    return ref_at_choice_ > 0 && elapsed_s > kSlowdown * kWindowSteps * ref_at_choice_;
  }

  int choice() const { return choice_; }
  std::int64_t probes() const { return probes_; }
  std::int64_t switches() const { return switches_; }

 private:
  int allowed_ = 0;             // the allowed count the state refers to (0: none yet)
  int choice_ = 1;              // threads used outside probes
  int window_threads_ = 1;      // threads of the window being run
  bool probing_ = false;        // the window being run is a probe
  int wait_ = kFirstProbe;      // windows between probes
  int since_probe_ = 0;         // windows at the choice since the last probe
  double last_at_choice_ = -1;  // seconds per step of the last window at the choice
  double ref_at_choice_ = -1;   // the choice's seconds per step when last chosen or confirmed
  std::int64_t probes_ = 0, switches_ = 0;
};

}  // namespace wirepack::sweep
