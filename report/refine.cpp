#include "report/refine.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>

#include "report/analyze.hpp"
#include "report/critical_table.hpp"
#include "sweep/atomic_file.hpp"
#include "sweep/config/json_file.hpp"
#include "sweep/config/sweep_config.hpp"
#include "sweep/errors.hpp"
#include "sweep/format.hpp"
#include "sweep/running/sweep_manifest.hpp"
#include "sweep/running/sweep_runner.hpp"

namespace wirepack::report {

namespace fs = std::filesystem;
using json = nlohmann::json;
using namespace wirepack::sweep;  // refine drives the sweep runner: configuration, runs, manifest

namespace {

constexpr int kDefaultPointsPerRound = 4;
constexpr int kUntilCiRounds = 10;  // rounds allowed by --until-ci without --budget

// The sweep of DIR: refine.json (written by an earlier refine) or the manifest's.
Sweep load_current(const fs::path& dir) {
  std::error_code ec;
  const fs::path refined = dir / "refine.json";
  if (fs::is_regular_file(refined, ec)) return load_sweep(refined.string());
  const std::string manifest = find_manifest(dir.string());
  if (manifest.empty())
    throw InputError(dir.string() +
                     ": no manifest.json and no refine.json: not a sweep directory (run "
                     "`wirepack sweep SWEEP.json --out DIR` first)");
  const json m = load_json_file(manifest);
  if (!m.is_object() || !m.contains("sweep"))
    throw InputError(manifest + ": /sweep: required key is missing (not a sweep manifest)");
  return parse_sweep(m["sweep"], manifest + " (/sweep)");
}

std::string text_of(const json& v) {
  if (v.is_number()) return format_number(v.get<double>());
  if (v.is_string()) return v.get<std::string>();
  return v.dump();
}

std::string name_of(const std::string& pointer) {
  std::string s = pointer.substr(1);
  std::replace(s.begin(), s.end(), '/', '.');
  return s;
}

std::string slice_text(const CriticalSlice& s) {
  std::string t;
  for (const auto& [ptr, v] : s.at)
    t += (t.empty() ? "" : ", ") + name_of(ptr) + " = " + text_of(v);
  return t.empty() ? "(one slice)" : t;
}

double width(const analysis::CriticalResult& f) {
  return f.status == "ok" ? f.x_c_hi - f.x_c_lo : NAN;
}

// 4 significant digits, for messages.
std::string short_number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.4g", x);
  return buf;
}

std::string fit_text(const analysis::CriticalResult& f) {
  if (!std::isfinite(f.x_c)) return f.status + (f.note.empty() ? "" : ": " + f.note);
  std::string t = "x_c = " + short_number(f.x_c);
  if (f.status == "ok")
    t += " [" + short_number(f.x_c_lo) + ", " + short_number(f.x_c_hi) + "], width " +
         short_number(width(f));
  return t + " (" + f.status + ", " + f.model + ", " + std::to_string(f.points) + " points)";
}

// Appends lines to DIR/refine_log.csv (header when new).
void append_log(const fs::path& dir, const std::vector<std::string>& lines) {
  const fs::path path = dir / "refine_log.csv";
  std::error_code ec;
  const bool fresh = !fs::exists(path, ec);
  std::ofstream out(path, std::ios::app);
  if (fresh)
    out << "time,axis,slice,listed_runs,points,values,status,model,x_c,x_c_lo,x_c_hi,width,"
           "added\n";
  for (const auto& l : lines) out << l << '\n';
}

// The refinement's runs: those beyond the grid's points times the sweep's seeds.
std::size_t refinement_runs(const Sweep& sw) {
  return sw.runs.size() - sw.grid_points * sw.seeds.size();
}

// The sweep's point at `x` on `axis` in slice `s` as a sweep-file object (every axis), or null
// when a value of another axis is not fixed by the slice.
json point_at(const Sweep& sw, const std::string& axis, const CriticalSlice& s, double x) {
  json point = json::object();
  for (const auto& a : sw.axes) {
    if (a.pointer == axis) {
      point[a.key] = x;
      continue;
    }
    const auto it =
        std::find_if(s.at.begin(), s.at.end(), [&](const auto& p) { return p.first == a.pointer; });
    if (it != s.at.end() && !it->second.is_null())
      point[a.key] = it->second;
    else if (a.values.size() == 1)
      point[a.key] = a.values[0];
    else
      return nullptr;
  }
  return point;
}

std::size_t pending_runs(const fs::path& dir, const Sweep& sw) {
  std::size_t n = 0;
  std::error_code ec;
  for (const auto& r : sw.runs) n += !fs::exists(dir / r.file, ec);
  return n;
}

}  // namespace

