// Effects on demand, measured (issue 7): the cost of one adaptive step of the same scene
// (rho = 20, seed 1, injected to l = 4, where the wire touches the shell and itself) with each
// effect on and off: rigid sphere vs elastic shell (xi = 10, eps = 1e3), friction (mu_s = 0.5),
// twist degrees of freedom, shell self-contact. An effect that is off must cost nothing: its
// term is not assembled (tests/engine assert the term lists; here the time). The label lists
// the terms assembled; counters: us per step, ns per wire node-step, shell faces (0: no mesh
// was built), peak resident memory.
#include <benchmark/benchmark.h>

#include <string>

#include "bench/peak_memory.hpp"
#include "engine/simulation.hpp"

namespace {

using namespace wirepack;

using bench::peak_rss_mib;

struct Variant {
  const char* name;
  bool elastic;
  double mu_s;
  EffectMode twist;
  EffectMode shell_self;
};

// In the order of the effect-cost table in docs/measurements.md ("Effects on demand").
const Variant kVariants[] = {
    {"rigid", false, 0.0, EffectMode::Auto, EffectMode::Auto},
    {"rigid, shell_self_contact on (a rigid sphere cannot fold)", false, 0.0, EffectMode::Auto,
     EffectMode::On},
    {"rigid + twist", false, 0.0, EffectMode::On, EffectMode::Auto},
    {"rigid + friction (twist off)", false, 0.5, EffectMode::Off, EffectMode::Auto},
    {"rigid + friction + twist", false, 0.5, EffectMode::Auto, EffectMode::Auto},
    {"elastic, shell self-contact off", true, 0.0, EffectMode::Auto, EffectMode::Off},
    {"elastic", true, 0.0, EffectMode::Auto, EffectMode::Auto},
    {"elastic + friction (twist off)", true, 0.5, EffectMode::Off, EffectMode::Auto},
    {"elastic + friction + twist", true, 0.5, EffectMode::Auto, EffectMode::Auto},
};

void BM_EffectStep(benchmark::State& state) {
  const Variant& v = kVariants[state.range(0)];
  SceneParams p;
  p.shell = v.elastic ? ShellKind::Elastic : ShellKind::Rigid;
  p.rho = 20;
  p.xi = 10;
  p.eps = 1000;
  p.mu_s = v.mu_s;
  p.mu_d = 0.9 * v.mu_s;
  p.numerics.twist = v.twist;
  p.numerics.shell_self_contact = v.shell_self;
  p.l_max = 1e9;
  Simulation sim(p);
  sim.advance_to(4.0);
  double node_steps = 0;
  for (auto _ : state) {
    sim.step();
    node_steps += static_cast<double>(sim.all_nodes().size());
  }
  std::string terms;
  for (const auto& t : sim.term_names()) terms += (terms.empty() ? "" : "+") + t;
  state.SetLabel(std::string(v.name) + ": " + terms);
  state.counters["ns_per_node_step"] =
      benchmark::Counter(node_steps, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["faces"] = static_cast<double>(sim.shell_triangles().size());
  state.counters["nodes"] = static_cast<double>(sim.all_nodes().size());
  state.counters["peak_MiB"] = peak_rss_mib();
}
BENCHMARK(BM_EffectStep)
    ->DenseRange(0, static_cast<int>(std::size(kVariants)) - 1)
    ->ArgName("variant")
    ->Iterations(2000)
    ->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
