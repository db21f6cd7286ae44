#include "sweep/running/sweep_runner.hpp"

#include <omp.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <set>
#include <thread>

#include "sweep/atomic_file.hpp"
#include "sweep/errors.hpp"
#include "sweep/format.hpp"
#include "sweep/parse_number.hpp"
#include "sweep/runfile/run_checkpoint.hpp"
#include "sweep/runfile/run_file.hpp"
#include "sweep/running/run.hpp"

namespace wirepack::sweep {

namespace fs = std::filesystem;
using clock_type = std::chrono::steady_clock;

void prepare_sweep_dir(const std::string& dir) {
  std::error_code ec;
  const fs::path runs = fs::path(dir) / "runs";
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    throw InputError(dir + ": --out must name a directory (it is a file)");
  // Shards may create it at the same moment: only its absence afterwards is an error.
  fs::create_directories(runs, ec);
  std::error_code ec2;
  if (!fs::is_directory(runs, ec2))
    throw InputError(dir + ": cannot create " + runs.string() + " (" + ec.message() + ")");
  if (::access(dir.c_str(), W_OK) != 0 || ::access(runs.c_str(), W_OK) != 0)
    throw InputError(dir + ": directory is not writable");
}

namespace {

double seconds_since(clock_type::time_point t) {
  return std::chrono::duration<double>(clock_type::now() - t).count();
}

// Shared state of one sweep invocation; every member below `mutex` is guarded by it.
class SweepState {
 public:
  SweepState(const Sweep& sweep, const SweepOptions& opt) : sweep_(sweep), opt_(opt) {}

  std::mutex mutex;
  std::vector<ManifestEntry> entries;  // this shard's runs, in run order
  std::unique_ptr<JobLog> joblog;
  std::size_t to_run = 0, started = 0, finished = 0;  // counts of this invocation
  std::size_t stopped = 0;   // runs stopped part-way (SweepOptions::stop), among `finished`
  double finished_wall = 0;  // sum of wall_s of finished runs [s]
  int threads = 1;           // concurrent runs
  int cores = 1;             // threads the sweep may use in all (--threads)

  // Threads for one run's force loops: 1 while runs wait to start; once every run has started,
  // the cores shared among the runs still going (the result does not depend on it).
  int threads_per_run() {
    std::lock_guard lock(mutex);
    if (started < to_run) return 1;
    const std::size_t running = std::max<std::size_t>(1, started - finished);
    return std::max(1, static_cast<int>(static_cast<std::size_t>(cores) / running));
  }
  bool manifest_dirty = false;
  bool changed = false;  // since the last progress line
  clock_type::time_point t0 = clock_type::now();
  clock_type::time_point last_manifest{}, last_progress = clock_type::now();
  std::vector<std::string> warnings;

  std::string path(const ManifestEntry& e) const { return (fs::path(opt_.dir) / e.run->file); }

  // Records a problem that does not stop the sweep (caller holds the mutex).
  void warn(const std::string& w) {
    warnings.push_back(w);
    if (opt_.progress) *opt_.progress << "warning: " << w << std::endl;
  }

  // Rewrites the manifest (caller holds the mutex).
  void write_manifest() {
    try {
      write_file_atomic(manifest_path(opt_.dir, opt_.shard),
                        manifest_json(sweep_, opt_.shard, entries).dump(1) + "\n");
      manifest_dirty = false;
    } catch (const std::exception& e) {
      warn(e.what());
    }
    last_manifest = clock_type::now();
  }

  // Periodic work (caller holds the mutex): a pending manifest write, a progress line.
  void tick() {
    if (manifest_dirty && seconds_since(last_manifest) >= 1.0) write_manifest();
    if (!opt_.progress) return;
    const double since = seconds_since(last_progress);
    if (since < opt_.progress_interval_s || (!changed && since < 60)) return;
    *opt_.progress << progress_line() << std::endl;
    last_progress = clock_type::now();
    changed = false;
  }

