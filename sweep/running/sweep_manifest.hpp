#pragma once
// What a sweep directory records besides the run files (docs/design.md §4.5): the manifest (the
// resolved sweep and every run with its status), the joblog (one CSV line per run attempt), the
// shard a process works on, and the lock that keeps two processes off the same shard.
//
// Concurrency: a process only ever writes files named after its own shard, so shards of one
// sweep can share a directory on any file system (NFS and Lustre included) without file locks:
//   1 shard:  DIR/manifest.json              DIR/joblog.csv              DIR/.lock
//   K of N:   DIR/manifest.shard-K-of-N.json DIR/joblog.shard-K-of-N.csv DIR/.lock.shard-K-of-N
// and the run files of its own runs. Inside a process, the threads share these through one
// mutex (sweep_runner). The manifest is rewritten whole (temp file, fsync, rename); the joblog
// grows by one write(2) per line.
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sweep/config/sweep_config.hpp"

namespace wirepack::sweep {

// Shard K of N: the runs whose index in the run order is K modulo N.
struct Shard {
  std::size_t index = 0;  // K, 0 <= K < N
  std::size_t count = 1;  // N

  bool contains(std::size_t run_index) const { return run_index % count == index; }
  std::string text() const;    // "K/N"
  std::string suffix() const;  // "" for one shard, ".shard-K-of-N" otherwise
};

// Parses "K/N" (0 <= K < N). Throws InputError naming `what` (e.g. "--shard").
Shard parse_shard(const std::string& text, const std::string& what);
// The shard of a SLURM job-array task: K = (SLURM_ARRAY_TASK_ID - SLURM_ARRAY_TASK_MIN) /
// SLURM_ARRAY_TASK_STEP (MIN 0 and STEP 1 when unset), N = SLURM_ARRAY_TASK_COUNT; nothing when
// ID or COUNT is unset. Throws InputError when they are set but inconsistent. `getenv` is
// ::getenv unless a test passes its own.
std::optional<Shard> shard_from_env(
    const std::function<const char*(const char*)>& getenv = nullptr);

std::string manifest_path(const std::string& dir, const Shard& shard);
std::string joblog_path(const std::string& dir, const Shard& shard);
std::string lock_path(const std::string& dir, const Shard& shard);

// State of one run as the manifest shows it.
enum class EntryStatus { Pending, Running, Complete, Failed };
std::string to_string(EntryStatus s);  // "pending" | "running" | "complete" | "failed"

struct ManifestEntry {
  const SweepRun* run = nullptr;
  EntryStatus status = EntryStatus::Pending;
  double wall_s = -1;         // wall time of the run [s]; < 0: unknown (pending, running)
  std::string reason = {};    // failure reason ("" unless failed)
  std::string started = {};   // ISO-8601 UTC ("" until started)
  std::string finished = {};  // ISO-8601 UTC ("" until finished)
};

// The manifest document: {"sweep": resolved sweep, "shard": "K/N", "version", "git",
// "updated", "counts": {runs, complete, failed, running, pending},
// "runs": [{index, id, file, point, seed, status, wall_s, reason, started, finished}]}.
nlohmann::json manifest_json(const Sweep& sweep, const Shard& shard,
                             const std::vector<ManifestEntry>& entries);

// One line of the joblog: a finished run attempt.
struct JobLogLine {
  std::string id, file;
  std::string start, end;  // ISO-8601 UTC
  double wall_s = 0;       // [s]
  std::string status;      // "complete" | "failed"
  std::string reason;
  std::string shard;  // "K/N"
};

// The joblog CSV: header `id,file,start,end,wall_s,status,reason,shard`, appended to across
// invocations. Each line is one write(2) to an O_APPEND descriptor, so it reaches the file even
// if the process is killed right after.
class JobLog {
 public:
  explicit JobLog(const std::string& path);  // throws std::runtime_error
  ~JobLog();
  JobLog(const JobLog&) = delete;
  JobLog& operator=(const JobLog&) = delete;
  void append(const JobLogLine& line);  // throws std::runtime_error

 private:
  int fd_ = -1;
  std::string path_;
};

// An exclusive flock on a lock file, held while the object lives. Throws InputError if another
// process holds it (a second `wirepack sweep` on the same shard and directory). On a file
// system without flock the lock is skipped (held() is false).
class DirLock {
 public:
  explicit DirLock(const std::string& path);
  ~DirLock();
  DirLock(const DirLock&) = delete;
  DirLock& operator=(const DirLock&) = delete;
  bool held() const { return held_; }

 private:
  int fd_ = -1;
  bool held_ = false;
};

// The manifest of a sweep directory: DIR/manifest.json, else the first shard's
// DIR/manifest.shard-K-of-N.json (each holds the whole sweep); "" when there is none.
std::string find_manifest(const std::string& dir);

}  // namespace wirepack::sweep
