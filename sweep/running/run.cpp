#include "sweep/running/run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "analysis/observables.hpp"
#include "engine/simulation.hpp"
#include "engine/state_archive.hpp"
#include "sweep/atomic_file.hpp"
#include "sweep/config/sweep_config.hpp"
#include "sweep/format.hpp"
#include "sweep/runfile/run_checkpoint.hpp"
#include "sweep/runfile/shell_fields.hpp"
#include "sweep/running/thread_governor.hpp"

namespace wirepack::sweep {

const std::vector<std::string>& series_names() {
  static const std::vector<std::string> names = names_of(recorded_series());
  return names;
}

namespace {

class Recorder {
 public:
  Recorder(const Scene& scene, RunRecord& record, const SeriesList& list)
      : scene_(scene), record_(record), list_(list) {
    for (const auto& s : list_) record_.series.push_back({s.name, {}});
  }

  // One row of every series (docs/design.md §5.7) from the current state.
  void row(const Simulation& sim, double wall) {
    const SeriesContext context(sim, scene_.engine, wall);
    for (std::size_t c = 0; c < list_.size(); ++c)
      record_.series[c].values.push_back(list_[c].compute(context));
    last_row_l_ = sim.l();
  }

  // Wire (inside part), its curvature and the shell mesh at the current state.
  void snapshot(const Simulation& sim) {
    Snapshot s;
    s.l = sim.l();
    const auto x = sim.inside_nodes();
    s.wire.reserve(x.size());
    for (const auto& p : x) s.wire.push_back({p.x(), p.y(), p.z()});
    s.curvature = analysis::curvatures(x);
    for (const auto& p : sim.shell_vertices()) s.shell_vertices.push_back({p.x(), p.y(), p.z()});
    for (const auto& t : sim.shell_triangles()) s.shell_triangles.push_back(t);
    s.wire_contacts = sim.wire_contacts_per_node();
    if (!s.shell_vertices.empty()) {
      Points rest;
      for (const auto& p : sim.shell_rest_vertices()) rest.push_back({p.x(), p.y(), p.z()});
      s.shell_area_stretch = face_area_stretch(rest, s.shell_vertices, s.shell_triangles);
      for (const auto& f : sim.shell_contact_forces())
        s.shell_contact_force.push_back({f.x(), f.y(), f.z()});
      for (char c : sim.shell_clamped()) s.shell_clamped.push_back(c ? 1 : 0);
    }
    record_.snapshots.push_back(std::move(s));
    last_snapshot_l_ = sim.l();
  }

  double last_row_l() const { return last_row_l_; }
  double last_snapshot_l() const { return last_snapshot_l_; }
  // A resumed run: the rows and snapshots so far are in the record already.
  void resume(double last_row_l, double last_snapshot_l) {
    last_row_l_ = last_row_l;
    last_snapshot_l_ = last_snapshot_l;
  }

 private:
  const Scene& scene_;
  RunRecord& record_;
  const SeriesList& list_;
  double last_row_l_ = -1;
  double last_snapshot_l_ = -1;
};

// `l = 12.3 / 20  wall 0:00:41  ETA 0:00:26`, ETA from the mean rate of l per wall second.
std::string progress_line(double l, double l_max, double wall, bool done = false) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "l = %.1f / ", l);
  std::string line = buf + format_number(l_max) + "  wall " + format_duration(wall);
  if (done) return line;
  const double eta = l > 0 && wall > 0 ? (l_max - l) / (l / wall) : -1;
  return line + "  ETA " + format_duration(eta);
}

}  // namespace