  // `sweep NAME: 12/40 done, 1 failed, 2 running, elapsed 0:10:00, ETA 0:20:00`. ETA: the mean
  // wall time of the runs finished in this invocation times the runs left, over the threads.
  std::string progress_line() const {
    std::size_t done = 0, failed = 0;
    for (const auto& e : entries) {
      done += e.status == EntryStatus::Complete || e.status == EntryStatus::Failed;
      failed += e.status == EntryStatus::Failed;
    }
    const std::size_t running = started - finished;
    double eta = -1;
    if (finished > 0)
      eta = finished_wall / static_cast<double>(finished) * static_cast<double>(to_run - finished) /
            threads;
    return "sweep " + sweep_.name + ": " + std::to_string(done) + "/" +
           std::to_string(entries.size()) + " done, " + std::to_string(failed) + " failed, " +
           std::to_string(running) + " running, elapsed " + format_duration(seconds_since(t0)) +
           ", ETA " + format_duration(eta);
  }

 private:
  const Sweep& sweep_;
  const SweepOptions& opt_;
};

// Looks at what a previous invocation left for `e`: .part leftovers are removed; a final file
// decides whether the run is finished. Returns true when the run has to be (re)done.
bool inspect(SweepState& st, ManifestEntry& e, bool retry_failed, SweepOutcome& out) {
  const std::string path = st.path(e);
  std::error_code ec;
  if (fs::exists(path + ".part", ec)) {
    // A killed run's partial file; the run starts over (from its checkpoint, if it has one).
    if (fs::remove(path + ".part", ec)) ++out.parts_removed;
  }
  if (!fs::exists(path, ec)) return true;
  RunRecord rec;
  try {
    rec = read_run_file(path);
  } catch (const std::exception& ex) {
    st.warn(path + ": unreadable (" + ex.what() + "); running it again");
    return true;
  }
  if (canonical_json(rec.config) != canonical_json(e.run->scene.resolved)) {
    st.warn(path + ": holds another configuration; running it again");
    return true;
  }
  if (rec.status == RunStatus::Running) return true;
  // The run file is final: a checkpoint left beside it (killed between the two) has served.
  fs::remove(checkpoint_path(path), ec);
  e.status = rec.status == RunStatus::Complete ? EntryStatus::Complete : EntryStatus::Failed;
  e.reason = rec.failure;
  e.started = rec.started;
  e.finished = rec.finished;
  if (const Series* w = rec.find_series("wall_s"); w && !w->values.empty())
    e.wall_s = w->values.back();
  if (e.status == EntryStatus::Failed && retry_failed) {
    e = ManifestEntry{e.run};
    return true;
  }
  ++out.found;
  return false;
}

// Removes the checkpoint temporaries (RUN.h5.ckpt.tmp.<pid>) of this shard's runs that killed
// invocations left (one scan of DIR/runs; other shards' runs are not touched).
void remove_checkpoint_temporaries(const std::string& dir, const std::vector<ManifestEntry>& mine) {
  std::set<std::string> runs;
  for (const auto& e : mine) runs.insert(fs::path(e.run->file).filename().string());
  std::error_code ec;
  for (const auto& f : fs::directory_iterator(fs::path(dir) / "runs", ec)) {
    const std::string name = f.path().filename().string();
    const auto at = name.find(".ckpt.tmp.");
    std::error_code rm;
    if (at != std::string::npos && runs.contains(name.substr(0, at))) fs::remove(f.path(), rm);
  }
}

// Removes the manifest temporaries (MANIFEST.tmp.<pid>) that killed invocations on this shard
// left; the shard's lock is held, so none of them is being written. Returns how many.
std::size_t remove_stale_temporaries(const std::string& dir, const Shard& shard) {
  const std::string prefix = fs::path(manifest_path(dir, shard)).filename().string() + ".tmp.";
  std::size_t n = 0;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    std::error_code rm;
    if (name.rfind(prefix, 0) == 0 && e.is_regular_file(rm) && fs::remove(e.path(), rm)) ++n;
  }
  return n;
}

// The run ids with a line in any joblog of DIR (every shard's: a run finished by a shard is
// not missing from the unsharded joblog).
std::set<std::string> joblog_ids(const std::string& dir) {
  std::set<std::string> ids;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (name.rfind("joblog", 0) != 0 || e.path().extension() != ".csv") continue;
    std::ifstream in(e.path());
    std::string line;
    std::getline(in, line);  // header
    while (std::getline(in, line))
      if (const auto comma = line.find(','); comma != std::string::npos)
        ids.insert(line.substr(0, comma));
  }
  return ids;
}

