// Hard-scene suite (issue 19, part 1; label "slow"): the 16 corners of rho in {10, 40},
// xi in {10, 200}, eps in {1, 1e4}, mu_s in {0, 1.5}, the head-on tip into the stiffest shell,
// the densest long runs (rho = 10, rigid and elastic), the coarsest and finest numerics presets
// at one corner, Engine VI's absolute damping and inertial preset and the neo-Hookean shell at
// three of them. Each scene runs to an l_max chosen to take well under a minute of CPU on the
// 2-core development machine (docs/reference.md "Hard scenes"; the table of one measured run is
// in docs/measurements.md "Hard scenes"). What each scene must show:
//   - it ends, within its budget of CPU time: complete, or failed with a reason; the only
//     failures accepted are the ones that say "this run cannot continue" (the step collapsed,
//     the packing jams the feed, or the budget was spent), never NaN/Inf or a wire through the
//     wall or the shell;
//   - no NaN/Inf in the wire, the shell or the energies (checked every 20 steps and at the end);
//   - every released node inside the shell: the rigid sphere |x| < R, the elastic shell by its
//     winding number (engine/shell/winding.hpp) against the deformed mesh, 20 times per run and
//     at the end (the engine itself checks every max(100, 4 n) steps);
//   - energy bounded by the feeder's work: E(t) - E(0) <= 1.02 W(t) (Simulation::feeder_work());
//   - overlaps (largest over every accepted step): wire-wire and wire-wall (nodes past the
//     entrance) below r, wire-shell reported (the engine fails a run whose wire axis reaches
//     the shell's mid-surface).
// One line per scene starting with HARD_SCENE (CSV) gives the figures of the table in
// docs/measurements.md "Hard scenes".
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <limits>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "engine/shell/winding.hpp"
#include "engine/simulation.hpp"
#include "sweep/config/scene_config.hpp"

