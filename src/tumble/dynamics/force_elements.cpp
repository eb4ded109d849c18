#include "tumble/dynamics/force_elements.hpp"

#include "tumble/math/dual.hpp"
#include "tumble/math/rotation.hpp"

namespace tumble {

template <typename S>
ElementLoadOf<S> calc_spring_load(const LinearSpring& spring,
                                  std::span<const BodyStateOf<S>> states) {
  using std::sqrt;
  const BodyStateOf<S>& a = state_or_ground(states, spring.body_a);
  const BodyStateOf<S>& b = state_or_ground(states, spring.body_b);
  // Attachment points from each COM (world axes) and their velocities.
  const Vec3Of<S> p_A_W = a.R_WB * spring.p_A_A.cast<S>();
  const Vec3Of<S> p_B_W = b.R_WB * spring.p_B_B.cast<S>();
  const Vec3Of<S> d_W = (b.r_G + p_B_W) - (a.r_G + p_A_W);
  const Vec3Of<S> v_rel_W =
      velocity_of_point<S>(b.v_G, b.omega_W, p_B_W) - velocity_of_point<S>(a.v_G, a.omega_W, p_A_W);
  const S length = sqrt(d_W.squaredNorm());
  ElementLoadOf<S> load;
  const S stretch = length - spring.rest_length;
  load.energy = 0.5 * spring.stiffness * stretch * stretch;
  if (value_of(length) == 0.0) return load;
  const Vec3Of<S> u_W = d_W / length;  // from A's point to B's
  const S length_rate = u_W.dot(v_rel_W);
  const S tension = spring.stiffness * stretch + spring.damping * length_rate;
  load.F_b_W = -tension * u_W;
  load.M_b_W = p_B_W.cross(load.F_b_W);
  load.F_a_W = tension * u_W;
  load.M_a_W = p_A_W.cross(load.F_a_W);
  load.power = -tension * length_rate;
  return load;
}

template <typename S>
ElementLoadOf<S> calc_torsional_spring_load(const TorsionalSpring& spring,
                                            std::span<const BodyStateOf<S>> states,
                                            const S& hinge_angle, const S& hinge_rate,
                                            const Vec3Of<S>& axis_W) {
  const BodyStateOf<S>& a = state_or_ground(states, spring.body_a);
  const BodyStateOf<S>& b = state_or_ground(states, spring.body_b);
  ElementLoadOf<S> load;
  Vec3Of<S> M_b_W;
  const Vec3Of<S> omega_rel_W = b.omega_W - a.omega_W;
  if (spring.hinge >= 0) {
    const S theta = hinge_angle - spring.rest_angle;
    M_b_W = -(spring.stiffness * theta + spring.damping * hinge_rate) * axis_W;
    load.energy = 0.5 * spring.stiffness * theta * theta;
  } else {
    // B turned from its rest pose relative to A: R_WB = exp([theta n]x) R_WA R_AB_rest.
    const Vec3Of<S> theta_n_W =
        log_so3<S>(b.R_WB * spring.R_AB_rest.transpose().cast<S>() * a.R_WB.transpose());
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

template <typename S>
ElementLoadOf<S> calc_loop_motor_load(const JointModel& joint,
                                      std::span<const BodyStateOf<S>> states) {
  const BodyStateOf<S>& a = state_or_ground(states, joint.body_a);
  const BodyStateOf<S>& b = state_or_ground(states, joint.body_b);
  const bool about_first_axis = joint.type == JointType::Universal && joint.motor.freedom == 0;
  const Vec3Of<S> axis_W = about_first_axis ? Vec3Of<S>(a.R_WB * joint.axis_A.cast<S>())
                                            : Vec3Of<S>(b.R_WB * joint.axis_B.cast<S>());
  const bool slides = joint.type == JointType::Prismatic ||
                      (joint.type == JointType::Cylindrical && joint.motor.freedom == 1);
  ElementLoadOf<S> load;
  if (slides) {
    // At B's joint point, which A's material point there meets.
    const Vec3Of<S> p_B_W = b.R_WB * joint.p_BJ_B.cast<S>();
    const Vec3Of<S> p_A_W = b.r_G + p_B_W - a.r_G;
    const Vec3Of<S> F_W = S(joint.motor.value) * axis_W;
    load.F_b_W = F_W;
    load.M_b_W = p_B_W.cross(F_W);
    load.F_a_W = -F_W;
    load.M_a_W = -p_A_W.cross(F_W);
    load.power = F_W.dot(velocity_of_point<S>(b.v_G, b.omega_W, p_B_W) -
                         velocity_of_point<S>(a.v_G, a.omega_W, p_A_W));
  } else {
    const Vec3Of<S> M_W = S(joint.motor.value) * axis_W;
    load.M_b_W = M_W;
    load.M_a_W = -M_W;
    load.power = M_W.dot(b.omega_W - a.omega_W);
  }
  return load;
}

template ElementLoadOf<double> calc_loop_motor_load<double>(const JointModel&,
                                                            std::span<const BodyStateOf<double>>);
template ElementLoadOf<Dual> calc_loop_motor_load<Dual>(const JointModel&,
                                                        std::span<const BodyStateOf<Dual>>);
template ElementLoadOf<double> calc_spring_load<double>(const LinearSpring&,
                                                        std::span<const BodyStateOf<double>>);
template ElementLoadOf<Dual> calc_spring_load<Dual>(const LinearSpring&,
                                                    std::span<const BodyStateOf<Dual>>);
template ElementLoadOf<double> calc_torsional_spring_load<double>(
    const TorsionalSpring&, std::span<const BodyStateOf<double>>, const double&, const double&,
    const Vec3Of<double>&);
template ElementLoadOf<Dual> calc_torsional_spring_load<Dual>(const TorsionalSpring&,
                                                              std::span<const BodyStateOf<Dual>>,
                                                              const Dual&, const Dual&,
                                                              const Vec3Of<Dual>&);

}  // namespace tumble