RunOutcome run_scene(const Scene& scene, const std::string& out_path, std::ostream* progress,
                     const std::function<int()>& threads, const SeriesList& series,
                     const CheckpointOptions& checkpoint) {
  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();
  double wall_before = 0;  // wall time of the run's part before the checkpoint it resumed [s]
  const auto wall = [&] {
    return wall_before + std::chrono::duration<double>(clock::now() - t0).count();
  };
  const double every = scene.output.every_l;
  const double snap_every = scene.output.snapshots_every_l;
  const double l_max = scene.engine.l_max;
  const bool checkpoints = checkpoint.every_s > 0;
  const std::string ckpt_path = checkpoint_path(out_path);

  RunRecord record;
  record.config = scene.resolved;
  record.version = build_version();
  record.git = build_git();
  record.started = utc_now_iso8601();
  Recorder rec(scene, record, series);
  RunOutcome out;
  double next_row = 0, next_snap = 0;

  // Resumes from the checkpoint at ckpt_path into `sim`, the record and the sampling points;
  // false (with the reason in out.checkpoint_note) when it cannot be used: the run then starts
  // at l = 0 with a fresh simulation, and the checkpoint is overwritten by the next one.
  const auto resume = [&](std::unique_ptr<Simulation>& sim) {
    try {
      RunCheckpoint c = read_checkpoint(ckpt_path);
      if (c.config != canonical_json(scene.resolved))
        throw CheckpointError(ckpt_path + ": holds another configuration");
      if (c.record.series.size() != series.size())
        throw CheckpointError(ckpt_path + ": records other series");
      for (std::size_t k = 0; k < series.size(); ++k) {
        if (c.record.series[k].name != series[k].name)
          throw CheckpointError(ckpt_path + ": records other series");
      }
      sim->restore_state(c.engine);
      record.series = std::move(c.record.series);
      record.snapshots = std::move(c.record.snapshots);
      record.started = c.record.started;
      rec.resume(c.last_row_l, c.last_snapshot_l);
      next_row = c.next_row;
      next_snap = c.next_snapshot;
      wall_before = c.wall_s;
      out.resumed_l = sim->l();
      return true;
    } catch (const std::exception& e) {
      out.checkpoint_note = std::string("checkpoint not used: ") + e.what();
      sim = std::make_unique<Simulation>(scene.engine);  // a failed restore leaves it unusable
      return false;
    }
  };
  // Writes the checkpoint; a failure (a full disk) is noted and the run goes on.
  const auto save = [&](const Simulation& sim) {
    RunCheckpoint c;
    c.config = canonical_json(scene.resolved);
    c.wall_s = wall();
    c.next_row = next_row;
    c.next_snapshot = next_snap;
    c.last_row_l = rec.last_row_l();
    c.last_snapshot_l = rec.last_snapshot_l();
    c.engine = sim.save_state();
    c.record = std::move(record);  // moved back below, also on failure
    try {
      write_checkpoint(c, ckpt_path);
    } catch (const std::exception& e) {
      const bool first = out.checkpoint_note.empty();
      out.checkpoint_note = std::string("checkpoint not written: ") + e.what();
      if (progress && first) *progress << out.checkpoint_note << std::endl;
    }
    record = std::move(c.record);
  };

  std::unique_ptr<Simulation> sim;
  try {
    sim = std::make_unique<Simulation>(scene.engine);
    std::error_code ec;
    const bool resumed = checkpoints && std::filesystem::exists(ckpt_path, ec) && resume(sim);
    if (progress && !out.checkpoint_note.empty()) *progress << out.checkpoint_note << std::endl;
    if (resumed) {
      if (checkpoint.on_resume) checkpoint.on_resume(sim->l());
      if (progress)
        *progress << "resumed from the checkpoint at l = "
                  << format_number(std::round(sim->l() * 1e3) / 1e3) << std::endl;
    } else {
      rec.row(*sim, wall());
      rec.snapshot(*sim);
      // Next samples at integer multiples of the intervals (no drift from accumulation).
      next_row = every * (std::floor(sim->l() / every) + 1);
      next_snap = snap_every * (std::floor(sim->l() / snap_every) + 1);
    }
    ThreadGovernor governor;  // threads window by window, up to threads()
    long window_steps = 0;    // steps of the window being run
    double window_s = 0;      // wall time of its steps [s]
    if (threads) sim->set_threads(governor.next(threads()));
    double next_report = wall() + 2.0;
    double next_checkpoint = wall() + checkpoint.every_s;
    while (!sim->finished()) {
      if (checkpoint.stop && checkpoint.stop->load(std::memory_order_relaxed)) {
        // Stopped from outside: keep the work in the checkpoint, write no run file.
        if (checkpoints) save(*sim);
        out.l = sim->l();
        out.steps = sim->steps();
        out.wall_s = wall();
        if (progress) {
          *progress << "stopped at l = " << format_number(std::round(out.l * 1e3) / 1e3);
          if (checkpoints && out.checkpoint_note.empty())
            *progress << "; checkpoint " << ckpt_path << " written: the same command resumes";
          *progress << std::endl;
        }
        return out;  // status Running
      }
      if (threads && (window_steps >= ThreadGovernor::kWindowSteps || governor.lost(window_s))) {
        // A window ends, or is cut short (a probe that has lost, a choice that slowed down): time
        // it (steps only, not the output), then pick the next window's threads
        // (sweep/running/thread_governor.hpp).
        governor.record(window_s / static_cast<double>(std::max(1L, window_steps)));
        window_steps = 0;
        window_s = 0;
        sim->set_threads(governor.next(threads()));
      }
      const auto s0 = clock::now();
      const long steps_before = sim->steps();
      sim->step();
      window_s += std::chrono::duration<double>(clock::now() - s0).count();
      window_steps += sim->steps() - steps_before;
      const double l = sim->l();
      if (l >= next_row) {
        rec.row(*sim, wall());
        next_row = every * (std::floor(l / every) + 1);
      }
      if (l >= next_snap) {
        rec.snapshot(*sim);
        next_snap = snap_every * (std::floor(l / snap_every) + 1);
      }
      if (checkpoints && wall() >= next_checkpoint) {
        save(*sim);
        next_checkpoint = wall() + checkpoint.every_s;
      }
      if (progress && wall() >= next_report) {
        // The last recorded D and N, so a user sees the morphology emerge.
        const Series* D = record.find_series("D");
        const Series* N = record.find_series("N");
        *progress << progress_line(l, l_max, wall());
        if (D && N && !D->values.empty())
          *progress << "  D " << format_number(std::round(D->values.back() * 1e3) / 1e3) << "  N "
                    << format_number(N->values.back());
        *progress << std::endl;
        next_report = wall() + 2.0;
      }
    }
    if (rec.last_row_l() != sim->l()) rec.row(*sim, wall());
    if (rec.last_snapshot_l() != sim->l()) rec.snapshot(*sim);
    record.status = RunStatus::Complete;
  } catch (const std::exception& e) {
    // The failed state itself is not recorded (it may hold NaN); the series so far are.
    record.status = RunStatus::Failed;
    record.failure = e.what();
    if (record.failure.empty()) record.failure = "unknown error";
  }
  record.finished = utc_now_iso8601();

  out.status = record.status;
  out.failure = record.failure;
  out.started = record.started;
  out.l = sim ? sim->l() : 0.0;
  out.steps = sim ? sim->steps() : 0;
  out.wall_s = wall();
  if (progress) {
    if (out.status == RunStatus::Complete)
      *progress << progress_line(out.l, l_max, out.wall_s, true) << "  done, " << out.steps
                << " steps" << std::endl;
    else
      *progress << "run failed at l = " << format_number(out.l) << ": " << out.failure << std::endl;
  }
  write_run_file(record, out_path);
  // The run file is whole: its checkpoint has served (kept if the write above threw, so that a
  // rerun resumes near the end).
  if (checkpoints) {
    std::error_code ec;
    std::filesystem::remove(ckpt_path, ec);
  }
  return out;
}

}  // namespace wirepack::sweep
