#pragma once
// Puts a ShellTerm (energy of the shell vertices alone) into a scene's list of terms.
#include <memory>

#include "engine/shell/shell_term.hpp"
#include "engine/term.hpp"

namespace wirepack {

class ShellTermAdapter : public Term {
 public:
  // min_vertex_mass: the lightest free vertex [kg], for the stability bound.
  ShellTermAdapter(std::unique_ptr<ShellTerm> term, double min_vertex_mass)
      : term_(std::move(term)), m_(min_vertex_mass) {}
  std::string name() const override { return term_->name(); }
  TermType type() const override { return term_->type(); }
  DofGroup dofs() const override { return DofGroup::kShell; }
  double accumulate(const State& s, Forces& out) override {
    return term_->accumulate(s.shell_x, out.shell_f);
  }
  double energy(const State& s) override { return term_->energy(s.shell_x); }
  double omega_max_sq(const RodInertia&) const override { return term_->omega_max_sq(m_); }

 private:
  std::unique_ptr<ShellTerm> term_;
  double m_;
};

}  // namespace wirepack
