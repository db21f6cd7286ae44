#pragma once
// The sweep driver (docs/design.md §4.5, §3.6): runs every (point, seed) of a sweep shard as an
// OpenMP task, longest expected first, each into its own run file; resumes from what is on disk.
#include <cstddef>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "sweep/config/sweep_config.hpp"
#include "sweep/running/run.hpp"
#include "sweep/running/sweep_manifest.hpp"

namespace wirepack::sweep {

// One condition of `wirepack sweep --only KEY=V1,V2,...`: the run's value of the grid axis KEY
// (KEY "seed": its seed) is one of `values`.
struct RunCondition {
  std::string key;
  std::vector<nlohmann::json> values;  // numbers, or strings for text-valued axes
};

// Parses "KEY=V1,V2,..." (a value that reads as a number is one). Throws InputError, prefixed by
// `what`, when the form is wrong, KEY is neither an axis of `sweep` nor "seed", or no run of the
// sweep has one of the values (a typo would otherwise select nothing, silently).
RunCondition parse_run_condition(const Sweep& sweep, const std::string& text,
                                 const std::string& what);

// Whether `run` meets every condition (numbers equal to 1e-12 relative); true when there is none.
bool meets(const SweepRun& run, const std::vector<RunCondition>& only);

struct SweepOptions {
  std::string dir;            // the sweep directory; run files go to DIR/runs/
  int threads = 0;            // concurrent runs; 0: omp_get_num_procs()
  Shard shard;                // which runs of the run order this process owns
  bool retry_failed = false;  // rerun runs whose file says "failed" (otherwise kept)
  // Simulate only the runs that meet all of these (`--only`); the others stay as they are on
  // disk, and the manifest still lists every run of the shard (pending ones as pending).
  std::vector<RunCondition> only;
  std::ostream* progress = nullptr;  // start line, progress lines, warnings (may be null)
  double progress_interval_s = 5.0;  // least time between progress lines [s]
  // Wall seconds between a run's checkpoints (sweep/running/run.hpp, CheckpointOptions); <= 0:
  // none.
  double checkpoint_every_s = kDefaultCheckpointEvery;
  // May be null. Once true (a signal handler: SIGTERM, SIGINT), no run starts and the runs
  // going write their checkpoints and stop; they stay pending for the next invocation.
  const std::atomic<bool>* stop = nullptr;
};

struct SweepOutcome {
  std::size_t runs = 0;           // runs in this shard
  std::size_t complete = 0;       // complete at the end (found or run)
  std::size_t failed = 0;         // failed at the end (found or run)
  std::size_t ran = 0;            // simulated by this invocation
  std::size_t found = 0;          // finished runs found on disk and kept
  std::size_t parts_removed = 0;  // .part leftovers of killed runs removed
  std::size_t temps_removed = 0;  // manifest temporaries of killed invocations removed
  std::size_t joblog_added = 0;   // joblog lines restored for runs finished on disk without one
  std::size_t stopped = 0;        // runs stopped part-way by SweepOptions::stop (pending again)
  std::size_t left_out = 0;       // runs to do that SweepOptions::only left for another time
  int threads = 0;                // threads used
  double wall_s = 0;              // [s]
  std::vector<std::pair<std::string, std::string>> failures;  // (file, reason), run order
  std::vector<std::string> warnings;  // manifest or joblog writes that failed, unreadable files
  std::string manifest;               // path of the manifest written
};

// Creates DIR and DIR/runs; throws InputError when that is impossible or DIR is not writable.
void prepare_sweep_dir(const std::string& dir);

// Runs the shard's runs that are not finished on disk (docs/design.md §4.5):
// - resume: a run whose final file exists and says "complete" is kept; "failed" is kept unless
//   retry_failed; a `.part` leftover is removed and the run redone; a file that cannot be read
//   or holds another config is redone. Manifest temporaries a killed invocation left
//   (MANIFEST.tmp.<pid>) are removed; a finished run without a joblog line (killed between its
//   rename and its line) gets its line, from the run file's own times.
// - scheduling: one OpenMP task per run in a `parallel` + `single` region of `threads` threads,
//   nesting off; each task takes the longest remaining run (expected_cost, ties in run order),
//   so long runs do not end up last. With `only`, the runs to do that do not meet it are left
//   out (pending, or as their files say).
// - isolation: a task catches everything; an engine failure is in the run file (run_scene), a
//   run file that cannot be written is recorded as failed; the sweep goes on.
// - records: the manifest is rewritten atomically when a run finishes (at most once a second;
//   always at the end) and the joblog gets one line per finished attempt.
// Throws InputError before any run when the directory is unusable or the shard is locked.
SweepOutcome run_sweep(const Sweep& sweep, const SweepOptions& options);

}  // namespace wirepack::sweep
