#include "tumble/dynamics/body_frame_formulation.hpp"

namespace tumble {

BodyFrameFormulation::BodyFrameFormulation(std::shared_ptr<const Model> model)
    : Formulation(std::move(model)) {
  for (std::size_t i = 0; i < body_count(); ++i) {
    quaternion_offsets_.push_back(static_cast<Eigen::Index>(i) * kPerBody + kQuaternion);
  }
}

Eigen::Index BodyFrameFormulation::dimension() const {
  return static_cast<Eigen::Index>(body_count()) * kPerBody;
}

void BodyFrameFormulation::derivative(double /*t*/, const VecX& y, VecX& dydt) const {
  const bool has_loads = !model_.loads.empty();
  for (std::size_t i = 0; i < body_count(); ++i) {
    const RigidBody& body = model_.bodies[i];
    const Eigen::Index o = static_cast<Eigen::Index>(i) * kPerBody;
    const auto q = y.segment<4>(o + kQuaternion);  // (w, x, y, z), unit only up to round-off
    const Vec3 omega_B = y.segment<3>(o + kOmegaBody);

    dydt.segment<3>(o + kPosition) = y.segment<3>(o + kVelocity);

    // q' = q (x) (0, omega_B) / 2, written out: w' = -v.omega/2, v' = (w omega + v x omega)/2.
    const Vec3 q_vec = q.tail<3>();
    dydt(o + kQuaternion) = -0.5 * q_vec.dot(omega_B);
    dydt.segment<3>(o + kQuaternion + 1) = 0.5 * (q(0) * omega_B + q_vec.cross(omega_B));

    Vec3 F_W = body.mass * model_.gravity_W;
    Vec3 M_G_B = -omega_B.cross(body.I_G_B * omega_B);
    if (has_loads) {
      // The rotation of the normalised quaternion: loads see a proper rotation even between
      // projections.
      const Mat3 R_WB = Quat(q(0), q(1), q(2), q(3)).normalized().toRotationMatrix();
      Vec3 F_applied_W, M_applied_G_W;
      calc_applied_loads(model_, i, hybrid_.schedule_time, R_WB, F_applied_W, M_applied_G_W);
      F_W += F_applied_W;
      M_G_B += R_WB.transpose() * M_applied_G_W;
    }
    dydt.segment<3>(o + kVelocity) = F_W / body.mass;
    dydt.segment<3>(o + kOmegaBody) = body.I_G_B_inv * M_G_B;
  }
}

void BodyFrameFormulation::pack(std::span<const BodyState> states, VecX& y) const {
  for (std::size_t i = 0; i < body_count(); ++i) {
    const Eigen::Index o = static_cast<Eigen::Index>(i) * kPerBody;
    const BodyState& s = states[i];
    Quat q(s.R_WB);
    q.normalize();
    if (q.w() < 0.0) q.coeffs() = -q.coeffs();
    y.segment<3>(o + kPosition) = s.r_G;
    y.segment<4>(o + kQuaternion) << q.w(), q.x(), q.y(), q.z();
    y.segment<3>(o + kVelocity) = s.v_G;
    y.segment<3>(o + kOmegaBody) = s.R_WB.transpose() * s.omega_W;
  }
}

BodyState BodyFrameFormulation::unpack(const VecX& y, std::size_t body) const {
  const Eigen::Index o = static_cast<Eigen::Index>(body) * kPerBody;
  const auto q = y.segment<4>(o + kQuaternion);
  BodyState s;
  s.r_G = y.segment<3>(o + kPosition);
  s.R_WB = Quat(q(0), q(1), q(2), q(3)).normalized().toRotationMatrix();
  s.v_G = y.segment<3>(o + kVelocity);
  s.omega_W = s.R_WB * y.segment<3>(o + kOmegaBody);
  return s;
}

}  // namespace tumble