// One task: simulates a run and records it. Catches everything (an exception must not leave an
// OpenMP task).
void execute(SweepState& st, ManifestEntry& e, const SweepOptions& opt) noexcept {
  try {
    if (opt.stop && opt.stop->load()) return;  // stopped: the run stays pending
    const std::string path = st.path(e);
    {
      std::lock_guard lock(st.mutex);
      e.status = EntryStatus::Running;
      e.started = utc_now_iso8601();
      ++st.started;
      st.changed = true;
    }
    const auto t0 = clock_type::now();
    EntryStatus status = EntryStatus::Failed;
    std::string reason;
    double run_wall = -1;     // the run's whole wall time, a resumed run's earlier part included
    std::string run_started;  // when the run first started, as its file says (resumed: earlier)
    try {
      // The run's own progress is not shown inside a sweep (null stream).
      // A resumed run says so when it resumes (its own progress is not shown).
      const auto on_resume = [&](double l) {
        if (!opt.progress) return;
        std::lock_guard lock(st.mutex);
        *opt.progress << e.run->file << ": resumed from its checkpoint at l = "
                      << format_number(std::round(l * 1e3) / 1e3) << std::endl;
      };
      const RunOutcome r = run_scene(
          e.run->scene, path, nullptr, [&st] { return st.threads_per_run(); }, recorded_series(),
          CheckpointOptions{opt.checkpoint_every_s, opt.stop, on_resume});
      if (r.status == RunStatus::Running) {
        // Stopped part-way: pending again, to resume from its checkpoint next time.
        std::lock_guard lock(st.mutex);
        if (!r.checkpoint_note.empty()) st.warn(e.run->file + ": " + r.checkpoint_note);
        e = ManifestEntry{e.run};
        ++st.finished;
        ++st.stopped;
        st.changed = true;
        st.manifest_dirty = true;
        return;
      }
      status = r.status == RunStatus::Complete ? EntryStatus::Complete : EntryStatus::Failed;
      reason = r.failure;
      run_wall = r.wall_s;
      run_started = r.started;
      std::lock_guard lock(st.mutex);
      if (!r.checkpoint_note.empty()) st.warn(e.run->file + ": " + r.checkpoint_note);
    } catch (const RunFileError& ex) {
      reason = std::string("run file not written: ") + ex.what();
    } catch (const std::exception& ex) {
      reason = ex.what();
    } catch (...) {
      reason = "unknown error";
    }
    if (status == EntryStatus::Failed && reason.empty()) reason = "unknown error";
    const double wall = run_wall >= 0 ? run_wall : seconds_since(t0);

    std::lock_guard lock(st.mutex);
    e.status = status;
    e.reason = reason;
    e.wall_s = wall;
    e.finished = utc_now_iso8601();
    if (!run_started.empty()) e.started = run_started;  // the manifest agrees with the file
    ++st.finished;
    st.finished_wall += wall;
    st.changed = true;
    st.manifest_dirty = true;
    if (st.joblog) {
      try {
        st.joblog->append({e.run->id, e.run->file, e.started, e.finished, wall, to_string(status),
                           reason, opt.shard.text()});
      } catch (const std::exception& ex) {
        st.warn(ex.what());
      }
    }
    st.tick();
  } catch (...) {
    // Only bookkeeping can get here (allocation failure); the run file is what counts.
  }
}

// A value of a run condition: a number where the text reads as one, else the text.
nlohmann::json condition_value(const std::string& text) {
  if (const auto v = to_double(text)) return *v;
  return text;
}

