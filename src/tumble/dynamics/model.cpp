#include "tumble/dynamics/model.hpp"

#include <algorithm>

namespace tumble {

double Model::next_load_switch(double t) const {
  double next = std::numeric_limits<double>::infinity();
  for (const AppliedLoad& load : loads) {
    if (load.from > t) next = std::min(next, load.from);
    if (load.to > t) next = std::min(next, load.to);
  }
  return next;
}

void calc_applied_loads(const Model& model, std::size_t body, double schedule_time,
                        const Mat3& R_WB, Vec3& F_W, Vec3& M_G_W) {
  F_W.setZero();
  M_G_W.setZero();
  for (const AppliedLoad& load : model.loads) {
    if (load.body != body || !load.active_at(schedule_time)) continue;
    const Vec3 value_W = load.body_frame ? Vec3(R_WB * load.value) : load.value;
    if (load.kind == AppliedLoad::Kind::Torque) {
      M_G_W += value_W;
    } else {
      // A force at point P adds the moment (r_P - r_G) x F about the COM.
      F_W += value_W;
      M_G_W += (R_WB * load.p_GP_B).cross(value_W);
    }
  }
}

}  // namespace tumble
