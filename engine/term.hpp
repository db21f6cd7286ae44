#pragma once
// One energy term of a scene (stretch, bend, twist, a contact type, ...). A scene is a list of
// terms; an effect that is off is simply not in the list (docs/design.md §2.8, effects on demand).
#include <string>

#include "engine/state.hpp"
#include "engine/state_archive.hpp"
#include "engine/term_type.hpp"

namespace wirepack {

// Lumped inertia of the rod, after mass scaling: node mass [kg], edge twist inertia [kg m^2].
struct RodInertia {
  double node_mass = 0.0;
  double edge_twist_inertia = 0.0;
};

// Which degrees of freedom a term's forces act on, for the stability bound: terms on disjoint
// sets of DOFs have block-diagonal stiffnesses, whose largest eigenvalue is the larger of the
// blocks', not their sum (engine/integrate/stability.hpp).
enum class DofGroup {
  kWire,      // wire node positions and twist angles
  kShell,     // shell vertex positions
  kCoupling,  // both (wire-shell contact)
};

class Term {
 public:
  virtual ~Term() = default;
  virtual DofGroup dofs() const { return DofGroup::kWire; }
  virtual std::string name() const = 0;
  // Where energies() reports this term's energy.
  virtual TermType type() const = 0;
  // Adds the generalised forces -dU/dq of this term into `out` and returns U [J].
  // May update caches of the term (contact lists, counters), hence non-const.
  virtual double accumulate(const State& s, Forces& out) = 0;
  // Energy only (no forces); used by finite-difference checks. Must match accumulate().
  virtual double energy(const State& s) = 0;
  // Square of the highest angular frequency this term can excite at the state of the last
  // accumulate() [1/s^2]; bounds the explicit time step.
  virtual double omega_max_sq(const RodInertia& inertia) const = 0;

  // History-dependent terms (friction): the next accumulate() belongs to a trial step of size
  // dt [s] (0: re-evaluation at the same instant); commit() accepts the last trial.
  virtual void begin_trial(double /*dt*/) {}
  virtual void commit() {}
  virtual bool has_friction() const { return false; }
  // Why the state of the last accumulate() cannot be accepted (empty: it can), e.g. a contact
  // whose bodies passed through each other.
  virtual std::string failure() const { return {}; }

  // Checkpoints (docs/design.md §4.8): the state this term carries from one accepted step to
  // the next (contact lists, friction springs), written after a commit() and read back into a
  // term of the same scene; what the next accumulate() recomputes is not stored. A restored
  // term continues bitwise as the saved one would have.
  virtual void save(StateWriter& /*out*/) const {}
  virtual void load(StateReader& /*in*/) {}
};

}  // namespace wirepack
