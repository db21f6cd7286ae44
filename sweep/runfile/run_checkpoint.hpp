#pragma once
// A run's checkpoint (docs/design.md §4.8): RUN.h5.ckpt beside the run file it will become,
// rewritten every few minutes of wall time while the run goes on, so a killed run resumes where
// its last checkpoint was instead of at l = 0. It holds what the run has recorded so far (the
// series, the snapshots, the recorder's next sampling points, the wall time spent) and the
// simulation's state (Simulation::save_state). A resumed run is bitwise the run that was never
// interrupted (apart from its wall-time column). Binary, in this machine's byte order; a
// checksum (FNV-1a 64) at the end refuses a damaged file.
#include <string>

#include "sweep/runfile/run_file.hpp"

namespace wirepack::sweep {

// Checkpoint format; bump it whenever the layout below changes.
inline constexpr int kCheckpointFormat = 1;

struct RunCheckpoint {
  std::string config;  // canonical JSON of the resolved scene (sweep_config.hpp)
  RunRecord record;    // what was recorded so far (status running); config is not stored twice
  double wall_s = 0;   // wall time spent before the checkpoint [s]
  double next_row = 0, next_snapshot = 0;        // the recorder's next sampling points (l)
  double last_row_l = -1, last_snapshot_l = -1;  // l of the last row and snapshot
  std::string engine;                            // Simulation::save_state()
};

// The checkpoint path of a run file.
inline std::string checkpoint_path(const std::string& run_file) {
  return run_file + ".ckpt";
}

// Writes `c` atomically (a temporary beside `path`, fsync, rename). Throws WriteError.
void write_checkpoint(const RunCheckpoint& c, const std::string& path);
// Reads a checkpoint; throws CheckpointError (engine/state_archive.hpp) naming the file and what
// is wrong: unreadable, not a checkpoint, another format, damaged (checksum), truncated.
RunCheckpoint read_checkpoint(const std::string& path);
// What a checkpoint has recorded so far, as the record of a run still going (status running,
// its config parsed), for `wirepack export` of a run part-way. Throws as read_checkpoint.
RunRecord read_checkpoint_record(const std::string& path);

}  // namespace wirepack::sweep