bool same_value(const nlohmann::json& a, const nlohmann::json& b) {
  if (a.is_number() && b.is_number()) {
    const double x = a.get<double>(), y = b.get<double>();
    return std::abs(x - y) <= 1e-12 * std::max(std::abs(x), std::abs(y));
  }
  return a == b;
}

// The run's value of a condition's key: its seed, or its point's value of that axis.
nlohmann::json run_value(const SweepRun& run, const std::string& key) {
  if (key == "seed") return run.seed;
  const auto it = run.point_values.find(key);
  return it == run.point_values.end() ? nlohmann::json() : *it;
}

}  // namespace

RunCondition parse_run_condition(const Sweep& sweep, const std::string& text,
                                 const std::string& what) {
  const auto eq = text.find('=');
  const std::string head = what + " " + text + ": ";
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
    throw InputError(head + "must be KEY=V1,V2,... (e.g. eps=1e4 or mu_s=0.1,0.2)");
  RunCondition c{text.substr(0, eq), {}};
  std::string axes;
  bool known = c.key == "seed";
  for (const auto& a : sweep.axes) {
    const std::string k = a.key;
    axes += (axes.empty() ? "" : ", ") + k;
    known = known || k == c.key;
  }
  if (!known)
    throw InputError(head + "\"" + c.key + "\" is not an axis of sweep " + sweep.name +
                     " (axes: " + (axes.empty() ? "none" : axes) + "; or seed)");
  std::size_t from = eq + 1;
  while (from <= text.size()) {
    const auto comma = std::min(text.find(',', from), text.size());
    const std::string v = text.substr(from, comma - from);
    if (v.empty()) throw InputError(head + "an empty value");
    c.values.push_back(condition_value(v));
    const bool some = std::any_of(sweep.runs.begin(), sweep.runs.end(), [&](const SweepRun& r) {
      return same_value(run_value(r, c.key), c.values.back());
    });
    if (!some)
      throw InputError(head + "no run of sweep " + sweep.name + " has " + c.key + " = " + v);
    from = comma + 1;
  }
  return c;
}

bool meets(const SweepRun& run, const std::vector<RunCondition>& only) {
  for (const auto& c : only) {
    const nlohmann::json v = run_value(run, c.key);
    if (std::none_of(c.values.begin(), c.values.end(),
                     [&](const nlohmann::json& w) { return same_value(v, w); }))
      return false;
  }
  return true;
}

