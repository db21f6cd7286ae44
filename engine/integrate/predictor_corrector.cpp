#include "engine/integrate/predictor_corrector.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>

namespace wirepack {

double PredictorCorrector::stable_step(double omega2) const {
  if (!(omega2 > 0)) return std::numeric_limits<double>::infinity();
  const double z = c_.damping_ratio;
  return c_.safety * 2.0 / std::sqrt(omega2) * (std::sqrt(1.0 + z * z) - z);
}

void PredictorCorrector::initialise(State& s, const EvaluateFn& eval,
                                    const PositionsChangedFn& moved) {
  moved(s);
  trial_dt_ = 0.0;
  const double omega2 = eval(s, a_, alpha_, sa_);
  dt_stable_ = stable_step(omega2);
  if (dt_ <= 0) dt_ = 0.1 * dt_stable_;  // start cautiously; the controller grows it
  dt_ = std::min(dt_, dt_stable_);
}

double PredictorCorrector::step(State& s, const EvaluateFn& eval, const PositionsChangedFn& moved) {
  const int n = s.num_nodes();
  const int ne = static_cast<int>(s.theta.size());
  const int nv = static_cast<int>(s.shell_x.size());
  // The start of the step moves into x0_, v0_, ... (a swap, not a copy); the predictor below
  // writes every entry of s.x, s.v, ... afresh, also after a rejection.
  const auto take = [](auto& state_vec, auto& start, int size) {
    start.swap(state_vec);
    state_vec.resize(size);
  };
  take(s.x, x0_, n);
  take(s.v, v0_, n);
  take(s.theta, th0_, ne);
  take(s.omega, om0_, ne);
  take(s.shell_x, sx0_, nv);
  take(s.shell_v, sv0_, nv);
  if (s.has_twist()) {
    saved_frames_.ref1 = s.ref1;
    saved_frames_.ref_tangent = s.ref_tangent;
    saved_frames_.ref_twist = s.ref_twist;
  }
  for (;;) {
    const double dt = dt_;
    const double h2 = 0.5 * dt * dt;
    // Predictor (the guide has a = 0 and moves at its constant velocity).
    for (int i = 0; i < n; ++i) {
      s.x[i] = x0_[i] + dt * v0_[i] + h2 * a_[i];
      s.v[i] = v0_[i] + dt * a_[i];
    }
    for (int j = 0; j < ne; ++j) {
      s.theta[j] = th0_[j] + dt * om0_[j] + h2 * alpha_[j];
      s.omega[j] = om0_[j] + dt * alpha_[j];
    }
    for (int k = 0; k < nv; ++k) {
      s.shell_x[k] = sx0_[k] + dt * sv0_[k] + h2 * sa_[k];
      s.shell_v[k] = sv0_[k] + dt * sa_[k];
    }
    moved(s);
    trial_dt_ = dt;
    const double omega2 = eval(s, a_new_, alpha_new_, sa_new_);
    // Corrector error estimate: dt^2/6 |a' - a| (positions), r dt^2/6 |alpha' - alpha| (twist).
    double da = 0.0;
    bool finite = true;
    Where peak;  // the DOF where |a' - a| peaks (named in a collapse message)
    for (int i = 0; i < s.n_free; ++i) {  // squared: one square root after the loop
      const double d2 = (a_new_[i] - a_[i]).squaredNorm();
      finite = finite && std::isfinite(d2);
      if (d2 > da) da = d2, peak = {"wire node", i};
    }
    da = std::sqrt(da);
    for (int j = 0; j < ne; ++j) {
      const double d = r_ * std::abs(alpha_new_[j] - alpha_[j]);
      finite = finite && std::isfinite(d);
      if (d > da) da = d, peak = {"twist of wire edge", j};
    }
    for (int k = 0; k < nv; ++k) {
      const double d = (sa_new_[k] - sa_[k]).norm();
      finite = finite && std::isfinite(d);
      if (d > da) da = d, peak = {"shell vertex", k};
    }
    const double err = dt * dt / 6.0 * da;
    dt_stable_ = stable_step(omega2);
    const double ratio = err > 0 ? c_.tolerance / err : 1e30;
    double factor = c_.safety * std::cbrt(ratio);
    if (!finite) factor = c_.min_shrink;
    const bool reject = !finite || err > 2.0 * c_.tolerance || dt > 1.5 * dt_stable_;
    if (reject) {
      ++rejected_;
      const double shrunk = dt * std::max(c_.min_shrink, std::min(factor, 0.9));
      dt_ = std::min(shrunk, dt_stable_);
      // A trial that overshot deep into a contact barrier reports a stability step far below the
      // floor that a shorter step need not reach: try the shorter step before giving up (the
      // acceptance test above still bounds every accepted step by its own stability step).
      if (!(dt_ > c_.dt_floor) && shrunk > c_.dt_floor) dt_ = shrunk;
      if (!(dt_ > c_.dt_floor)) {
        // Leave the state at the start of the step.
        s.x = x0_;
        s.v = v0_;
        s.theta = th0_;
        s.omega = om0_;
        s.shell_x = sx0_;
        s.shell_v = sv0_;
        if (!finite) throw SimulationError("non-finite forces (NaN/Inf)");
        std::ostringstream why;  // the floor is ~1e-9 s: std::to_string printed "0.000000"
        why << std::setprecision(3) << "time step collapsed below " << c_.dt_floor
            << " s (the error control's last try " << dt_ << " s; at " << dt
            << " s the position error " << err << " m against the tolerance " << c_.tolerance
            << " m peaked at " << peak.kind << " " << peak.index << ", the stability step "
            << dt_stable_ << " s)";
        throw SimulationError(why.str());
      }
      // Retry from the start: the predictor rewrites the positions and velocities, the
      // reference frames (updated in place) are restored.
      if (s.has_twist()) {
        s.ref1 = saved_frames_.ref1;
        s.ref_tangent = saved_frames_.ref_tangent;
        s.ref_twist = saved_frames_.ref_twist;
      }
      continue;
    }
    // Corrector on velocities.
    for (int i = 0; i < n; ++i) s.v[i] = v0_[i] + 0.5 * dt * (a_[i] + a_new_[i]);
    for (int j = 0; j < ne; ++j) s.omega[j] = om0_[j] + 0.5 * dt * (alpha_[j] + alpha_new_[j]);
    for (int k = 0; k < nv; ++k) s.shell_v[k] = sv0_[k] + 0.5 * dt * (sa_[k] + sa_new_[k]);
    std::swap(a_, a_new_);
    std::swap(alpha_, alpha_new_);
    std::swap(sa_, sa_new_);
    // Hysteresis: keep the step unless the error asks for a clear change. A step that follows
    // the error estimate every step correlates with the oscillation phase and makes the
    // (otherwise time-reversible) scheme drift in energy.
    if (factor < 1.0) {
      dt_ = dt * std::max(factor, c_.min_shrink);
    } else if (factor > c_.grow_when) {
      dt_ = dt * std::min(factor, c_.max_growth);
    }
    dt_ = std::min(dt_, dt_stable_);
    return dt;
  }
}

template <class Self, class Archive>
void PredictorCorrector::serialize(Self& pc, Archive& ar) {
  ar.tag("INTG");
  ar(pc.dt_, pc.dt_stable_, pc.rejected_, pc.a_, pc.alpha_, pc.sa_);
}

void PredictorCorrector::save(StateWriter& out) const {
  serialize(*this, out);
}
void PredictorCorrector::load(StateReader& in) {
  serialize(*this, in);
}

}  // namespace wirepack
