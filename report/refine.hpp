#pragma once
// `wirepack refine DIR` (issue 16): adaptive refinement of a sweep at the transition. Rounds of
//   1. run what the sweep in DIR still lacks (run_sweep: same seeds, resumable),
//   2. fit x_c of D along the refined parameter in every slice (critical_table.hpp),
//   3. stop when every interval is narrower than --until-ci or the run budget is spent,
//   4. else propose, per slice, new seeds at the grid values in and next to the interval while
//      they have fewer than analysis::kMinSeedsNearCritical (analysis::propose_seeds; the
//      sweep's extra_seeds), or else new values (analysis::propose_refinement; its listed
//      points), and write the sweep to DIR/refine.json (a sweep file) before running them.
// The sweep is DIR/refine.json when it exists, else the manifest's. Killing refine loses only the
// runs in flight: a rerun reads refine.json and continues. DIR/refine_log.csv gets one line per
// slice and round.
#include <cstddef>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace wirepack::report {

struct RefineOptions {
  std::string dir;                 // sweep directory (written by `wirepack sweep`)
  std::string axis;                // "mu_s" or "/mu_s"; "" = mu_s if swept, else the only one
  int runs = 0;                    // new runs per slice and round (whole points); 0: 4 points
  std::string add = "auto";        // "auto": seeds while the values around x_c lack them,
                                   // then values;
                                   // "values": grid values only; "seeds": seeds only
  std::optional<double> until_ci;  // stop when every slice's interval is at most this wide
  std::optional<long> budget;      // most runs the listed points may hold; default one round
  int threads = 0;                 // concurrent runs; 0: every core
  std::vector<std::string> critical_ranges;  // "NAME=X_MIN,X_MAX": fit and refine inside
  std::ostream* progress = nullptr;
};

struct RefineOutcome {
  int rounds = 0;                  // rounds that added points (this invocation)
  std::size_t added_runs = 0;      // runs added by this invocation
  std::size_t listed_runs = 0;     // runs beyond the grid's in the end (listed points and
                                   // extra seeds; all invocations)
  std::size_t failed = 0;          // failed runs in the sweep at the end
  std::string stop;                // why it stopped, in words
  std::string sweep_file;          // DIR/refine.json ("" when nothing was ever added)
  std::vector<std::string> lines;  // final summary: one line per slice
};

// Throws InputError (nothing written) when DIR is not a sweep directory, the axis is not a swept
// transition parameter (mu_s, eps, xi, rho), or an option is out of range.
RefineOutcome refine_sweep(const RefineOptions& options);

}  // namespace wirepack::report
