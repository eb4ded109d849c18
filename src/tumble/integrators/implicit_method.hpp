#pragma once
// What the implicit methods (radau5.hpp, trbdf2.hpp) share: the Jacobian df/dy they take from
// the system and keep across steps while Newton converges fast, the step its factorisations are
// for, f at the current state, Newton's predicted error factor, their start and restart, and
// that memory's fields in a checkpoint. Each method adds its stages, its factorisations and its
// error control.
#include "tumble/integrators/integrator.hpp"

namespace tumble {

class ImplicitMethod : public Integrator {
 public:
  // Jacobians taken and Newton matrices factored, over the run (for reports and tests).
  long jacobian_evaluations() const { return jacobian_evaluations_; }
  long factorisations() const { return factorisations_; }

 protected:
  // Throws std::invalid_argument for tolerances or step bounds that make no sense;
  // StepControl::fixed_step is ignored. The largest step is the whole span unless max_step.
  ImplicitMethod(std::string_view name, const StepControl& control);

  // The shared part of start(): checks the start, takes J at (t0, y0) (std::invalid_argument
  // where the system gives none), sets t, y, f0, the tolerances, the counts and the first step
  // (the explicit methods' rule from the slope: on a stiff system it is short, and the
  // controllers lengthen it five- to eight-fold a step).
  void start_implicit(OdeSystem& system, double t0, const VecX& y0, double t_end);
  // The shared part of restart(): the new state and f there; the Jacobian belongs to what came
  // before the jump, and is taken anew before the next step.
  void restart_implicit(double t, const VecX& y);
  // J at (t_, y_) into jacobian_; the factorisations are then out of date.
  void take_jacobian();
  // Called after each new Jacobian (taken or loaded): radau5 bounds its spectral radius.
  virtual void on_new_jacobian() {}
  // The shared memory's fields, through f0 (each method's own follow), and Newton's factor.
  void archive_implicit(StateArchive& archive);
  void archive_newton_factor(StateArchive& archive);
  // The size of Newton's last correction, against the tolerance, at which its predicted
  // remaining error is small enough to stop (RADAU5's rule).
  double newton_enough() const;
  // The RMS norm of v / sk.
  static double rms(const VecX& v, const VecX& sk);

  // A step within 10 % of the stop is stretched onto it; a step that would grow by less than a
  // fifth keeps its size (and the factorisations: not worth new ones).
  static constexpr double kLandingStretch = 1.1;
  static constexpr double kKeepSizeBelow = 1.2;

  StepControl control_;
  OdeSystem* system_ = nullptr;
  double direction_ = 1.0;  // +1 forward in time, -1 backward
  double h_max_ = 0.0;      // s, bound on |h|
  VecX atol_;               // the absolute tolerance per component

  MatX jacobian_;                  // df/dy at the state it was taken at
  bool jacobian_current_ = false;  // taken at (t_, y_)
  bool need_jacobian_ = true;      // to be taken before the next try (else the last one serves)
  double factored_h_ = 0.0;        // the signed step the factorisations are for; 0: none
  VecX f0_;                        // f(t_, y_)
  double faccon_ = 1.0;            // Newton's predicted error factor, theta / (1 - theta)
  long jacobian_evaluations_ = 0;
  long factorisations_ = 0;

 private:
  std::string_view name_;
};

}  // namespace tumble
