// Engine III micro-benchmarks (Google Benchmark): nanoseconds per shell face-step for
// (a) the membrane and bending forces alone on the default mesh of the reference scene
// (R = 10 mm, t = 1 mm, mesh 1 mm: 2.8 k faces), perturbed off its rest shape, and (b) whole
// adaptive steps of the elastic reference scene (rho = 20, xi = 10, eps = 1e3) at l ~ 5 with
// wire-shell contact, mu_s = 0 and 0.5. Peak resident memory is reported beside the time.
#include <benchmark/benchmark.h>

#include <random>

#include "bench/peak_memory.hpp"
#include "engine/shell/bending.hpp"
#include "engine/shell/membrane.hpp"
#include "engine/shell/mesh_builders.hpp"
#include "engine/simulation.hpp"

namespace {

using namespace wirepack;

using bench::peak_rss_mib;

// (a) Membrane and/or bending forces; argument: 1 membrane, 2 bending, 3 both.
void BM_ShellForces(benchmark::State& state) {
  const int which = static_cast<int>(state.range(0));
  const double R = 0.01, t = 0.001, h = 0.001;
  const ShellMesh mesh = sphere_with_hole(R, h, 1.1 * 0.5e-3 + 0.5 * t, h);
  ShellMaterial mat;
  mat.E = 1e6;
  mat.nu = 1.0 / 3.0;
  mat.t = t;
  MembraneTerm membrane(mesh, mat);
  BendingTerm bending(mesh, mat);
  Vec3List x = mesh.rest;
  std::mt19937_64 rng(5);
  std::normal_distribution<double> g(0.0, 0.02 * h);
  for (auto& p : x) p += Vec3(g(rng), g(rng), g(rng));
  Vec3List f(x.size(), Vec3::Zero());
  for (auto _ : state) {
    for (auto& fi : f) fi.setZero();
    double U = 0;
    if (which & 1) U += membrane.accumulate(x, f);
    if (which & 2) U += bending.accumulate(x, f);
    benchmark::DoNotOptimize(U);
  }
  state.counters["ns_per_face_step"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * mesh.num_faces(),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["faces"] = mesh.num_faces();
  state.counters["peak_MiB"] = peak_rss_mib();
}
BENCHMARK(BM_ShellForces)
    ->Arg(1)
    ->Arg(2)
    ->Arg(3)
    ->ArgName("membrane1_bending2")
    ->Unit(benchmark::kMicrosecond);

// (b) Whole steps of the elastic reference scene; argument: mu_s x 10. The cost per step is
// reported per shell face and per wire node (both are simulated every step).
void BM_ElasticStep(benchmark::State& state) {
  SceneParams p;
  p.shell = ShellKind::Elastic;
  p.rho = 20;
  p.xi = 10;
  p.eps = 1000;
  p.mu_s = 0.1 * static_cast<double>(state.range(0));
  p.mu_d = 0.9 * p.mu_s;
  p.l_max = 1e9;
  Simulation sim(p);
  sim.advance_to(5.0);
  const double faces = static_cast<double>(sim.shell_triangles().size());
  double face_steps = 0, node_steps = 0;
  for (auto _ : state) {
    sim.step();
    face_steps += faces;
    node_steps += static_cast<double>(sim.all_nodes().size());
  }
  state.counters["ns_per_face_step"] =
      benchmark::Counter(face_steps, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["ns_per_node_step"] =
      benchmark::Counter(node_steps, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["faces"] = faces;
  state.counters["nodes"] = static_cast<double>(sim.all_nodes().size());
  state.counters["l_end"] = sim.l();
  state.counters["peak_MiB"] = peak_rss_mib();
}
BENCHMARK(BM_ElasticStep)
    ->Arg(0)
    ->Arg(5)
    ->ArgName("mu_s_x10")
    ->Iterations(3000)
    ->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
