#pragma once
// The run file (docs/design.md §4.3): one HDF5 file per run. Root attributes status, failure,
// config, version, git, started, finished, layout; /series/<name> 1-D float64 datasets in
// recording order; /snapshots/<k>/{wire, curvature, shell_vertices, shell_triangles} with
// attribute l. Layout 2: datasets of 32 KiB or more chunked and compressed (shuffle + deflate)
// where the HDF5 library can, the shell's triangles stored once as /shell_triangles and
// hard-linked into every snapshot whose mesh it is. Layout 1 (no attribute layout): a triangle
// dataset in every snapshot; still read. Fields (issue 18), optional on read (files from before
// them lack them): /snapshots/<k>/{wire_contacts, shell_area_stretch, shell_contact_force} and
// the clamped rim, stored once as /shell_clamped and hard-linked like the triangles.
// Written as PATH.part and renamed to PATH once fully written and closed.
#include <array>
#include <cstdint>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace wirepack::sweep {

// An HDF5 or file-system failure while writing or reading a run file.
class RunFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class RunStatus { Running, Complete, Failed };
std::string to_string(RunStatus s);                      // "running" | "complete" | "failed"
RunStatus run_status_from_string(const std::string& s);  // throws RunFileError if unknown

struct Snapshot {
  double l = 0;                                       // injected length / R
  std::vector<std::array<double, 3>> wire;            // inside centerline, tip first (n x 3) [m]
  std::vector<double> curvature;                      // kappa_i at the wire nodes (n) [1/m]
  std::vector<std::array<double, 3>> shell_vertices;  // (m x 3) [m]; empty for a rigid shell
  std::vector<std::array<int, 3>> shell_triangles;    // vertex indices (f x 3); empty if rigid
  // Fields, each empty where not recorded (rigid shell, or a file from before them):
  std::vector<int> wire_contacts;          // self-contacts per wire node (n) [-]
  std::vector<double> shell_area_stretch;  // current / rest area per face (f) [-]; float32 in file
  std::vector<std::array<double, 3>> shell_contact_force;  // wire's force per vertex (m x 3) [N]
  std::vector<std::uint8_t> shell_clamped;                 // 1 on the clamped rim (m)
};

struct Series {
  std::string name;            // observable name (docs/design.md §5.7), e.g. "U_b_hat"
  std::vector<double> values;  // one value per recorded row
};

// Everything a run file holds, in memory.
struct RunRecord {
  nlohmann::json config;  // resolved scene (all defaults filled)
  RunStatus status = RunStatus::Running;
  std::string failure;  // reason of a failed run, "" otherwise
  std::string version;  // wirepack version and git hash that produced the file
  std::string git;
  std::string started;         // ISO-8601 UTC
  std::string finished;        // ISO-8601 UTC, "" while running
  std::vector<Series> series;  // columns in recording order, all of equal length
  std::vector<Snapshot> snapshots;
  // Layout of the file read (1: triangles in every snapshot, 2: shared /shell_triangles);
  // write_run_file always writes kRunFileLayout and ignores this.
  int layout = 2;

  // The series called `name`, or nullptr.
  const Series* find_series(const std::string& name) const;
  Series* find_series(const std::string& name);
};

// The run file layout write_run_file writes, and the newest read_run_file reads.
inline constexpr int kRunFileLayout = 2;

// HDF5 path of snapshot k's shell triangles in the file `r` was read from (or is written to):
// "/shell_triangles" where the snapshot shares the run's mesh in a layout 2 file, else
// "/snapshots/<k>/shell_triangles" (the snapshot's own dataset; in layout 2 also a hard link).
std::string shell_triangles_path(const RunRecord& r, std::size_t k);

// The version and git hash of this build (for RunRecord::version, git).
std::string build_version();
std::string build_git();

// Serialises every HDF5 call in the process (the HDF5 library is not safe to call from
// several threads at once). write_run_file and read_run_file take it themselves.
std::mutex& hdf5_mutex();

// Builds the file in memory (layout kRunFileLayout; uncompressed if the library has no deflate
// encoder), writes it to `path + ".part"` (one write, fsync) and renames that to `path`. On failure
// (a full disk: "No space left on device", a file-size limit: "File too large") the .part file is
// removed and RunFileError is thrown; an existing `path` is then left untouched.
void write_run_file(const RunRecord& record, const std::string& path);
// Reads a run file written by write_run_file. Throws RunFileError, with the path and the
// reason: not HDF5, truncated, written by a newer wirepack (attribute `version`) or in an
// unknown layout (attribute `layout`), a required part missing (attributes status and config,
// groups /series and /snapshots, /series/l) or series of unequal lengths. Reads layouts 1 and 2.
// Every snapshot comes back with its own copy of the triangles, wherever the file keeps them.
RunRecord read_run_file(const std::string& path);

}  // namespace wirepack::sweep
