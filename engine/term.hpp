#pragma once
// One energy term of a scene (stretch, bend, twist, a contact type, ...). A scene is a list of
// terms; an effect that is off is simply not in the list (DESIGN §3, effects on demand).
#include <string>

#include "engine/rod/rod_state.hpp"

namespace wirepack {

// Lumped inertia of the rod, after mass scaling: node mass [kg], edge twist inertia [kg m^2].
struct RodInertia {
  double node_mass = 0.0;
  double edge_twist_inertia = 0.0;
};

class Term {
 public:
  virtual ~Term() = default;
  virtual std::string name() const = 0;
  // Adds the generalised forces -dU/dq of this term into `out` and returns U [J].
  // May update caches of the term (contact lists, counters), hence non-const.
  virtual double accumulate(const RodState& s, RodForces& out) = 0;
  // Energy only (no forces); used by finite-difference checks. Must match accumulate().
  virtual double energy(const RodState& s) = 0;
  // Square of the highest angular frequency this term can excite at the state of the last
  // accumulate() [1/s^2]; bounds the explicit time step.
  virtual double omega_max_sq(const RodInertia& inertia) const = 0;

  // History-dependent terms (friction): the next accumulate() belongs to a trial step of size
  // dt [s] (0: re-evaluation at the same instant); commit() accepts the last trial.
  virtual void begin_trial(double /*dt*/) {}
  virtual void commit() {}
  virtual bool has_friction() const { return false; }
};

}  // namespace wirepack
