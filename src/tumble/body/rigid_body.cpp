#include "tumble/body/rigid_body.hpp"

#include <utility>

namespace tumble {

RigidBody RigidBody::make(std::string name, double mass, const Mat3& I_G_B) {
  RigidBody body;
  body.name = std::move(name);
  body.mass = mass;
  body.I_G_B = I_G_B;
  body.I_G_B_inv = I_G_B.inverse();
  return body;
}

Mat3 calc_inertia_about_com_W(const RigidBody& body, const Mat3& R_WB) {
  return R_WB * body.I_G_B * R_WB.transpose();
}

Vec3 calc_linear_momentum(const RigidBody& body, const BodyState& s) {
  return body.mass * s.v_G;
}

Vec3 calc_angular_momentum_about_com_W(const RigidBody& body, const BodyState& s) {
  // I_G omega with I_G = R I_G_B R^T, evaluated as R (I_G_B (R^T omega)).
  return s.R_WB * (body.I_G_B * (s.R_WB.transpose() * s.omega_W));
}

Vec3 calc_angular_momentum_about_point_W(const RigidBody& body, const BodyState& s,
                                         const Vec3& r_O) {
  return (s.r_G - r_O).cross(body.mass * s.v_G) + calc_angular_momentum_about_com_W(body, s);
}

double calc_kinetic_energy(const RigidBody& body, const BodyState& s) {
  return 0.5 * body.mass * s.v_G.squaredNorm() +
         0.5 * s.omega_W.dot(calc_angular_momentum_about_com_W(body, s));
}

double calc_gravity_potential(const RigidBody& body, const BodyState& s, const Vec3& gravity_W) {
  return -body.mass * gravity_W.dot(s.r_G);
}

SystemQuantities calc_system_quantities(std::span<const RigidBody> bodies,
                                        std::span<const BodyState> states, const Vec3& gravity_W) {
  SystemQuantities q;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const RigidBody& body = bodies[i];
    const BodyState& s = states[i];
    // H_G once for the kinetic energy and the angular momentum: the same terms as
    // calc_kinetic_energy's and calc_angular_momentum_about_point_W's, in the same order.
    const Vec3 H_G_W = calc_angular_momentum_about_com_W(body, s);
    q.kinetic_energy += 0.5 * body.mass * s.v_G.squaredNorm() + 0.5 * s.omega_W.dot(H_G_W);
    q.potential_energy += calc_gravity_potential(body, s, gravity_W);
    q.linear_momentum += calc_linear_momentum(body, s);
    q.angular_momentum_about_origin += s.r_G.cross(body.mass * s.v_G) + H_G_W;
  }
  q.total_energy = q.kinetic_energy + q.potential_energy;
  return q;
}

}  // namespace tumble
