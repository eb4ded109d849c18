#include "tumble/dynamics/force_elements.hpp"

#include "tumble/math/rotation.hpp"

namespace tumble {

const BodyState& state_or_ground(std::span<const BodyState> states, int body) {
  static const BodyState kGroundState{};
  return body == kGround ? kGroundState : states[static_cast<std::size_t>(body)];
}

ElementLoad calc_spring_load(const LinearSpring& spring, std::span<const BodyState> states) {
  const BodyState& a = state_or_ground(states, spring.body_a);
  const BodyState& b = state_or_ground(states, spring.body_b);
  // Attachment points from each COM (world axes) and their velocities.
  const Vec3 p_A_W = a.R_WB * spring.p_A_A;
  const Vec3 p_B_W = b.R_WB * spring.p_B_B;
  const Vec3 d_W = (b.r_G + p_B_W) - (a.r_G + p_A_W);
  const Vec3 v_rel_W =
      velocity_of_point(b.v_G, b.omega_W, p_B_W) - velocity_of_point(a.v_G, a.omega_W, p_A_W);
  const double length = d_W.norm();
  ElementLoad load;
  const double stretch = length - spring.rest_length;
  load.energy = 0.5 * spring.stiffness * stretch * stretch;
  if (length == 0.0) return load;
  const Vec3 u_W = d_W / length;  // from A's point to B's
  const double length_rate = u_W.dot(v_rel_W);
  const double tension = spring.stiffness * stretch + spring.damping * length_rate;
  load.F_b_W = -tension * u_W;
  load.M_b_W = p_B_W.cross(load.F_b_W);
  load.F_a_W = tension * u_W;
  load.M_a_W = p_A_W.cross(load.F_a_W);
  load.power = -tension * length_rate;
  return load;
}

ElementLoad calc_torsional_spring_load(const TorsionalSpring& spring,
                                       std::span<const BodyState> states, double hinge_angle,
                                       double hinge_rate, const Vec3& axis_W) {
  const BodyState& a = state_or_ground(states, spring.body_a);
  const BodyState& b = state_or_ground(states, spring.body_b);
  ElementLoad load;
  Vec3 M_b_W;
  const Vec3 omega_rel_W = b.omega_W - a.omega_W;
  if (spring.hinge >= 0) {
    const double theta = hinge_angle - spring.rest_angle;
    M_b_W = -(spring.stiffness * theta + spring.damping * hinge_rate) * axis_W;
    load.energy = 0.5 * spring.stiffness * theta * theta;
  } else {
    // B turned from its rest pose relative to A: R_WB = exp([theta n]x) R_WA R_AB_rest.
    const Vec3 theta_n_W = log_so3(b.R_WB * spring.R_AB_rest.transpose() * a.R_WB.transpose());
    M_b_W = -spring.stiffness * theta_n_W - spring.damping * omega_rel_W;
    load.energy = 0.5 * spring.stiffness * theta_n_W.squaredNorm();
  }
  // The pair M_b on B and -M_b on A does work at M_b . (omega_b - omega_a); across a hinge
  // omega_rel . axis is the hinge rate.
  load.power = M_b_W.dot(omega_rel_W);
  load.M_b_W = M_b_W;
  load.M_a_W = -M_b_W;
  return load;
}

}  // namespace tumble
