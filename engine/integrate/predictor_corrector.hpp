#pragma once
// Explicit second-order predictor-corrector with adaptive time step (paper, section "Model";
// docs/design.md §3.1). One force evaluation per step:
//   predict  x' = x + dt v + dt^2/2 a,   v* = v + dt a           (same for theta, omega)
//   evaluate a' = a(x', v*)
//   correct  v' = v + dt/2 (a + a')
// The local error is estimated from the corrector: the position update with the trapezoidal
// acceleration differs from the predictor by dt^2/6 |a' - a|. Steps with an error above twice
// the tolerance are rejected and retried; the next step size follows (tol/err)^{1/3}, bounded by
// the stability limit 2/omega_max (sqrt(1 + zeta^2) - zeta) of an explicit damped oscillator.
#include <functional>

#include "engine/state.hpp"
#include "engine/state_archive.hpp"

namespace wirepack {

struct StepControl {
  double tolerance = 0;      // allowed local position error per step [m]
  double damping_ratio = 0;  // largest modal damping ratio in the system [-]
  double safety = 0.9;       // fraction of the stability limit and of the error-optimal step
  double max_growth = 1.5;   // largest step growth factor per step
  double min_shrink = 0.2;   // smallest step shrink factor per step
  // Hysteresis: the step grows only when the error-optimal step (safety included) is at least
  // this many times the current one; it shrinks as soon as it is below the current one.
  double grow_when = 2.0;
  double dt_floor = 0;  // below this the step has collapsed [s]
};

// Accelerations of the dynamic DOFs at a state: fills a (n, zero for the guide), alpha
// (n-1, zero for fixed edges) and shell_a (one per shell vertex, zero when clamped; left empty
// without a shell); returns omega_max^2 of the system at that state [1/s^2].
using EvaluateFn =
    std::function<double(State&, Vec3List& a, std::vector<double>& alpha, Vec3List& shell_a)>;
// Called after positions change (reference frames, ...).
using PositionsChangedFn = std::function<void(State&)>;

class PredictorCorrector {
 public:
  PredictorCorrector(const StepControl& c, double length_scale) : c_(c), r_(length_scale) {}
  // Computes a and alpha at the current state (start, or after the DOF count changed).
  void initialise(State& s, const EvaluateFn& eval, const PositionsChangedFn& moved);
  // Advances by one accepted step; returns the step taken [s]. Throws SimulationError when the
  // step collapses below the floor or the state stops being finite.
  double step(State& s, const EvaluateFn& eval, const PositionsChangedFn& moved);

  double dt() const { return dt_; }
  // Size of the step being tried during an evaluation (0 during initialise) [s].
  double trial_dt() const { return trial_dt_; }
  double dt_stable() const { return dt_stable_; }
  long rejected() const { return rejected_; }
  const Vec3List& acceleration() const { return a_; }
  // Checkpoints: the step size, the stability step, the rejection count and the accelerations
  // of the last accepted state (the next predictor starts from them).
  void save(StateWriter& out) const;
  void load(StateReader& in);

 private:
  double stable_step(double omega2) const;
  // A degree of freedom named in a collapse message.
  struct Where {
    const char* kind = "no DOF";
    int index = -1;
  };
  template <class Self, class Archive>
  static void serialize(Self& pc, Archive& ar);

  StepControl c_;
  double r_;  // length scale of the twist error (wire radius) [m]
  double dt_ = 0, dt_stable_ = 0, trial_dt_ = 0;
  long rejected_ = 0;
  Vec3List a_, a_new_, x0_, v0_;
  Vec3List sa_, sa_new_, sx0_, sv0_;  // the same for shell vertices
  std::vector<double> alpha_, alpha_new_, th0_, om0_;
  State saved_frames_;  // ref1 / ref_tangent / ref_twist before a step, for rejection
};

}  // namespace wirepack