SweepOutcome run_sweep(const Sweep& sweep, const SweepOptions& opt) {
  SweepOutcome out;
  prepare_sweep_dir(opt.dir);
  DirLock lock(lock_path(opt.dir, opt.shard));

  SweepState st(sweep, opt);
  for (const auto& run : sweep.runs)
    if (opt.shard.contains(run.index)) st.entries.push_back(ManifestEntry{&run});
  out.runs = st.entries.size();

  // Resume: what is on disk decides what runs (the manifest is only a report).
  remove_checkpoint_temporaries(opt.dir, st.entries);
  std::vector<ManifestEntry*> todo;
  for (auto& e : st.entries)
    if (inspect(st, e, opt.retry_failed, out)) {
      if (meets(*e.run, opt.only))
        todo.push_back(&e);
      else
        ++out.left_out;
    }
  // Longest expected first; ties in run order (stable sort of run-ordered entries).
  std::stable_sort(todo.begin(), todo.end(), [](const ManifestEntry* a, const ManifestEntry* b) {
    return a->run->cost > b->run->cost;
  });
  st.to_run = todo.size();
  const int want = opt.threads > 0 ? opt.threads : omp_get_num_procs();
  st.threads = static_cast<int>(std::max<std::size_t>(1, std::min<std::size_t>(want, todo.size())));
  st.cores = std::max(1, want);
  out.threads = st.threads;
  out.manifest = manifest_path(opt.dir, opt.shard);

  try {
    st.joblog = std::make_unique<JobLog>(joblog_path(opt.dir, opt.shard));
  } catch (const std::exception& e) {
    st.warn(e.what());
  }
  // A run killed between its rename and its joblog line is finished on disk but not in the
  // joblog: its line is added now, from the run file's own times.
  if (st.joblog) {
    const std::set<std::string> logged = joblog_ids(opt.dir);
    for (const auto& e : st.entries) {
      if (e.status != EntryStatus::Complete && e.status != EntryStatus::Failed) continue;
      if (logged.contains(e.run->id)) continue;
      try {
        st.joblog->append({e.run->id, e.run->file, e.started, e.finished, std::max(e.wall_s, 0.0),
                           to_string(e.status), e.reason, opt.shard.text()});
        ++out.joblog_added;
      } catch (const std::exception& ex) {
        st.warn(ex.what());
        break;
      }
    }
  }
  out.temps_removed = remove_stale_temporaries(opt.dir, opt.shard);
  st.write_manifest();

  if (opt.progress) {
    std::size_t failed_kept = 0;
    for (const auto& e : st.entries) failed_kept += e.status == EntryStatus::Failed;
    std::string line = "sweep " + sweep.name + ": " + std::to_string(sweep.runs.size()) + " runs";
    if (opt.shard.count > 1)
      line += " (shard " + opt.shard.text() + ": " + std::to_string(out.runs) + ")";
    line += ", " + std::to_string(out.found - failed_kept) + " already complete";
    if (failed_kept > 0)
      line += ", " + std::to_string(failed_kept) + " failed before (kept; --retry-failed reruns)";
    if (out.parts_removed > 0)
      line += ", " + std::to_string(out.parts_removed) + " leftover .part file(s) removed";
    if (out.temps_removed > 0)
      line +=
          ", " + std::to_string(out.temps_removed) + " leftover manifest temporary file(s) removed";
    if (out.joblog_added > 0)
      line += ", " + std::to_string(out.joblog_added) + " missing joblog line(s) added";
    if (todo.empty())
      line += "; nothing to run in " + opt.dir;
    else
      line += "; running " + std::to_string(todo.size()) + " on " + std::to_string(st.threads) +
              " thread" + (st.threads == 1 ? "" : "s") + " into " + opt.dir;
    if (out.left_out > 0)
      line += " (" + std::to_string(out.left_out) + " more to do, left out by --only)";
    *opt.progress << line << std::endl;
  }

  // Progress and throttled manifest writes while the tasks run.
  std::mutex wake_mutex;
  std::condition_variable wake;
  bool stop = false;
  std::thread monitor([&] {
    std::unique_lock wl(wake_mutex);
    while (!wake.wait_for(wl, std::chrono::milliseconds(250), [&] { return stop; })) {
      wl.unlock();
      {
        std::lock_guard sl(st.mutex);
        st.tick();
      }
      wl.lock();
    }
  });

  // One task per run. Tasks may start in any order, so each takes the next run of the
  // longest-first list itself. Nested parallelism: the last runs get the idle cores for their
  // force loops (threads_per_run); Eigen is built without threads (EIGEN_DONT_PARALLELIZE).
  if (!todo.empty()) {
    std::atomic<std::size_t> next{0};
    omp_set_max_active_levels(2);
#pragma omp parallel num_threads(st.threads)
#pragma omp single
    {
      for (std::size_t t = 0; t < todo.size(); ++t) {
#pragma omp task
        execute(st, *todo[next.fetch_add(1)], opt);
      }
    }
  }

  {
    std::lock_guard wl(wake_mutex);
    stop = true;
  }
  wake.notify_all();
  monitor.join();

  std::lock_guard sl(st.mutex);
  st.manifest_dirty = true;
  st.write_manifest();
  out.ran = st.finished - st.stopped;
  out.stopped = st.stopped;
  for (const auto& e : st.entries) {
    if (e.status == EntryStatus::Complete) ++out.complete;
    if (e.status == EntryStatus::Failed) {
      ++out.failed;
      out.failures.emplace_back(e.run->file, e.reason);
    }
  }
  out.warnings = st.warnings;
  out.wall_s = seconds_since(st.t0);
  return out;
}

}  // namespace wirepack::sweep
