// Engine I micro-benchmarks (Google Benchmark): nanoseconds per wire node-step for
// (a) the elastic forces alone and (b) a whole adaptive step with wall and self-contact at a
// packed state (rho = 20, l ~ 10 and 18). Peak resident memory is reported beside the time.
#include <benchmark/benchmark.h>

#include <random>

#include "bench/peak_memory.hpp"
#include "engine/rod/bend.hpp"
#include "engine/rod/frames.hpp"
#include "engine/rod/material.hpp"
#include "engine/rod/stretch.hpp"
#include "engine/rod/twist.hpp"
#include "engine/simulation.hpp"

namespace {

using namespace wirepack;

using bench::peak_rss_mib;

State random_walk_rod(int n, bool twist) {
  std::mt19937_64 rng(3);
  std::normal_distribution<double> g(0.0, 1.0);
  const double ell = 0.5e-3;
  State s;
  Vec3 dir(0, 0, 1);
  s.x.push_back(Vec3::Zero());
  for (int i = 1; i < n; ++i) {
    dir = (dir + 0.2 * Vec3(g(rng), g(rng), g(rng))).normalized();
    s.x.push_back(s.x.back() + ell * dir);
  }
  s.v.assign(n, Vec3::Zero());
  s.rest_length.assign(n - 1, ell);
  s.n_free = n;
  if (twist) {
    s.theta.assign(n - 1, 0.0);
    s.omega.assign(n - 1, 0.0);
    init_reference_frames(s, 0);
  }
  return s;
}

// (a) Elastic forces only: stretch + bend (+ twist with reference-frame update).
void BM_ElasticForces(benchmark::State& state) {
  const bool twist = state.range(0) != 0;
  const int n = 2000;
  State s = random_walk_rod(n, twist);
  const RodMaterial m = RodMaterial::from(WireParams{});
  StretchTerm stretch(m.EA());
  BendTerm bend(m.EI());
  TwistTerm tw(m.GJ());
  Forces f;
  for (auto _ : state) {
    f.reset(s);
    double U = stretch.accumulate(s, f) + bend.accumulate(s, f);
    if (twist) {
      update_reference_frames(s, f);  // as the simulation does, from reset()'s tangents
      U += tw.accumulate(s, f);
    }
    benchmark::DoNotOptimize(U);
  }
  state.counters["ns_per_node_step"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * n,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["peak_MiB"] = peak_rss_mib();
}
BENCHMARK(BM_ElasticForces)->Arg(0)->Arg(1)->ArgName("twist")->Unit(benchmark::kMicrosecond);

// (b) Whole steps (predictor, all terms, damping, corrector, feeder) at a packed state;
// arguments: mu_s x 10 (friction and twist are on for mu_s > 0) and the injected length l of
// the state (at l = 10 the strands are apart, N = 0; at l = 18 the coil's windings touch).
void BM_PackedStep(benchmark::State& state) {
  SceneParams p;
  p.shell = ShellKind::Rigid;
  p.rho = 20;
  p.mu_s = 0.1 * static_cast<double>(state.range(0));
  p.mu_d = 0.9 * p.mu_s;
  p.l_max = 1e9;
  Simulation sim(p);
  sim.advance_to(static_cast<double>(state.range(1)));
  double node_steps = 0;
  for (auto _ : state) {
    sim.step();
    node_steps += static_cast<double>(sim.all_nodes().size());
  }
  state.counters["ns_per_node_step"] =
      benchmark::Counter(node_steps, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["nodes"] = static_cast<double>(sim.all_nodes().size());
  state.counters["N_contacts"] = sim.wire_contacts();
  state.counters["l_end"] = sim.l();
  state.counters["peak_MiB"] = peak_rss_mib();
}
BENCHMARK(BM_PackedStep)
    ->Args({0, 10})
    ->Args({10, 10})
    ->Args({0, 18})
    ->Args({10, 18})
    ->ArgNames({"mu_s_x10", "l"})
    ->Iterations(5000)
    ->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
