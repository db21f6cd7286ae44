#pragma once
// Reading a finished sweep directory (docs/design.md §4.5, §4.6): its manifest, its run files
// (the one reader of the report layer: `wirepack analyze` and `wirepack accuracy`) and the
// snapshots the distributions need. Runs are grouped by sweep::point_key.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "report/reductions.hpp"
#include "report/settings.hpp"
#include "sweep/config/sweep_config.hpp"
#include "sweep/runfile/run_file.hpp"

namespace wirepack::report {

// The run files of a directory: DIR/runs/*.h5 when DIR/runs exists (a sweep directory), else
// DIR/*.h5; names relative to DIR ("runs/NAME.h5"), sorted. `parts`: the NAME.h5 of each
// NAME.h5.part there (a run killed before its rename).
struct RunFileList {
  std::string runs_dir;  // the directory searched
  std::vector<std::string> files;
  std::vector<std::string> parts;
};
RunFileList list_run_files(const std::string& dir);

// Series `name` of a run record as a column of `rows` values, NaN where the series is missing
// or shorter.
std::vector<double> series_column(const sweep::RunRecord& record, const std::string& name,
                                  std::size_t rows);
// The rows of a run record: the length of its series "l" (0 without one).
std::size_t series_rows(const sweep::RunRecord& record);

// Reads `r.file` (relative to `dir`, known to exist): status, the series l and `kept`, the
// snapshots' l, then summarize_run. An unreadable file sets status "unreadable" and the reason.
void read_run(const std::filesystem::path& dir, RunData& r, const AnalysisSettings& settings,
              const std::vector<std::string>& kept = kept_series());

struct Directory {
  std::optional<sweep::Sweep> sweep;  // from the manifest, when there is one
  std::string manifest;               // its path ("" none)
  std::vector<RunData> runs;          // every expected or found run, by file name
};

// Opens DIR: its manifest (whose analysis block is applied to `settings`) and the list of runs,
// expected or found, by file name; nothing is read from the run files yet. Throws InputError.
Directory open_directory(const std::string& dir, AnalysisSettings& settings);

// Reads every run file that exists (read_run).
void read_runs(const std::string& dir, Directory& d, const AnalysisSettings& settings,
               const std::vector<std::string>& kept = kept_series());

// The distribution samples of each point at a.distribution_l, from the runs' snapshots.
std::vector<Samples> distribution_samples(const std::filesystem::path& dir, const Analysis& a);

}  // namespace wirepack::report
