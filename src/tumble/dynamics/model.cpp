#include "tumble/dynamics/model.hpp"

#include <algorithm>

namespace tumble {

bool Model::bodies_are_free() const {
  return joints.empty() && springs.empty() && torsional_springs.empty() && impulses.empty() &&
         contacts.empty();
}

double Model::next_load_switch(double t) const {
  double next = std::numeric_limits<double>::infinity();
  const auto consider = [&](double edge) {
    if (edge > t) next = std::min(next, edge);
  };
  for (const AppliedLoad& load : loads) {
    consider(load.from);
    consider(load.to);
  }
  for (const ImpulseLoad& impulse : impulses) consider(impulse.time);
  for (const JointModel& joint : joints) {
    if (joint.motor.kind != JointMotor::Kind::None) {
      consider(joint.motor.from);
      consider(joint.motor.to);
    }
    consider(joint.lock_at);
  }
  return next;
}

LoadOnBody calc_load_on_body(const AppliedLoad& load, const Mat3& R_WB) {
  const Vec3 value_W = load.body_frame ? Vec3(R_WB * load.value) : load.value;
  LoadOnBody on_body;
  if (load.kind == AppliedLoad::Kind::Torque) {
    on_body.M_G_W = value_W;
  } else {
    // A force at point P adds the moment (r_P - r_G) x F about the COM.
    on_body.F_W = value_W;
    on_body.M_G_W = (R_WB * load.p_GP_B).cross(value_W);
  }
  return on_body;
}

void calc_applied_loads(const Model& model, std::size_t body, double schedule_time,
                        const Mat3& R_WB, Vec3& F_W, Vec3& M_G_W) {
  F_W.setZero();
  M_G_W.setZero();
  for (const AppliedLoad& load : model.loads) {
    if (load.body != body || !load.active_at(schedule_time)) continue;
    const LoadOnBody on_body = calc_load_on_body(load, R_WB);
    F_W += on_body.F_W;
    M_G_W += on_body.M_G_W;
  }
}

}  // namespace tumble
