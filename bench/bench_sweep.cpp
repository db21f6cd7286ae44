// Parallel efficiency of the sweep driver (issue 5): one sweep of equal runs (a rigid sphere,
// rho = 20, l_max = 12, default numerics, 8 seeds; ~1 s per run) run at 1 thread and at every
// core. Efficiency = T_1 / (p T_p); the target is >= 90 % on 2 cores. Each iteration writes a
// fresh sweep directory (HDF5 run files included) under $TMPDIR. Run it on an idle machine:
// other processes on the cores lower the efficiency but hardly the occupancy and cpu_ratio.
#include <benchmark/benchmark.h>
#include <omp.h>
#include <sys/resource.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "sweep/config/sweep_config.hpp"
#include "sweep/running/sweep_runner.hpp"

namespace {

using namespace wirepack::sweep;

const Sweep& equal_runs() {
  static const Sweep sw =
      parse_sweep({{"name", "bench"},
                   {"base", {{"rho", 20}, {"mu_s", 0}, {"shell", "rigid"}, {"l_max", 12}}},
                   {"grid", nlohmann::json::object()},
                   {"seeds", 8}},
                  "<bench>");
  return sw;
}

std::string fresh_dir() {
  std::string tmpl = (std::filesystem::temp_directory_path() / "wirepack_bench_XXXXXX").string();
  if (!::mkdtemp(tmpl.data())) throw std::runtime_error("mkdtemp failed");
  return tmpl;
}

double t1_wall = 0;  // wall time at 1 thread [s], from the first benchmark
double t1_cpu = 0;   // CPU time at 1 thread [s]

// User + system CPU time of the whole process so far [s].
double process_cpu_s() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

void BM_SweepEqualRuns(benchmark::State& state) {
  const int threads = static_cast<int>(state.range(0));
  const Sweep& sw = equal_runs();
  double wall = 0, cpu = 0;
  for (auto _ : state) {
    const std::string dir = fresh_dir();
    SweepOptions opt;
    opt.dir = dir;
    opt.threads = threads;
    const double cpu0 = process_cpu_s();
    const SweepOutcome o = run_sweep(sw, opt);
    cpu = process_cpu_s() - cpu0;
    wall = o.wall_s;
    // Occupancy: the runs' own wall times over threads x sweep wall time (1 = no idle thread,
    // no driver overhead); unlike the efficiency it does not see contention between the runs.
    std::ifstream in(o.manifest);
    const auto m = nlohmann::json::parse(in);
    double busy = 0;
    for (const auto& r : m["runs"]) busy += r["wall_s"].get<double>();
    state.counters["occupancy"] = busy / (threads * wall);
    std::filesystem::remove_all(dir);
    if (o.complete != sw.runs.size()) state.SkipWithError("a run failed");
  }
  state.counters["runs"] = static_cast<double>(sw.runs.size());
  state.counters["wall_s"] = wall;
  state.counters["cpu_s"] = cpu;
  if (threads == 1) {
    t1_wall = wall;
    t1_cpu = cpu;
  }
  if (threads > 1 && t1_wall > 0) {
    state.counters["efficiency"] = t1_wall / (threads * wall);
    // The work a run costs in parallel relative to alone (caches, memory bandwidth, the HDF5
    // lock); times the occupancy it estimates the efficiency on an otherwise idle machine.
    state.counters["cpu_ratio"] = t1_cpu / cpu;
    state.counters["idle_estimate"] = t1_cpu / cpu * state.counters["occupancy"];
  }
}
BENCHMARK(BM_SweepEqualRuns)
    ->ArgName("threads")
    ->Apply([](benchmark::internal::Benchmark* b) {
      b->Arg(1);
      if (omp_get_num_procs() > 1) b->Arg(omp_get_num_procs());
    })
    ->Iterations(1)
    ->UseRealTime()
    ->Unit(benchmark::kSecond);

}  // namespace

BENCHMARK_MAIN();
