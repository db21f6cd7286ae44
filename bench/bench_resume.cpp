// Whole adaptive steps from a run's checkpoint, i.e. at a late, packed state of a real run (a
// committed campaign checkpoint: hundreds of wire-shell contacts with friction), where a step
// costs what it costs in the campaign and not what it costs at l ~ 5. Prints the wall time per
// step (median and best of the repeats), the l reached, the peak memory and a hash of the state
// after the steps: two binaries or two thread counts that print the same hash stepped bitwise
// alike. Each repeat restores the checkpoint again, so every repeat does the same work.
//   bench_resume CHECKPOINT [STEPS=2000] [THREADS=1] [REPEATS=3]
// Run it with GOMP_SPINCOUNT=300000 for THREADS > 1, as `wirepack run` sets for itself.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "bench/peak_memory.hpp"
#include "engine/simulation.hpp"
#include "sweep/config/scene_config.hpp"
#include "sweep/config/sweep_config.hpp"
#include "sweep/runfile/run_checkpoint.hpp"

int main(int argc, char** argv) {
  using namespace wirepack;
  if (argc < 2 || argc > 5) {
    std::fprintf(stderr, "usage: bench_resume CHECKPOINT [STEPS=2000] [THREADS=1] [REPEATS=3]\n");
    return 2;
  }
  try {
    const std::string path = argv[1];
    const long steps = argc > 2 ? std::stol(argv[2]) : 2000;
    const int threads = argc > 3 ? std::stoi(argv[3]) : 1;
    const int repeats = argc > 4 ? std::stoi(argv[4]) : 3;
    if (steps < 1 || threads < 1 || repeats < 1) throw std::invalid_argument("counts must be >= 1");
    const sweep::RunCheckpoint c = sweep::read_checkpoint(path);
    // The canonical JSON writes every number as a double; the schema wants an integer seed.
    nlohmann::json config = nlohmann::json::parse(c.config);
    if (config.contains("seed")) config["seed"] = static_cast<long>(config["seed"].get<double>());
    const sweep::Scene scene = sweep::parse_scene(config, path);
    std::vector<double> per_step;  // [s]
    double l0 = 0, l1 = 0;
    std::uint64_t hash = 0;
    for (int k = 0; k < repeats; ++k) {
      Simulation sim(scene.engine);
      sim.set_threads(threads);
      sim.restore_state(c.engine);
      l0 = sim.l();
      const auto t0 = std::chrono::steady_clock::now();
      for (long i = 0; i < steps; ++i) sim.step();
      const auto t1 = std::chrono::steady_clock::now();
      per_step.push_back(std::chrono::duration<double>(t1 - t0).count() / steps);
      l1 = sim.l();
      const std::uint64_t h = sweep::fnv1a64(sim.save_state());
      if (k > 0 && h != hash) throw std::runtime_error("repeats ended in different states");
      hash = h;
    }
    std::sort(per_step.begin(), per_step.end());
    std::printf(
        "%s: %ld steps from l = %.4f to %.4f on %d thread(s): median %.1f us/step, best %.1f "
        "us/step (%d repeats), peak memory %.1f MiB, state hash %016llx\n",
        path.c_str(), steps, l0, l1, threads, 1e6 * per_step[per_step.size() / 2],
        1e6 * per_step.front(), repeats, bench::peak_rss_mib(),
        static_cast<unsigned long long>(hash));
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_resume: %s\n", e.what());
    return 1;
  }
}
