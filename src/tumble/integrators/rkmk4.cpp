#include "tumble/integrators/rkmk4.hpp"

#include <cmath>
#include <stdexcept>

namespace tumble {

namespace {

using Vec4 = Eigen::Vector4d;  // a quaternion as stored in the state: (w, x, y, z)

// Hamilton product q (x) p = (q_w p_w - q_v . p_v, q_w p_v + p_w q_v + q_v x p_v).
Vec4 quaternion_product(const Vec4& q, const Vec4& p) {
  const Vec3 qv = q.tail<3>();
  const Vec3 pv = p.tail<3>();
  Vec4 r;
  r[0] = q[0] * p[0] - qv.dot(pv);
  r.tail<3>() = q[0] * pv + p[0] * qv + qv.cross(pv);
  return r;
}

// The unit quaternion of the rotation vector theta: (cos(|theta|/2), sin(|theta|/2) theta/|theta|).
// Below |theta| = 1e-4 the factor sin(x/2)/x is its series 1/2 - x^2/48, whose next term
// (x^4/3840 < 3e-20) is below round-off.
Vec4 quaternion_exp(const Vec3& theta) {
  const double angle = theta.norm();
  const double factor = angle > 1e-4 ? std::sin(0.5 * angle) / angle : 0.5 - angle * angle / 48.0;
  Vec4 r;
  r[0] = std::cos(0.5 * angle);
  r.tail<3>() = factor * theta;
  return r;
}

}  // namespace

void Rkmk4::prepare(OdeSystem& system, Eigen::Index n) {
  quaternion_offsets_ = system.unit_quaternion_offsets();
  for (const Eigen::Index offset : quaternion_offsets_) {
    if (offset < 0 || offset + 4 > n) {
      throw std::invalid_argument(
          "rkmk4: a unit quaternion offset of the system lies outside the state; fix the "
          "system's unit_quaternion_offsets()");
    }
  }
  const auto slots = static_cast<Eigen::Index>(quaternion_offsets_.size());
  for (Eigen::Matrix3Xd& slope : slopes_) slope.setZero(3, slots);
  theta_.setZero(3, slots);
}

void Rkmk4::finish_dense_output(VecX& y_out) const {
  normalize_unit_quaternions(quaternion_offsets_, y_out);
}

void Rkmk4::calc_lie_algebra_slopes(const VecX& y, const VecX& f, const Eigen::Matrix3Xd& theta,
                                    Eigen::Matrix3Xd& slopes) const {
  for (std::size_t j = 0; j < quaternion_offsets_.size(); ++j) {
    const Eigen::Index offset = quaternion_offsets_[j];
    const auto col = static_cast<Eigen::Index>(j);
    // omega_B = 2 vec(conj(q) (x) q') / |q|^2, with vec(conj(q) (x) p) = q_w p_v - p_w q_v
    // - q_v x p_v; the division by |q|^2 keeps it exact for a q that is not quite unit.
    const Vec4 q = y.segment<4>(offset);
    const Vec4 q_dot = f.segment<4>(offset);
    const Vec3 qv = q.tail<3>();
    const Vec3 pv = q_dot.tail<3>();
    const Vec3 omega_B = (2.0 / q.squaredNorm()) * (q[0] * pv - q_dot[0] * qv - qv.cross(pv));
    const Vec3 u = theta.col(col);
    const Vec3 u_x_omega = u.cross(omega_B);
    slopes.col(col) = omega_B + 0.5 * u_x_omega + (1.0 / 12.0) * u.cross(u_x_omega);
  }
}

void Rkmk4::rotate_quaternions(const Eigen::Matrix3Xd& theta, VecX& y_out) const {
  for (std::size_t j = 0; j < quaternion_offsets_.size(); ++j) {
    const Eigen::Index offset = quaternion_offsets_[j];
    const Vec3 rotation = theta.col(static_cast<Eigen::Index>(j));
    y_out.segment<4>(offset) = quaternion_product(y_.segment<4>(offset), quaternion_exp(rotation));
  }
}

StepOutcome Rkmk4::step(double t_stop) {
  const step_control::FixedStepEnd end = begin_step(t_stop);
  const double h = end.t_new - t_;
  const double t_half = t_ + 0.5 * h;

  // Stage 1: Theta_1 = 0, so K_1 = omega_1.
  const VecX& k1 = f_current_;
  theta_.setZero();
  calc_lie_algebra_slopes(y_, k1, theta_, slopes_[0]);

  theta_ = (0.5 * h) * slopes_[0];
  y_stage_ = y_ + (0.5 * h) * k1;
  rotate_quaternions(theta_, y_stage_);
  system_->derivative(t_half, y_stage_, k2_);
  calc_lie_algebra_slopes(y_stage_, k2_, theta_, slopes_[1]);

  theta_ = (0.5 * h) * slopes_[1];
  y_stage_ = y_ + (0.5 * h) * k2_;
  rotate_quaternions(theta_, y_stage_);
  system_->derivative(t_half, y_stage_, k3_);
  calc_lie_algebra_slopes(y_stage_, k3_, theta_, slopes_[2]);

  theta_ = h * slopes_[2];
  y_stage_ = y_ + h * k3_;
  rotate_quaternions(theta_, y_stage_);
  system_->derivative(end.t_new, y_stage_, k4_);
  calc_lie_algebra_slopes(y_stage_, k4_, theta_, slopes_[3]);
  stats_.rhs_evaluations += 3;

  theta_ = (h / 6.0) * (slopes_[0] + 2.0 * slopes_[1] + 2.0 * slopes_[2] + slopes_[3]);
  y_new_ = y_ + (h / 6.0) * (k1 + 2.0 * k2_ + 2.0 * k3_ + k4_);
  rotate_quaternions(theta_, y_new_);
  return accept_step(end);
}

}  // namespace tumble
