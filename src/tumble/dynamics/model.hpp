#pragma once
// The constant description of a mechanical system (what MuJoCo calls the model): bodies, uniform
// gravity, the applied loads, force elements, joints and contacts. The state lives elsewhere (in
// the integrator's vector y).
#include <limits>
#include <string>
#include <vector>

#include "tumble/body/rigid_body.hpp"
#include "tumble/contact/plane_contact.hpp"
#include "tumble/dynamics/force_elements.hpp"
#include "tumble/dynamics/joint_model.hpp"

namespace tumble {

// A constant force at a body point, or a pure torque, active for from <= t < to.
struct AppliedLoad {
  enum class Kind { Force, Torque } kind = Kind::Force;
  std::string name;
  std::size_t body = 0;
  Vec3 value = Vec3::Zero();  // N or N m: world axes, or body axes when body_frame
  bool body_frame = false;
  Vec3 p_GP_B = Vec3::Zero();  // force: point of application from the COM, body axes, m
  double from = -std::numeric_limits<double>::infinity();  // s
  double to = std::numeric_limits<double>::infinity();     // s

  bool active_at(double t) const { return from <= t && t < to; }
};

struct Model {
  std::vector<RigidBody> bodies;
  Vec3 gravity_W = Vec3(0.0, 0.0, -9.81);  // m/s^2
  std::vector<AppliedLoad> loads;
  std::vector<LinearSpring> springs;
  std::vector<TorsionalSpring> torsional_springs;
  std::vector<ImpulseLoad> impulses;
  std::vector<JointModel> joints;
  std::vector<PlaneContact> contacts;
  // The step a fixed-step method takes (s), which keeps it whatever the contacts' step limit;
  // 0 for an adaptive method, which keeps within it. The broad phase screens a step this long.
  double fixed_step = 0.0;
  // Each contact's entry among the contacts' work-ledger entries, and their names: a contact's
  // own, or the one `bodies: all`'s pairs share (hit for hit_ball1_ball2). Empty: one per
  // contact, named as it is.
  std::vector<std::size_t> contact_ledger;
  std::vector<std::string> contact_ledger_names;
  std::size_t contact_ledger_entry(std::size_t contact) const {
    return contact_ledger.empty() ? contact : contact_ledger[contact];
  }
  std::size_t contact_ledger_size() const {
    return contact_ledger.empty() ? contacts.size() : contact_ledger_names.size();
  }
  const std::string& contact_ledger_name(std::size_t entry) const {
    return contact_ledger.empty() ? contacts[entry].name : contact_ledger_names[entry];
  }

  // Only free bodies under gravity and one-body loads: the free-body formulations run it.
  bool bodies_are_free() const;

  // The first schedule edge strictly after t (a load's or motor's from or to, an impulse, a
  // lock), or +infinity.
  double next_load_switch(double t) const;
};

// What one active load does to its body at orientation R_WB: the force (world) and its moment
// about the COM (world). Written once over the scalar (a run's double, `tumble modes`' Dual).
template <typename S>
struct LoadOnBodyOf {
  Vec3Of<S> F_W = Vec3Of<S>::Zero();
  Vec3Of<S> M_G_W = Vec3Of<S>::Zero();
};
using LoadOnBody = LoadOnBodyOf<double>;
template <typename S>
LoadOnBodyOf<S> calc_load_on_body(const AppliedLoad& load, const Mat3Of<S>& R_WB) {
  const Vec3Of<S> value_W =
      load.body_frame ? Vec3Of<S>(R_WB * load.value.cast<S>()) : Vec3Of<S>(load.value.cast<S>());
  LoadOnBodyOf<S> on_body;
  if (load.kind == AppliedLoad::Kind::Torque) {
    on_body.M_G_W = value_W;
  } else {
    // A force at point P adds the moment (r_P - r_G) x F about the COM.
    on_body.F_W = value_W;
    on_body.M_G_W = (R_WB * load.p_GP_B.cast<S>()).cross(value_W);
  }
  return on_body;
}
inline LoadOnBody calc_load_on_body(const AppliedLoad& load, const Mat3& R_WB) {
  return calc_load_on_body<double>(load, R_WB);
}

// Resultant of the applied loads on one body (gravity excluded): the force (world) and the
// moment about the COM (world), for orientation R_WB. The loads that act are those active at
// `schedule_time`, the last schedule edge reached (not the current time: the last stage of a step
// that ends on an edge belongs to the interval before it). Does not allocate.
void calc_applied_loads(const Model& model, std::size_t body, double schedule_time,
                        const Mat3& R_WB, Vec3& F_W, Vec3& M_G_W);

}  // namespace tumble