RefineOutcome refine_sweep(const RefineOptions& o) {
  const fs::path dir(o.dir);
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw InputError(o.dir + ": no such directory (give a directory written by `wirepack sweep`)");
  if (o.runs < 0) throw InputError("--runs: must be >= 1 (got " + std::to_string(o.runs) + ")");
  if (o.until_ci && !(std::isfinite(*o.until_ci) && *o.until_ci > 0))
    throw InputError("--until-ci: must be a width > 0 in units of the refined parameter (got " +
                     format_number(*o.until_ci) + ")");
  if (o.add != "auto" && o.add != "values" && o.add != "seeds")
    throw InputError("--add: must be auto, values or seeds (got " + o.add + ")");
  if (o.budget && *o.budget < 0)
    throw InputError("--budget: must be >= 0 runs (got " + std::to_string(*o.budget) + ")");
  Sweep sw = load_current(dir);

  // The refined parameter: a transition parameter that is a grid axis with numbers.
  std::vector<std::string> candidates;
  for (const auto& a : sw.axes)
    if (is_transition_axis(a.pointer)) candidates.push_back(a.pointer);
  std::string axis;
  const std::string wanted = o.axis.empty() || o.axis[0] == '/' ? o.axis : "/" + o.axis;
  std::string valid;
  for (const auto& c : candidates) valid += (valid.empty() ? "" : ", ") + c.substr(1);
  if (!wanted.empty()) {
    if (std::find(candidates.begin(), candidates.end(), wanted) == candidates.end())
      throw InputError("--axis: " + o.axis + " is not a swept transition parameter of " + o.dir +
                       " (swept: " + (valid.empty() ? "none" : valid) + ")");
    axis = wanted;
  } else if (const auto first = std::find_if(
                 candidates.begin(), candidates.end(),
                 [](const std::string& c) { return sweep::find_key(c)->roles.refine_first; });
             first != candidates.end()) {
    axis = *first;
  } else if (candidates.size() == 1) {
    axis = candidates[0];
  } else {
    throw InputError(
        o.dir + ": " +
        (candidates.empty()
             ? "no transition parameter (" +
                   sweep::key_names_with(&sweep::KeySpec::Roles::transition) + ") is a grid axis"
             : "several transition parameters are swept (" + valid + "): choose one with --axis"));
  }
  const GridAxis& grid_axis = *std::find_if(sw.axes.begin(), sw.axes.end(),
                                            [&](const GridAxis& a) { return a.pointer == axis; });
  for (const auto& v : grid_axis.values)
    if (!v.is_number())
      throw InputError(o.dir + ": /grid/" + grid_axis.key + ": refine needs numbers (got " +
                       v.dump() + ")");

  const std::size_t seeds = sw.seeds.size();
  const std::size_t per_round =
      o.runs > 0 ? std::max<std::size_t>(1, static_cast<std::size_t>(o.runs) / seeds)
                 : kDefaultPointsPerRound;
  DirLock lock((dir / ".lock.refine").string());  // one refine per directory

  RefineOutcome out;
  const std::size_t listed_at_start = refinement_runs(sw);
  // Without --budget and --until-ci: one round, or finishing an interrupted one.
  const bool one_round = !o.budget && !o.until_ci;
  const bool interrupted = pending_runs(dir, sw) > 0;
  std::optional<std::size_t> budget;
  if (o.budget) budget = static_cast<std::size_t>(*o.budget);
  const fs::path refined = dir / "refine.json";
  if (fs::exists(refined, ec)) out.sweep_file = refined.string();

  for (int round = 0;; ++round) {
    SweepOptions so;
    so.dir = o.dir;
    so.threads = o.threads;
    so.progress = o.progress;
    const SweepOutcome ran = run_sweep(sw, so);
    out.failed = ran.failed;

    AnalyzeOptions ao;
    ao.dir = o.dir;
    ao.critical_ranges = o.critical_ranges;
    const CriticalData data = read_critical_data(ao);
    const auto slices = critical_slices(data.axes, data.points, data.settings.bootstrap_resamples,
                                        axis, data.settings.critical_ranges);
    out.listed_runs = refinement_runs(sw);
    out.lines.clear();
    for (const auto& s : slices)
      out.lines.push_back(name_of(axis) + " at " + slice_text(s) + ": " + fit_text(s.fit));

    // Stop?
    const bool narrow = o.until_ci && !slices.empty() &&
                        std::all_of(slices.begin(), slices.end(), [&](const CriticalSlice& s) {
                          return width(s.fit) <= *o.until_ci;
                        });
    if (!budget) {
      const std::size_t rounds = one_round ? 1 : kUntilCiRounds;
      budget =
          listed_at_start + rounds * per_round * seeds * std::max<std::size_t>(1, slices.size());
    }
    std::string stop;
    if (narrow)
      stop = "every interval of x_c is at most " + format_number(*o.until_ci) + " wide";
    else if (one_round && (interrupted || round > 0))
      stop = interrupted ? "finished the interrupted round (rerun to refine further)"
                         : "one round done (rerun, or give --budget / --until-ci, for more)";
    else if (out.listed_runs + seeds > *budget)
      stop = "run budget reached: " + std::to_string(out.listed_runs) + " refinement runs of " +
             std::to_string(*budget);

    // Proposals: per slice, seeds at the values around an interval that have too few of them
    // (or as --add says), else whole points, as many runs as the budget leaves.
    json points = sw.resolved.contains("points") ? sw.resolved["points"] : json::array();
    json extra = sw.resolved.contains("extra_seeds") ? sw.resolved["extra_seeds"] : json::array();
    std::set<std::string> existing;
    for (const auto& r : sw.runs) existing.insert(canonical_json(r.point_values));
    // New seeds are numbered after every seed of the sweep, the same ones at every point.
    std::uint64_t next_seed = 0;
    for (const auto& r : sw.runs) next_seed = std::max(next_seed, r.seed + 1);
    std::vector<std::string> log;
    std::size_t left = stop.empty() ? *budget - out.listed_runs : 0;  // runs
    std::size_t added = 0;                                            // runs
    for (const auto& s : slices) {
      const bool done = o.until_ci && width(s.fit) <= *o.until_ci;
      const auto samples = slice_samples(s, data.points);
      analysis::SeedProposal more;
      if (left > 0 && !done && o.add != "values")
        more = analysis::propose_seeds(samples, s.fit, s.options, o.add == "seeds");
      std::string added_text;
      if (!more.x.empty()) {
        // The seeds the values lack, within a round's runs (with --add seeds, as many as a
        // round's runs give), at least one; with fewer runs left than values, the values
        // nearest the middle of the chosen ones.
        auto& xs = more.x;
        const std::size_t round_runs = std::min(per_round * seeds, left);
        if (round_runs < xs.size()) {
          const double mid = (xs.front() + xs.back()) / 2;
          std::stable_sort(xs.begin(), xs.end(), [&](double a, double b) {
            return std::abs(a - mid) < std::abs(b - mid);
          });
          xs.resize(round_runs);
          std::sort(xs.begin(), xs.end());
        }
        const std::size_t fit_in = std::max<std::size_t>(1, round_runs / xs.size());
        const std::size_t per_point =
            std::min(fit_in, o.add == "seeds" ? std::max(more.seeds, fit_in) : more.seeds);
        json new_seeds = json::array();
        for (std::size_t k = 0; k < per_point; ++k) new_seeds.push_back(next_seed + k);
        std::string at;
        for (const double x : xs) {
          json point = point_at(sw, axis, s, x);
          if (point.is_null() || !existing.count(canonical_json(point))) continue;
          point["seeds"] = new_seeds;
          extra.push_back(point);
          if (!at.empty()) at += ' ';
          at += format_number(x);
          added += per_point;
          left -= std::min(left, per_point);
        }
        if (!at.empty()) {
          added_text = "seeds";
          for (const auto& seed : new_seeds) {
            added_text += ' ';
            added_text += seed.dump();
          }
          added_text += " at " + at;
        }
      } else {
        std::vector<double> xs;
        if (left >= seeds && !done && o.add != "seeds")
          xs = analysis::propose_refinement(
              samples, s.fit, static_cast<int>(std::min(per_round, left / seeds)), s.options);
        for (const double x : xs) {
          const json point = point_at(sw, axis, s, x);
          if (point.is_null() || !existing.insert(canonical_json(point)).second) continue;
          points.push_back(point);
          if (!added_text.empty()) added_text += ' ';
          added_text += format_number(x);
          added += seeds;
          left -= std::min(left, seeds);
        }
      }
      const auto& f = s.fit;
      const auto n = [](double v) { return std::isnan(v) ? std::string("nan") : format_number(v); };
      log.push_back(utc_now_iso8601() + "," + name_of(axis) + "," + csv_field(slice_text(s)) + "," +
                    std::to_string(out.listed_runs) + "," + std::to_string(f.points) + "," +
                    std::to_string(f.values) + "," + csv_field(f.status) + "," + f.model + "," +
                    n(f.x_c) + "," + n(f.x_c_lo) + "," + n(f.x_c_hi) + "," + n(width(f)) + "," +
                    csv_field(added_text));
      if (o.progress)
        *o.progress << "refine: " << name_of(axis) << " at " << slice_text(s) << ": " << fit_text(f)
                    << (added_text.empty() ? "" : "; adding " + added_text) << '\n';
    }
    append_log(dir, log);
    if (added == 0) {
      const bool usable = std::any_of(slices.begin(), slices.end(),
                                      [](const CriticalSlice& s) { return s.fit.points >= 2; });
      out.stop = !stop.empty() ? stop
                 : usable      ? "no new value or seed to add (the gaps are below the rounding)"
                               : "nothing to refine: no slice has two grid values with a finite D "
                                 "(failed runs, or a D window beyond l_max)";
      break;
    }
    // Record the new points before running them: a killed refine continues from here.
    json resolved = sw.resolved;
    if (!points.empty()) resolved["points"] = points;
    if (!extra.empty()) resolved["extra_seeds"] = extra;
    sw = parse_sweep(resolved, refined.string());
    write_file_atomic(refined.string(), sw.resolved.dump(2) + "\n");
    out.sweep_file = refined.string();
    out.added_runs += added;
    ++out.rounds;
  }
  out.listed_runs = refinement_runs(sw);
  return out;
}

}  // namespace wirepack::report