namespace wirepack::sweep {
namespace {

using nlohmann::json;

struct HardScene {
  std::string name;  // test name
  json scene;        // the scene file's content (parse_scene fills the defaults)
  // Budget of CPU time [s]: past it the run ends as failed ("budget spent"), not as a hang.
  // CPU rather than wall time: on the shared machine a run gets 10-90 % of a core, and the
  // work a scene needs should not decide its outcome.
  double budget_s = 120.0;
  // Where set, the run must end failed with this reason (the engine's check at work).
  std::string expect_failure = {};
};
// gtest names the parameter by the scene (not its bytes).
void PrintTo(const HardScene& s, std::ostream* os) {
  *os << s.name;
}

// Overlap bound, in units of r, for wire-wire and wire-wall contacts: half-way to a
// pass-through (two capsules cross at 2 r; a node centre leaves the rigid sphere at r). The
// fast suite holds the rigid ones to 0.15 r and 0.3 r. The wire-shell overlap is only
// reported: its limit, the wire's axis at the shell's mid-surface (overlap r + t/2), is the
// engine's own failure check, whose reason the test does not accept; against a soft shell
// (eps = 1e4) the Hertz overlap is legitimately above r (the wire indents the soft material).
constexpr double kMaxOverlap = 1.0;
// Energy bound: E(t) - E(0) <= W(t) + kEnergySlack * W(t). The slack covers the feeder work's
// quadrature (trapezoid over the steps, the damping force at the predicted velocity), which
// is O(dt^2) per step; damping and friction remove more (measured: E/W <= 0.99 at any time of
// any scene, in the jammed rigid l = 100 run, <= 0.97 in the others, the largest early in a
// run, when W is still small; 0.01-0.9 at the end).
constexpr double kEnergySlack = 0.02;
// The inside test skips the entrance: nodes within 3 r above the south pole (the engine's own
// test skips z < z_hole + 2 r; the hole's rim is at ~0.05 r above the pole).
constexpr double kHoleSkip = 3.0;

struct Outcome {
  bool complete = false;
  std::string failure;  // the SimulationError's reason, or the budget
  bool budget_spent = false;
  double l = 0, wall_s = 0;  // injected length reached / R, wall time [s]
  double cpu_s = 0;          // CPU time of the process over the run [s] (one thread)
  long steps = 0;
  double dt_min = std::numeric_limits<double>::infinity(), dt_end = 0;  // [s]
  ContactOverlaps overlap;              // largest over every accepted step [m]
  double wall_past_entrance = 0;        // the wall's, nodes in the entrance left out [m]
  double energy_ratio_max = 0;          // max over samples of (E - E0) / W
  double energy_ratio_end = 0;          // the same at the last state
  std::vector<std::string> violations;  // invariant violations, with the l they happened at
};

double total(const Energies& e) {
  return e.U_b + e.U_t + e.U_s + e.U_m + e.U_sb + e.U_contact + e.E_kin;
}

bool finite_state(const Simulation& sim) {
  for (const Vec3& x : sim.all_nodes())
    if (!x.allFinite()) return false;
  for (const Vec3& x : sim.shell_vertices())
    if (!x.allFinite()) return false;
  return std::isfinite(total(sim.energies())) && std::isfinite(sim.feeder_work());
}

// The first released node outside the shell (-1: none). Rigid: the centre beyond R; elastic:
// winding number below 1/2 against the current mesh.
int node_outside(const Simulation& sim, const ShellWinding* winding) {
  const double R = sim.params().R(), r = sim.params().wire.radius;
  const auto x = sim.inside_nodes();
  Vec3List shell(sim.shell_vertices().begin(), sim.shell_vertices().end());
  for (int i = 0; i < static_cast<int>(x.size()); ++i) {
    if (x[i][2] < -R + kHoleSkip * r) continue;
    const bool inside = winding ? (*winding)(x[i], shell) >= 0.5 : x[i].norm() < R;
    if (!inside) return i;
  }
  return -1;
}

// Largest overlap |x| + r - R of a released node with the rigid sphere, the nodes in the
// entrance (kHoleSkip) left out: there a jammed feed may push the last node back out of the
// hole (docs/measurements.md "Hard scenes"), which is no node leaving the cavity through its
// wall [m].
double wall_overlap(const Simulation& sim) {
  const double R = sim.params().R(), r = sim.params().wire.radius;
  double worst = 0.0;
  for (const Vec3& x : sim.inside_nodes())
    if (x[2] >= -R + kHoleSkip * r) worst = std::max(worst, x.norm() + r - R);
  return worst;
}

std::string at(const Simulation& sim) {
  char buf[48];
  std::snprintf(buf, sizeof(buf), " at l = %.3f", sim.l());
  return buf;
}

Outcome run_scene_checked(const Scene& scene, double budget_s) {
  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();
  const auto wall = [&] { return std::chrono::duration<double>(clock::now() - t0).count(); };
  const std::clock_t c0 = std::clock();
  const auto cpu = [&] { return static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC; };
  Outcome out;
  Simulation sim(scene.engine);
  const double l_max = scene.engine.l_max;
  // The winding test's mesh: the run's faces (the rest positions are not used by it).
  ShellMesh mesh;
  std::unique_ptr<ShellWinding> winding;
  if (!sim.shell_triangles().empty()) {
    mesh.rest.assign(sim.shell_vertices().begin(), sim.shell_vertices().end());
    mesh.faces.assign(sim.shell_triangles().begin(), sim.shell_triangles().end());
    mesh.clamped.assign(mesh.rest.size(), 0);
    mesh.build_topology();
    winding = std::make_unique<ShellWinding>(mesh);
  }
  const auto violate = [&](const std::string& what) {
    if (out.violations.size() < 10) out.violations.push_back(what + at(sim));
  };
  const double E0 = total(sim.energies());
  const auto check_energy = [&] {
    if (!finite_state(sim)) {
      violate("non-finite state or energy");
      return false;
    }
    const double dE = total(sim.energies()) - E0, W = sim.feeder_work();
    if (dE > (1.0 + kEnergySlack) * W)
      violate("energy gain " + std::to_string(dE) + " J above the feeder's work " +
              std::to_string(W) + " J");
    if (W > 0) {
      out.energy_ratio_end = dE / W;
      out.energy_ratio_max = std::max(out.energy_ratio_max, dE / W);
    }
    return true;
  };
  double next_inside = l_max / 20, next_report = 10.0;
  try {
    while (!sim.finished()) {
      sim.step();
      const ContactOverlaps o = sim.max_overlaps();
      out.overlap.wire_wire = std::max(out.overlap.wire_wire, o.wire_wire);
      out.overlap.wall = std::max(out.overlap.wall, o.wall);
      if (!winding) out.wall_past_entrance = std::max(out.wall_past_entrance, wall_overlap(sim));
      out.overlap.wire_shell = std::max(out.overlap.wire_shell, o.wire_shell);
      out.dt_min = std::min(out.dt_min, sim.dt());
      if (sim.steps() % 20 == 0 && !check_energy()) break;
      if (sim.l() >= next_inside) {
        if (const int i = node_outside(sim, winding.get()); i >= 0)
          violate("node " + std::to_string(i) + " outside the shell");
        next_inside += l_max / 20;
      }
      if (sim.steps() % 16 != 0) continue;
      if (cpu() > next_report) {
        std::printf("  l = %.2f  %ld steps  dt %.3g s  CPU %.0f s  wall %.0f s\n", sim.l(),
                    sim.steps(), sim.dt(), cpu(), wall());
        std::fflush(stdout);
        next_report += 10.0;
      }
      if (cpu() > budget_s) {
        char buf[160];
        std::snprintf(buf, sizeof(buf),
                      "budget of %.0f s of CPU spent at l = %.3f (dt = %.3g s, %ld steps)",
                      budget_s, sim.l(), sim.dt(), sim.steps());
        out.failure = buf;
        out.budget_spent = true;
        break;
      }
    }
    out.complete = sim.finished() && out.failure.empty();
    if (out.complete) {
      // The last state: finite, inside, energy (whatever the sampling missed).
      check_energy();
      if (const int i = node_outside(sim, winding.get()); i >= 0)
        violate("node " + std::to_string(i) + " outside the shell at the end");
    }
  } catch (const std::exception& e) {
    out.failure = e.what();
    if (out.failure.empty()) out.failure = "unknown error";
  }
  out.l = sim.l();
  out.steps = sim.steps();
  out.dt_end = sim.dt();
  out.wall_s = wall();
  out.cpu_s = cpu();
  return out;
}

// The reasons a run may legitimately stop early: it cannot continue at an affordable cost.
bool cannot_continue(const Outcome& o) {
  return o.budget_spent || o.failure.find("time step collapsed") != std::string::npos ||
         o.failure.find("the packing jams the feed") != std::string::npos;
}

json elastic(double rho, double xi, double eps, double mu_s, double l_max) {
  return {{"rho", rho}, {"xi", xi}, {"eps", eps}, {"mu_s", mu_s}, {"l_max", l_max}};
}

std::vector<HardScene> hard_scenes() {
  std::vector<HardScene> s;
  // The 16 corners. rho = 10 at the default numerics; rho = 40 at the fast preset: its sphere
  // at the default mesh has ~11.6 k faces (4x rho = 20's) and needs ~40 s of CPU per unit l,
  // so one minute would end before the head-on contact at l ~ 2; the fast preset's 4 r mesh
  // (~2.9 k faces) reaches l = 2.5, past it. l_max: thin (xi = 200) and soft (eps = 1e4)
  // shells take smaller steps (docs/measurements.md "Hard scenes"), friction adds twist.
  struct Corner {
    double rho, xi, eps, mu_s, l_max;
  };
  const Corner corners[] = {
      {10, 10, 1, 0, 15},       {10, 10, 1, 1.5, 12},   {10, 10, 1e4, 0, 8},
      {10, 10, 1e4, 1.5, 8},    {10, 200, 1, 0, 8},     {10, 200, 1, 1.5, 6},
      {10, 200, 1e4, 0, 5},     {10, 200, 1e4, 1.5, 5}, {40, 10, 1, 0, 2.5},
      {40, 10, 1, 1.5, 2.5},    {40, 10, 1e4, 0, 2.5},  {40, 10, 1e4, 1.5, 2.5},
      {40, 200, 1, 0, 2.5},     {40, 200, 1, 1.5, 2.5}, {40, 200, 1e4, 0, 2.5},
      {40, 200, 1e4, 1.5, 2.5},
  };
  for (const Corner& c : corners) {
    char name[64];
    std::snprintf(name, sizeof(name), "rho%g_xi%g_eps%g_mu%g", c.rho, c.xi, c.eps, c.mu_s);
    std::string n = name;
    std::replace(n.begin(), n.end(), '.', 'p');
    json j = elastic(c.rho, c.xi, c.eps, c.mu_s, c.l_max);
    if (c.rho > 20) j["numerics"] = "fast";
    s.push_back({n, j});
  }
  // The straight wire reaches the north pole at l ~ 2 and pushes head-on into the stiffest
  // elastic shell (thick, xi = 10, and as stiff as the wire, eps = 1).
  s.push_back({"head_on_stiffest_shell", elastic(20, 10, 1, 0, 3)});
  // The densest long runs, rho = 10, at the fast preset: the rigid one to l = 100 (at the
  // default numerics it needs ~145 s of CPU: it reached l = 90.6 in the 120 s budget), the
  // elastic one (the paper's xi = 10, eps = 1e3) to l = 100 (fast preset).
  // The rigid one jams (the packing pushes the wire back out through the hole, l = 84.6; the
  // engine's jam check, which this scene found missing, must end it).
  s.push_back({"dense_long_rigid",
               {{"rho", 10}, {"shell", "rigid"}, {"mu_s", 0}, {"l_max", 100}, {"numerics", "fast"}},
               120.0,
               "the packing jams the feed"});
  s.push_back({"dense_long_elastic", [] {
                 json j = elastic(10, 10, 1000, 0, 100);
                 j["numerics"] = "fast";
                 return j;
               }()});
  // High friction with a swivel at the hole (feeder_spin "free"): the friction torques spin the
  // wire as a whole instead of twisting it against the feeder; the second corner above, swivel.
  s.push_back({"swivel_rho10_xi10_eps1_mu1p5", [] {
                 json j = elastic(10, 10, 1, 1.5, 12);
                 j["feeder_spin"] = "free";
                 return j;
               }()});
  // Engine VI's options at the hard corners with friction (results/crumpling): damping of the
  // whole velocity (numerics.damping_form "absolute") at zeta = 0.5, its strongest setting in
  // the study, and the inertial preset (uniform mass scaling, q = 0.01), each on the thick stiff
  // shell at mu_s = 1.5, the thin soft shell at mu_s = 1.5, and the head-on tip.
  for (const auto& [variant, numerics] :
       {std::pair<std::string, json>{"absolute",
                                     {{"damping_form", "absolute"}, {"damping_ratio", 0.5}}},
        std::pair<std::string, json>{"inertial", {{"preset", "inertial"}}}}) {
    for (const auto& [corner, j0] :
         {std::pair{"rho10_xi10_eps1_mu1p5", elastic(10, 10, 1, 1.5, 12)},
          std::pair{"rho10_xi200_eps1e4_mu1p5", elastic(10, 200, 1e4, 1.5, 5)},
          std::pair{"head_on_stiffest_shell", elastic(20, 10, 1, 0, 3)}}) {
      json j = j0;
      j["numerics"] = numerics;
      s.push_back({variant + "_" + corner, j});
    }
  }
  // The neo-Hookean shell (shell_material, issue 51) at the same three: it stiffens without
  // bound where a face collapses, the thin soft shell is the most strained, the head-on tip
  // presses the stiffest shell hardest.
  for (const auto& [corner, j0] :
       {std::pair{"rho10_xi10_eps1_mu1p5", elastic(10, 10, 1, 1.5, 12)},
        std::pair{"rho10_xi200_eps1e4_mu1p5", elastic(10, 200, 1e4, 1.5, 5)},
        std::pair{"head_on_stiffest_shell", elastic(20, 10, 1, 0, 3)}}) {
    json j = j0;
    j["shell_material"] = "neo_hookean";
    s.push_back({std::string("neo_hookean_") + corner, j});
  }
  // The coarsest and the finest numerics presets at the first corner (whose row above is the
  // default preset): fast to the same l, accurate just past the head-on contact.
  for (const auto& [preset, l_max] : {std::pair{"fast", 15.0}, std::pair{"accurate", 2.2}}) {
    json j = elastic(10, 10, 1, 0, l_max);
    j["numerics"] = preset;
    s.push_back({std::string("preset_") + preset + "_rho10_xi10_eps1_mu0", j});
  }
  return s;
}

class HardScenes : public ::testing::TestWithParam<HardScene> {};

TEST_P(HardScenes, EndsWithTheInvariantsHeld) {
  const HardScene& hs = GetParam();
  const Scene scene = parse_scene(hs.scene, hs.name);
  const SceneParams& p = scene.engine;
  const Outcome o = run_scene_checked(scene, hs.budget_s);
  const double r = p.wire.radius;
  const bool rigid = p.shell == ShellKind::Rigid;
  std::printf(
      "HARD_SCENE,%s,%g,%s,%s,%g,%s,%g,%s,%.3f,%ld,%.1f,%.1f,%.3g,%.3g,%.4f,%.4f,%.4f,%.3f,%.3f,\"%"
      "s\"\n",
      hs.name.c_str(), p.rho, rigid ? "" : std::to_string(static_cast<int>(p.xi)).c_str(),
      rigid ? "" : std::to_string(static_cast<int>(p.eps)).c_str(), p.mu_s,
      scene.numerics_preset.c_str(), p.l_max, o.complete ? "complete" : "failed", o.l, o.steps,
      o.wall_s, o.cpu_s, o.dt_min, o.dt_end, o.overlap.wire_wire / r, o.wall_past_entrance / r,
      o.overlap.wire_shell / r, o.energy_ratio_end, o.energy_ratio_max, o.failure.c_str());
  for (const std::string& v : o.violations) ADD_FAILURE() << v;
  if (!o.complete) {
    EXPECT_FALSE(o.failure.empty()) << "a run that stops must say why";
    EXPECT_TRUE(cannot_continue(o)) << "failed: " << o.failure;
    EXPECT_LE(o.cpu_s, hs.budget_s + 10.0) << "the budget check must end the run";
  }
  if (!hs.expect_failure.empty()) {
    EXPECT_FALSE(o.complete);
    EXPECT_NE(o.failure.find(hs.expect_failure), std::string::npos) << o.failure;
  }
  EXPECT_LT(o.overlap.wire_wire, kMaxOverlap * r);
  EXPECT_LT(o.wall_past_entrance, kMaxOverlap * r);
  std::printf("  largest wall overlap, entrance included: %.4f r\n", o.overlap.wall / r);
}

INSTANTIATE_TEST_SUITE_P(Suite, HardScenes, ::testing::ValuesIn(hard_scenes()),
                         [](const ::testing::TestParamInfo<HardScene>& info) {
                           return info.param.name;
                         });

}  // namespace
}  // namespace wirepack::sweep
