#pragma once
// `integrator: auto`: DOP853 while the motion sets the step, Radau IIA (radau5) while stiffness
// does, switching either way at a step's end and saying where and why. A user need not know
// which method a problem wants, and a problem that is stiff only for a while (a transient through
// a stiff damper) pays for the implicit method only then.
//
// To implicit: DOP853's own test (Hairer and Wanner, "Solving Ordinary Differential Equations
// II", section IV.2, and their code): after each accepted step, |h| |lambda| from the step's two
// evaluations at its end (Dop853::last_step_h_lambda). Above 6.1, the edge of the method's
// stability region, the step is held by stability, not accuracy; fifteen such steps without six
// calm ones in a row between them make the problem stiff. At a tight tolerance the step-size
// controller pushes against the edge from inside it: on a stiff mount at rtol 1e-12 DOP853's
// steps sit at |h lambda| 4 to 6 and one attempt in three is rejected, so that Hairer's test
// alone never fires and DOP853 takes four times radau5's steps. So a step is also held when an
// attempt at it was rejected and its |h lambda| is above 0.6 of the edge (no accuracy-limited
// step of the examples comes there with a rejection: the highest, the inverted mast near its
// critical spring at rtol 1e-10, reaches 4.7 without one), and a step is calm only below that
// (in between, neither).
// Back to explicit: after each of radau5's steps, its |h| times a bound on the spectral radius of
// its Jacobian (Radau5::last_step_h_lambda). Where that stays within half of 6.1 for fifteen
// steps in a row, DOP853 would be stable at the steps radau5 takes, and with its order 8 it needs
// fewer of them.
// Either test that fires switches at the start of the next step (or at the restart that comes
// first): the step just taken keeps its continuous extension for the driver's rows and events.
// The method switched to restarts from the state there, as after a jump (radau5 starts the first
// time with its own first step; DOP853 goes on from its last step size).
// Where the system gives no Jacobian (free bodies under gravity alone, which are never stiff),
// auto is DOP853 throughout, and a stiffness it detects is reported, once, as not taken. Where
// it gives none only in some modes (OdeSystem::gives_jacobian_at; tumble's own systems give one
// in every mode of their contacts), auto does not switch to radau5 in them, and a jump into one
// while radau5 runs hands the run back to DOP853 (a switch with h_lambda kModesWithoutJacobian).
//
// No allocation in a step: the switches are kept in a fixed array (the first kKeptSwitches of
// them, and the count of all).
#include <array>
#include <memory>
#include <span>

#include "tumble/integrators/dop853.hpp"
#include "tumble/integrators/radau5.hpp"

namespace tumble {

struct MethodSwitch {
  double t = 0.0;  // s, where the next method takes over
  bool to_implicit = false;
  double h_lambda = 0.0;  // the |h| |lambda| of the step that decided it, or:
  // a jump into modes in which the system gives no Jacobian decided it (back to DOP853)
  static constexpr double kModesWithoutJacobian = -1.0;
  bool modes_without_jacobian() const { return h_lambda == kModesWithoutJacobian; }
};

class AutoSwitching final : public Integrator {
 public:
  // Throws std::invalid_argument for tolerances or step bounds that make no sense for the
  // adaptive methods; StepControl::fixed_step is ignored.
  explicit AutoSwitching(const StepControl& control);

  std::string_view name() const override { return "auto"; }
  int order() const override { return active().order(); }
  bool adaptive() const override { return true; }

  void start(OdeSystem& system, double t0, const VecX& y0, double t_end) override;
  void restart(double t, const VecX& y) override;
  std::unique_ptr<Integrator> clone_onto(OdeSystem& system) const override;
  void archive_memory(StateArchive& archive) override;
  StepOutcome step(double t_stop) override;
  void dense_output(double t, VecX& y_out) const override { active().dense_output(t, y_out); }
  IntegratorStats stats() const override;
  double last_step_h_lambda() const override { return active().last_step_h_lambda(); }

  // The method that takes the next step: "dop853" or "radau5".
  std::string_view method_in_use() const { return active().name(); }
  // The switches so far, the first kKeptSwitches of them, and how many there were in all.
  static constexpr std::size_t kKeptSwitches = 16;
  std::span<const MethodSwitch> switches() const {
    return {switches_.data(), std::min<std::size_t>(switch_count_, kKeptSwitches)};
  }
  long switch_count() const { return static_cast<long>(switch_count_); }
  // Where DOP853 first found the problem stiff but the system gave no Jacobian there (negative:
  // never).
  double stiff_without_jacobian_at() const { return stiff_without_jacobian_at_; }
  // Accepted steps taken by each method.
  long explicit_steps() const { return explicit_.stats().accepted_steps; }
  long implicit_steps() const { return implicit_started_ ? implicit_.stats().accepted_steps : 0; }

  // Hairer's bound on DOP853's |h lambda| and the count of steps above it that make a problem
  // stiff; six calm steps in a row forgive the count.
  static constexpr double kExplicitStabilityEdge = 6.1;
  static constexpr int kStiffSteps = 15;
  static constexpr int kCalmStepsForgive = 6;
  // Above this a retried step is held too; at or below it a step is calm.
  static constexpr double kNearEdge = 0.6 * kExplicitStabilityEdge;

 private:
  const Integrator& active() const {
    return implicit_active_ ? static_cast<const Integrator&>(implicit_) : explicit_;
  }
  Integrator& active() {
    return implicit_active_ ? static_cast<Integrator&>(implicit_) : explicit_;
  }
  // Reads the last step's |h lambda| and arms a switch when a test fires; `retried`: an attempt
  // at the step was rejected.
  void watch_stiffness(bool retried);
  // Hands the run to the other method at (t, y) (after a jump: the active method restarts there
  // if it keeps the run); DOP853 keeps it where the system gives no Jacobian at (t, y).
  void take_switch(double t, const VecX& y, bool after_jump);
  // The active method's t, y, step and bound, mirrored into this one's (Integrator's accessors).
  void mirror_active();

  StepControl control_;
  OdeSystem* system_ = nullptr;
  double t_end_ = 0.0;
  bool implicit_available_ = false;
  Dop853 explicit_;
  Radau5 implicit_;  // started at the first switch
  bool implicit_started_ = false;
  bool implicit_active_ = false;
  bool switch_armed_ = false;  // at the next step or restart
  int stiff_steps_ = 0;        // DOP853's steps held by stability (Hairer's IASTI)
  int calm_steps_ = 0;         // in a row: DOP853's not held (NONSTI), radau5's within reach
  double armed_h_lambda_ = 0.0;
  double stiff_without_jacobian_at_ = -1.0;
  std::array<MethodSwitch, kKeptSwitches> switches_{};
  std::size_t switch_count_ = 0;
};

}  // namespace tumble
