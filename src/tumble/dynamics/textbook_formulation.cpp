#include "tumble/dynamics/textbook_formulation.hpp"

#include "tumble/math/rotation.hpp"

namespace tumble {

namespace {

// Row-major view of the nine rotation components inside y.
using RowMajorMat3 = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;

}  // namespace

Eigen::Index TextbookFormulation::dimension() const {
  return static_cast<Eigen::Index>(body_count()) * kPerBody;
}

void TextbookFormulation::derivative(double /*t*/, const VecX& y, VecX& dydt) const {
  for (std::size_t i = 0; i < body_count(); ++i) {
    const RigidBody& body = model_.bodies[i];
    const Eigen::Index o = static_cast<Eigen::Index>(i) * kPerBody;
    const Mat3 R_WB = Eigen::Map<const RowMajorMat3>(y.data() + o + kRotation);
    const Vec3 omega_W = y.segment<3>(o + kOmegaWorld);

    Vec3 F_W = body.mass * model_.gravity_W;
    Vec3 M_G_W = Vec3::Zero();
    if (!model_.loads.empty()) {
      Vec3 F_applied_W;
      calc_applied_loads(model_, i, hybrid_.schedule_time, R_WB, F_applied_W, M_G_W);
      F_W += F_applied_W;
    }
    const Mat3 I_G_W = R_WB * body.I_G_B * R_WB.transpose();
    const Vec3 alpha_W = I_G_W.inverse() * (M_G_W - omega_W.cross(I_G_W * omega_W));
    const Mat3 R_dot = hat(omega_W) * R_WB;

    dydt.segment<3>(o + kPosition) = y.segment<3>(o + kVelocity);
    dydt.segment<3>(o + kVelocity) = F_W / body.mass;
    Eigen::Map<RowMajorMat3>(dydt.data() + o + kRotation) = R_dot;
    dydt.segment<3>(o + kOmegaWorld) = alpha_W;
  }
}

void TextbookFormulation::project(double /*t*/, VecX& /*y*/) const {}

void TextbookFormulation::pack(std::span<const BodyState> states, VecX& y) const {
  for (std::size_t i = 0; i < body_count(); ++i) {
    const Eigen::Index o = static_cast<Eigen::Index>(i) * kPerBody;
    y.segment<3>(o + kPosition) = states[i].r_G;
    y.segment<3>(o + kVelocity) = states[i].v_G;
    Eigen::Map<RowMajorMat3>(y.data() + o + kRotation) = states[i].R_WB;
    y.segment<3>(o + kOmegaWorld) = states[i].omega_W;
  }
}

BodyState TextbookFormulation::unpack(const VecX& y, std::size_t body) const {
  const Eigen::Index o = static_cast<Eigen::Index>(body) * kPerBody;
  BodyState s;
  s.r_G = y.segment<3>(o + kPosition);
  s.v_G = y.segment<3>(o + kVelocity);
  s.R_WB = Eigen::Map<const RowMajorMat3>(y.data() + o + kRotation);
  s.omega_W = y.segment<3>(o + kOmegaWorld);
  return s;
}

}  // namespace tumble
