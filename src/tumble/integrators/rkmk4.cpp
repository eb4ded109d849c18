#include "tumble/integrators/rkmk4.hpp"

#include <cmath>
#include <stdexcept>

#include "tumble/integrators/hermite.hpp"
#include "tumble/integrators/step_size_control.hpp"

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

Rkmk4::Rkmk4(const StepControl& control) {
  step_control::validate_fixed(name(), control);
  h_ = control.fixed_step;
}

void Rkmk4::start(OdeSystem& system, double t0, const VecX& y0, double t_end) {
  step_control::validate_start(name(), system, t0, y0, t_end);
  system_ = &system;
  quaternion_offsets_ = system.unit_quaternion_offsets();
  for (const Eigen::Index offset : quaternion_offsets_) {
    if (offset < 0 || offset + 4 > y0.size()) {
      throw std::invalid_argument(
          "rkmk4: a unit quaternion offset of the system lies outside the state; fix the "
          "system's unit_quaternion_offsets()");
    }
  }
  const Eigen::Index n = y0.size();
  const auto slots = static_cast<Eigen::Index>(quaternion_offsets_.size());
  f_previous_.setZero(n);
  f_current_.setZero(n);
  k2_.setZero(n);
  k3_.setZero(n);
  k4_.setZero(n);
  y_stage_.setZero(n);
  y_new_.setZero(n);
  for (Eigen::Matrix3Xd& slope : slopes_) slope.setZero(3, slots);
  theta_.setZero(3, slots);
  direction_ = t_end > t0 ? 1.0 : -1.0;
  stats_ = IntegratorStats{};
  restart(t0, y0);
}

void Rkmk4::restart(double t, const VecX& y) {
  if (system_ == nullptr) throw std::logic_error("rkmk4: restart() before start()");
  if (y.size() != f_current_.size()) {
    throw std::invalid_argument("rkmk4: restart() with a wrong-size y");
  }
  t_ = t_previous_ = t_grid_ = t;
  grid_steps_ = 0;
  y_ = y;
  y_previous_ = y;
  system_->derivative(t_, y_, f_current_);
  ++stats_.rhs_evaluations;
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
  if (system_ == nullptr) throw std::logic_error("rkmk4: step() before start()");
  step_control::require_ahead(name(), t_, t_stop, direction_);
  const step_control::FixedStepEnd end =
      step_control::next_fixed_step_end(t_grid_, grid_steps_, h_, direction_, t_stop);
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
  if (!y_new_.allFinite()) return StepOutcome::NonFiniteState;

  y_previous_.swap(y_);
  y_.swap(y_new_);
  system_->project(end.t_new, y_);
  f_previous_.swap(f_current_);
  system_->derivative(end.t_new, y_, f_current_);
  ++stats_.rhs_evaluations;
  t_previous_ = t_;
  t_ = end.t_new;
  if (end.lands) {
    t_grid_ = end.t_new;
    grid_steps_ = 0;
  } else {
    ++grid_steps_;
  }
  ++stats_.accepted_steps;
  return StepOutcome::Ok;
}

void Rkmk4::dense_output(double t, VecX& y_out) const {
  if (t_ == t_previous_) {  // no step since start or restart
    y_out = y_;
    return;
  }
  hermite_interpolate(t_previous_, y_previous_, f_previous_, t_, y_, f_current_, t, y_out);
  normalize_unit_quaternions(quaternion_offsets_, y_out);
}

}  // namespace tumble
