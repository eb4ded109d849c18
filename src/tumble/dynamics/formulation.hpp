#pragma once
// A formulation turns a Model into an OdeSystem: it chooses the state vector y and writes the
// Newton-Euler equations on it. Two exist:
//  - BodyFrameFormulation (production): per body [r_G, q_WB, v_G, omega_B], Euler's equations in
//    body axes, a unit quaternion for the orientation (kept unit by projection or by the Lie
//    method), so R_WB is orthonormal to round-off over any run.
//  - TextbookFormulation: the chapter's own [R; omega] with I = R I0 R^T in the world frame, kept
//    for teaching and comparison; R drifts from orthonormality at the integrator's accuracy.
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tumble/dynamics/model.hpp"
#include "tumble/integrators/ode_system.hpp"

namespace tumble {

// What a row of output reports besides the bodies' states, for formulations with joints and
// force elements (empty otherwise).
struct JointReaction {
  Vec3 F_W = Vec3::Zero();    // force the joint's first body exerts on its second, world, N
  Vec3 M_J_W = Vec3::Zero();  // moment of it about the joint point, world, N m
};
struct ElementWork {
  double power = 0.0;  // W, rate of work on the bodies now
  double work = 0.0;   // J, done since t0 (impulses and locks: at their instants)
};
// A contact's force and how it touches (docs/scenario.md, the CSV's C.* columns).
struct ContactOutput {
  double normal_force = 0.0;       // N, >= 0 (0 when apart)
  Vec3 friction_W = Vec3::Zero();  // N, the tangential force on the body, world
  double slip_speed = 0.0;         // m/s, of the body's material point at the contact
  int mode = 0;                    // 0 apart, 1 sliding, 2 rolling / sticking
};
struct RowExtras {
  std::vector<JointReaction> joints;    // one per Model::joints entry
  std::vector<ContactOutput> contacts;  // one per Model::contacts entry
  std::vector<ElementWork> elements;    // one per element_names() entry
  double elastic_energy = 0.0;          // J, stored in springs: part of PE
};

class Formulation : public OdeSystem {
 public:
  explicit Formulation(Model model) : model_(std::move(model)) {}

  const Model& model() const { return model_; }
  std::size_t body_count() const { return model_.bodies.size(); }

  virtual std::string_view name() const = 0;
  // Writes the bodies' states into y (sized by the caller to dimension()).
  virtual void pack(std::span<const BodyState> states, VecX& y) const = 0;
  // Reads one body's state from y; unit quaternions are normalised on the way out.
  virtual BodyState unpack(const VecX& y, std::size_t body) const = 0;
  // Every body's state at once (states sized to body_count()).
  virtual void unpack_all(const VecX& y, std::span<BodyState> states) const;

  // The elements whose power and work a row reports (loads, springs, motors, impulses, locks),
  // and the row's joint reactions, element powers and works and elastic energy at (t, y).
  virtual std::vector<std::string> element_names() const { return {}; }
  virtual void calc_row_extras(double t, const VecX& y, RowExtras& extras) const;

  // Load schedules: the active set is fixed between switching times and changes only here.
  void begin(double t0, const VecX& /*y*/) override { schedule_time_ = t0; }
  double next_breakpoint(double t) const override { return model_.next_load_switch(t); }
  void at_breakpoint(double t, VecX& /*y*/) override { schedule_time_ = t; }

 protected:
  Model model_;
  double schedule_time_ = 0.0;  // the last schedule edge reached: decides which loads act
};

// "body" or "textbook"; throws std::invalid_argument otherwise. "body" runs free bodies under
// gravity alone in the body-frame form, and anything with joints, force elements or loads (whose
// work the rows report) in the articulated form (joint coordinates).
std::unique_ptr<Formulation> make_formulation(std::string_view name, Model model);

}  // namespace tumble
