#pragma once
// The run loop (docs/design.md §4.3, §5): one validated scene -> one Simulation -> one run file.
#include <atomic>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "sweep/config/scene_config.hpp"
#include "sweep/runfile/run_file.hpp"
#include "sweep/runfile/series.hpp"

namespace wirepack::sweep {

struct RunOutcome {
  // Complete or Failed once run_scene returns; Running when it was stopped (CheckpointOptions::
  // stop): no run file was written, the checkpoint (if on) holds where it stopped.
  RunStatus status = RunStatus::Running;
  std::string failure;    // reason of a failed run ("" otherwise)
  double l = 0;           // injected length / R reached
  long steps = 0;         // accepted steps
  double wall_s = 0;      // wall-clock duration, resumed runs' earlier part too [s]
  std::string started;    // when the run first started (ISO 8601 UTC; a resumed run's first part)
  double resumed_l = -1;  // l of the checkpoint this run resumed from (-1: started at l = 0)
  // Why a checkpoint was not used or could not be written ("" when nothing went wrong); the
  // run itself is unaffected by it.
  std::string checkpoint_note;
};

// Checkpoints of a run (sweep/runfile/run_checkpoint.hpp): every `every_s` seconds of wall time the
// state goes to RUN.h5.ckpt; a run whose checkpoint exists (same configuration) resumes from
// it. <= 0: no checkpoints, and an existing one is neither read nor removed.
// `stop` (may be null): once it reads true (a signal handler sets it: SIGTERM at a batch
// system's time limit, Ctrl-C), the run writes its checkpoint at once (if checkpoints are on)
// and returns with status Running, writing no run file.
struct CheckpointOptions {
  double every_s = 0;  // [s]
  const std::atomic<bool>* stop = nullptr;
  std::function<void(double l)> on_resume = {};  // called once resumed, with the l reached
};
inline constexpr double kDefaultCheckpointEvery = 300.0;  // [s]

// Names of the recorded series (sweep/runfile/series.hpp), in column order.
const std::vector<std::string>& series_names();

// Simulates `scene` to l_max. Records the series at l = 0, every output.every_l and at the end;
// snapshots at l = 0, every output.snapshots_every_l and at the end. Progress lines go to
// `progress` (may be null) at most every 2 s of wall time. Any exception from the simulation
// ends the run as failed: the series so far are still written with status "failed" and the
// reason. The run file is written once, at the end (write-then-rename); a failure to write it
// throws RunFileError. `threads` (empty: 1) says how many threads the simulation's force loops
// may use; it is asked again every 64 steps, so a sweep can give its idle cores to the runs
// still going, and the run uses fewer while more are measured to be slower (a busy machine;
// sweep/running/thread_governor.hpp). The result does not depend on it (bitwise). `series`: the
// columns recorded, one value of each per row, in its order. `checkpoint`: see CheckpointOptions; a
// resumed run's file is bitwise the uninterrupted run's (its wall-time column apart); the
// checkpoint is removed once the run file is written.
RunOutcome run_scene(const Scene& scene, const std::string& out_path, std::ostream* progress,
                     const std::function<int()>& threads = {},
                     const SeriesList& series = recorded_series(),
                     const CheckpointOptions& checkpoint = {});

}  // namespace wirepack::sweep
