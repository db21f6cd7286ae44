#pragma once
// A contact term with an optional Coulomb friction history (friction.hpp): null when mu_s = 0,
// so a frictionless scene keeps no springs and applies no torques. The Term hooks that carry
// the history through trial steps (begin_trial, commit) are the same for every contact type
// (wire-wire, wire-wall, wire-shell, shell-shell) and live here once.
#include <memory>

#include "engine/contact/friction.hpp"
#include "engine/term.hpp"

namespace wirepack {

class FrictionalTerm : public Term {
 public:
  explicit FrictionalTerm(const FrictionParams& p)
      : friction_(p.enabled() ? std::make_unique<FrictionHistory>(p) : nullptr) {}
  void begin_trial(double dt) override {
    if (friction_) friction_->begin_trial(dt);
  }
  void commit() override {
    if (friction_) friction_->commit();
  }
  bool has_friction() const override { return friction_ != nullptr; }
  const FrictionHistory* friction() const { return friction_.get(); }

 protected:
  std::unique_ptr<FrictionHistory> friction_;
};

}  // namespace wirepack
