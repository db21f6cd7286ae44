#pragma once
// A small dynamics rig for friction tests: a rod with a chosen set of terms, external forces
// and the engine's predictor-corrector, with the same trial/commit protocol as Simulation.
#include <functional>
#include <memory>
#include <vector>

#include "engine/integrate/predictor_corrector.hpp"
#include "engine/rod/frames.hpp"
#include "engine/term.hpp"

namespace wirepack::testing {

struct FrictionRig {
  State s;
  std::vector<std::unique_ptr<Term>> terms;
  RodInertia inertia;
  std::vector<bool> fixed;  // nodes held at rest (in addition to the guide)
  // External generalised forces at time t (added to the forces of the terms).
  std::function<void(double t, const State&, Forces&)> external;
  Forces f;
  double t = 0;
  std::unique_ptr<PredictorCorrector> pc;

  void start(double tolerance, double damping_ratio) {
    StepControl c;
    c.tolerance = tolerance;
    c.damping_ratio = damping_ratio;
    c.dt_floor = 1e-14;
    pc = std::make_unique<PredictorCorrector>(c, 0.5e-3);
    if (fixed.empty()) fixed.assign(s.x.size(), false);
    pc->initialise(s, eval(), moved());
    commit();
  }
  EvaluateFn eval() {
    return [this](State& st, Vec3List& a, std::vector<double>& alpha, Vec3List& shell_a) {
      f.reset(st);
      double omega2 = 0;
      for (auto& term : terms) {
        term->begin_trial(pc->trial_dt());
        term->accumulate(st, f);
        omega2 += term->omega_max_sq(inertia);
      }
      if (external) external(t + pc->trial_dt(), st, f);
      a.resize(st.x.size());
      for (size_t i = 0; i < st.x.size(); ++i) {
        const bool dyn = static_cast<int>(i) < st.n_free && !fixed[i];
        a[i] = dyn ? Vec3(f.f[i] / inertia.node_mass) : Vec3::Zero();
      }
      alpha.assign(st.theta.size(), 0.0);
      for (size_t j = 0; j < st.theta.size(); ++j) {
        if (!fixed[j] || !fixed[j + 1]) alpha[j] = f.torque[j] / inertia.edge_twist_inertia;
      }
      shell_a.assign(st.shell_x.size(), Vec3::Zero());  // a shell, if any, is held
      return omega2;
    };
  }
  static PositionsChangedFn moved() {
    return [](State& st) { update_reference_frames(st); };
  }
  void commit() {
    for (auto& term : terms) term->commit();
  }
  double step() {
    const double dt = pc->step(s, eval(), moved());
    commit();
    t += dt;
    return dt;
  }
  void run_until(double t_end, const std::function<void()>& each_step = {}) {
    while (t < t_end) {
      step();
      if (each_step) each_step();
    }
  }
  Vec3 centroid(int first, int last) const {  // nodes [first, last)
    Vec3 c = Vec3::Zero();
    for (int i = first; i < last; ++i) c += s.x[i];
    return c / (last - first);
  }
  Vec3 mean_velocity(int first, int last) const {
    Vec3 c = Vec3::Zero();
    for (int i = first; i < last; ++i) c += s.v[i];
    return c / (last - first);
  }
};

}  // namespace wirepack::testing
