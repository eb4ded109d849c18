#pragma once
// A formulation turns a Model into an OdeSystem: it chooses the state vector y and writes the
// Newton-Euler equations on it. Three exist:
//  - BodyFrameFormulation (production, free bodies): per body [r_G, q_WB, v_G, omega_B], Euler's
//    equations in body axes, a unit quaternion for the orientation (kept unit by projection or by
//    the Lie method), so R_WB is orthonormal to round-off over any run.
//  - TextbookFormulation: the chapter's own [R; omega] with I = R I0 R^T in the world frame, kept
//    for teaching and comparison; R drifts from orthonormality at the integrator's accuracy.
//  - ArticulatedFormulation (multibody/): joints, force elements and contacts, in joint
//    coordinates.
//
// Model, data, state: the Model is constant and shared (std::shared_ptr<const Model>) by every
// formulation made from it; a formulation is one run's: it owns that run's scratch (the data,
// written by const evaluations, so one formulation serves one thread at a time) and its hybrid
// state. new_run() makes another over the same model, for another run on any thread.
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tumble/dynamics/hybrid_state.hpp"
#include "tumble/dynamics/model.hpp"
#include "tumble/dynamics/row_extras.hpp"
#include "tumble/integrators/ode_system.hpp"

namespace tumble {

class Formulation : public OdeSystem {
 public:
  explicit Formulation(std::shared_ptr<const Model> model)
      : shared_model_(std::move(model)), model_(*shared_model_) {}

  const Model& model() const { return model_; }
  std::size_t body_count() const { return model_.bodies.size(); }

  // A formulation for another run of the same model: the constant parts are shared, not copied
  // (cheap, and safe to call while this one runs on another thread); scratch and state are new.
  virtual std::unique_ptr<Formulation> new_run() const = 0;

  virtual std::string_view name() const = 0;
  // Writes the bodies' states into y (sized by the caller to dimension()).
  virtual void pack(std::span<const BodyState> states, VecX& y) const = 0;
  // After pack (and the check that the given velocities are the ones packed): y onto the
  // constraints that pack does not hold by construction (the loops' joints). Nothing by default.
  virtual void assemble(VecX& /*y*/) const {}
  // Reads one body's state from y; unit quaternions are normalised on the way out.
  virtual BodyState unpack(const VecX& y, std::size_t body) const = 0;
  // Every body's state at once (states sized to body_count()).
  virtual void unpack_all(const VecX& y, std::span<BodyState> states) const;

  // The elements whose power and work a row reports (loads, springs, motors, impulses, locks),
  // and the row's joint reactions, element powers and works and elastic energy at (t, y).
  virtual std::vector<std::string> element_names() const { return {}; }
  // Whether y carries a work ledger (every element's work since t0), so that the rows can check
  // the work-energy theorem.
  virtual bool keeps_work_ledger() const { return false; }
  virtual void calc_row_extras(double t, const VecX& y, RowExtras& extras) const;

  // Why the run cannot start from y0 (a contact inside its plane, or touching it and moving
  // into it; joints that close loops and leave nothing free to move): the contact's index, or
  // the model joint's where `joint` >= 0, and the reason; nullopt if it can.
  struct StartProblem {
    std::size_t contact = 0;
    std::string why;
    int joint = -1;
  };
  virtual std::optional<StartProblem> start_problem(const VecX& /*y0*/) const {
    return std::nullopt;
  }
  // The rate of a hinge's or slider's one freedom at y (rad/s or m/s, its sign as the scenario
  // states the joint); 0 for a formulation without joints.
  virtual double joint_rate(const VecX& /*y*/, std::size_t /*joint*/) const { return 0.0; }

  // The run's state besides y: the modes of the right-hand side and what has happened so far.
  // A copy of it with y (and the integrator's memory) resumes the run exactly.
  const HybridState& hybrid_state() const { return hybrid_; }
  void set_hybrid_state(const HybridState& state) { hybrid_ = state; }

  // Load schedules: the active set is fixed between switching times and changes only here.
  void begin(double t0, const VecX& /*y*/) override { hybrid_.schedule_time = t0; }
  double next_breakpoint(double t) const override { return model_.next_load_switch(t); }
  void at_breakpoint(double t, VecX& /*y*/) override { hybrid_.schedule_time = t; }

  const Formulation* rigid_body_formulation() const final { return this; }

 protected:
  std::shared_ptr<const Model> shared_model_;
  const Model& model_;  // *shared_model_
  HybridState hybrid_;
};

}  // namespace tumble
