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
