// Free bodies under gravity and applied loads, against closed-form motions: Newton-Euler with a
// constant torque about a principal axis, a force through the COM and off it, a load switched
// on a schedule (the driver must land on the switching times), and a spinning projectile whose
// COM follows the particle parabola while its rotation stays torque-free.
#include <gtest/gtest.h>

#include <cmath>

#include "tumble/dynamics/body_frame_formulation.hpp"
#include "tumble/dynamics/textbook_formulation.hpp"
#include "tumble/exact/torque_free.hpp"
#include "tumble/integrators/driver.hpp"
#include "tumble/math/rotation.hpp"
#include "tumble/simulation/make_formulation.hpp"

namespace tumble {
namespace {

BodyState run_to(Formulation& system, const BodyState& s0, const std::string& method, double t_end,
                 IntegrationReport* report_out = nullptr) {
  StepControl control;
  control.rtol = 1e-10;
  control.atol = 1e-13;
  auto integrator = make_integrator(method, control);
  VecX y0(system.dimension());
  system.pack(std::span<const BodyState>(&s0, 1), y0);
  BodyState last;
  const IntegrationReport r = integrate(*integrator, system, 0.0, y0, t_end, DriverOptions{},
                                        [&](double, const VecX& y) { last = system.unpack(y, 0); });
  EXPECT_TRUE(r.completed) << r.failure;
  if (report_out != nullptr) *report_out = r;
  return last;
}

Model one_body(double mass, const Vec3& I_diag, const Vec3& gravity) {
  Model m;
  m.gravity_W = gravity;
  m.bodies.push_back(RigidBody::make("body", mass, I_diag.asDiagonal()));
  return m;
}

// A constant torque Q about a principal axis from rest: I dw/dt = Q, so w = Q t / I and the
// angle turned is Q t^2 / (2 I) (6.6: sum of moments = I_G alpha + omega x I_G omega, with the
// gyroscopic term zero for a spin about a principal axis).
TEST(AppliedLoads, ConstantTorqueAboutAPrincipalAxis) {
  for (const std::string formulation : {"body", "textbook"}) {
    for (const double Q : {0.2, 3.0}) {
      Model m = one_body(2.0, Vec3(0.5, 0.8, 1.1), Vec3::Zero());
      AppliedLoad torque;
      torque.kind = AppliedLoad::Kind::Torque;
      torque.value = Vec3(0.0, Q, 0.0);
      m.loads.push_back(torque);
      auto system = make_formulation(formulation, m);
      const double t = 2.0;
      const BodyState s = run_to(*system, BodyState{}, "dopri5", t);
      const double I = 0.8;
      EXPECT_NEAR(s.omega_W.y(), Q * t / I, 1e-9 * Q * t / I) << formulation;
      const Mat3 R_exact = rotation_from_axis_angle(Vec3::UnitY(), Q * t * t / (2 * I));
      EXPECT_LT((s.R_WB - R_exact).cwiseAbs().maxCoeff(), 1e-8) << formulation;
    }
  }
}

// A force F at a point offset d from the COM, normal to the offset, applied in body axes so it
// turns with the body: the COM accelerates as F/M in the turning direction, and the body spins
// up with I w' = d F. Checked in the world frame: the body frame value [0, F, 0] at p = [d, 0, 0]
// gives w(t) = d F t / I_zz about z, and the COM velocity is the integral of R(t) F / M, with
// R(t) a rotation about z by theta(t) = d F t^2 / (2 I_zz): v_x = -(F/M) int sin, v_y = (F/M) int
// cos. Compared with a quadrature of those integrals.
TEST(AppliedLoads, BodyFixedForceOffTheCentreOfMass) {
  const double M = 3.0, F = 1.5, d = 0.4, Izz = 0.6;
  Model m = one_body(M, Vec3(0.3, 0.5, Izz), Vec3::Zero());
  AppliedLoad force;
  force.value = Vec3(0.0, F, 0.0);
  force.body_frame = true;
  force.p_GP_B = Vec3(d, 0.0, 0.0);
  m.loads.push_back(force);
  BodyFrameFormulation system(m);
  const double t_end = 1.5;
  const BodyState s = run_to(system, BodyState{}, "dop853", t_end);
  const double k = d * F / (2 * Izz);  // theta = k t^2
  EXPECT_NEAR(s.omega_W.z(), 2 * k * t_end, 1e-9);
  // Simpson's rule with 20000 panels: error ~ h^4 * max|f''''| ~ 1e-17.
  const int n = 20000;
  double int_sin = 0.0, int_cos = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double t = t_end * i / n;
    const double w = (i == 0 || i == n) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
    int_sin += w * std::sin(k * t * t);
    int_cos += w * std::cos(k * t * t);
  }
  int_sin *= t_end / n / 3.0;
  int_cos *= t_end / n / 3.0;
  EXPECT_NEAR(s.v_G.x(), -F / M * int_sin, 1e-9);
  EXPECT_NEAR(s.v_G.y(), F / M * int_cos, 1e-9);
}

// A torque switched on for 0.3 <= t < 1.1 only: the driver lands a step on each switching time,
// so the final spin is exactly Q (1.1 - 0.3) / I, not smeared by a step straddling a switch.
TEST(AppliedLoads, ScheduledTorqueActsExactlyOverItsInterval) {
  for (const std::string method : {"dopri5", "dop853", "rk4", "rkmk4"}) {
    Model m = one_body(1.0, Vec3(2.0, 2.0, 2.0), Vec3::Zero());
    AppliedLoad torque;
    torque.kind = AppliedLoad::Kind::Torque;
    torque.value = Vec3(0.0, 0.0, 4.0);
    torque.from = 0.3;
    torque.to = 1.1;
    m.loads.push_back(torque);
    BodyFrameFormulation system(m);
    StepControl control;
    control.rtol = 1e-10;
    control.atol = 1e-13;
    control.fixed_step = 0.07;  // deliberately not a divisor of 0.3 or 1.1
    auto integrator = make_integrator(method, control);
    VecX y0(system.dimension());
    const BodyState s0;
    system.pack(std::span<const BodyState>(&s0, 1), y0);
    BodyState last;
    const IntegrationReport r =
        integrate(*integrator, system, 0.0, y0, 2.0, DriverOptions{},
                  [&](double, const VecX& y) { last = system.unpack(y, 0); });
    ASSERT_TRUE(r.completed) << r.failure;
    // Constant acceleration inside the interval: every RK method of order >= 1 is exact on it.
    EXPECT_NEAR(last.omega_W.z(), 4.0 * 0.8 / 2.0, 1e-13) << method;
    // Angle: 0.8^2 * 2 / 2 = 0.64 during, then 1.6 rad/s for 0.9 s. The rotation is not
    // polynomial in t, so only the adaptive methods are held to their tolerance here (global
    // error ~1e-10 over 2 rad); the fixed-step ones to their O(h^4) error at h = 0.07.
    const double angle = 0.5 * 2.0 * 0.8 * 0.8 + 1.6 * 0.9;
    const double tolerance = integrator->adaptive() ? 1e-8 : 1e-4;
    EXPECT_LT((last.R_WB - rotation_from_axis_angle(Vec3::UnitZ(), angle)).cwiseAbs().maxCoeff(),
              tolerance)
        << method;
  }
}

// A spinning projectile: gravity acts at the COM, so r_G(t) = r0 + v0 t + g t^2 / 2 exactly, the
// rotation is the torque-free Euler-Poinsot motion, and E = T + U is conserved.
TEST(AppliedLoads, SpinningProjectileFollowsTheParabolaAndTheFreeRotation) {
  const Vec3 g(0.0, 0.0, -9.81);
  const Vec3 I(0.004, 0.004, 0.0007);  // a bottle-like cylinder
  for (const std::string formulation : {"body", "textbook"}) {
    auto system = make_formulation(formulation, one_body(0.9, I, g));
    BodyState s0;
    s0.r_G = Vec3(0.0, 0.0, 1.5);
    s0.v_G = Vec3(8.0, 0.0, 8.0);
    s0.R_WB = rotation_from_axis_angle(Vec3::UnitY(), 0.35);
    s0.omega_W = Vec3(8.0, 1.5, 23.0);
    const double t = 1.7;
    const BodyState s = run_to(*system, s0, "dop853", t);
    const Vec3 r_exact = s0.r_G + s0.v_G * t + 0.5 * g * t * t;
    EXPECT_LT((s.r_G - r_exact).norm(), 1e-9 * r_exact.norm()) << formulation;
    const TorqueFreeMotion rotation(I.asDiagonal(), s0.R_WB, s0.omega_W);
    EXPECT_LT((s.R_WB - rotation.R_WB(t)).cwiseAbs().maxCoeff(), 1e-8) << formulation;
    EXPECT_LT((s.omega_W - rotation.omega_W(t)).norm(), 1e-8 * s0.omega_W.norm()) << formulation;
    const RigidBody& body = system->model().bodies[0];
    const double E0 = calc_kinetic_energy(body, s0) + calc_gravity_potential(body, s0, g);
    const double E = calc_kinetic_energy(body, s) + calc_gravity_potential(body, s, g);
    EXPECT_NEAR(E, E0, 1e-9 * std::abs(E0)) << formulation;
  }
}

// OdeSystem's quaternion contract, which lets dopri5 renormalise without evaluating f again:
// scaling q scales its four derivatives by the same factor and leaves every other component of
// f unchanged, here with loads that use the rotation (a body-frame force at an offset point).
TEST(BodyFrameFormulation, RescalingTheQuaternionRescalesOnlyItsDerivative) {
  Model m = one_body(1.5, Vec3(0.4, 0.9, 1.2), Vec3(0.0, 0.0, -9.81));
  AppliedLoad force;
  force.value = Vec3(0.3, -1.0, 0.2);
  force.body_frame = true;
  force.p_GP_B = Vec3(0.1, 0.2, -0.3);
  m.loads.push_back(force);
  BodyFrameFormulation system(m);
  system.begin(0.0, VecX());
  BodyState s;
  s.R_WB = rotation_from_axis_angle(Vec3(1.0, -2.0, 0.5), 0.9);
  s.omega_W = Vec3(0.7, 1.1, -0.4);
  s.v_G = Vec3(1.0, 2.0, 3.0);
  VecX y(13), y_scaled(13), f(13), f_scaled(13);
  system.pack(std::span<const BodyState>(&s, 1), y);
  y_scaled = y;
  y_scaled.segment<4>(BodyFrameFormulation::kQuaternion) *= 1.0 + 3e-7;  // drifted norm
  system.derivative(0.0, y_scaled, f_scaled);
  system.derivative(0.0, y, f);
  VecX f_rescaled = f_scaled;
  ASSERT_TRUE(
      rescale_quaternion_derivatives(system.unit_quaternion_offsets(), y_scaled, y, f_rescaled));
  EXPECT_LT((f_rescaled - f).cwiseAbs().maxCoeff(), 1e-15);
  // Any change outside the quaternion is refused: f must then be evaluated again.
  VecX y_moved = y;
  y_moved(0) += 1e-9;
  EXPECT_FALSE(
      rescale_quaternion_derivatives(system.unit_quaternion_offsets(), y, y_moved, f_rescaled));
}

// The chapter's momentum and energy formulas (6.6, table "3D") on one hand-computed state.
TEST(BodyQuantities, MomentaAndEnergyMatchTheChapterFormulas) {
  const RigidBody body = RigidBody::make("b", 2.0, Vec3(1.0, 2.0, 3.0).asDiagonal());
  BodyState s;
  s.r_G = Vec3(1.0, 0.0, 0.0);
  s.v_G = Vec3(0.0, 3.0, 0.0);
  s.R_WB = rotation_from_axis_angle(Vec3::UnitZ(), M_PI / 2);  // body x -> world y
  s.omega_W = Vec3(0.0, 1.0, 1.0);                             // = body (1, 0, 1) in body axes
  // I_G (world) = R diag(1,2,3) R^T = diag(2, 1, 3): h_G = (0, 1, 3).
  EXPECT_LT((calc_angular_momentum_about_com_W(body, s) - Vec3(0, 1, 3)).norm(), 1e-15);
  // h_O = r_G x M v_G + I_G omega = (1,0,0) x (0,6,0) + (0,1,3) = (0, 1, 9).
  EXPECT_LT((calc_angular_momentum_about_point_W(body, s, Vec3::Zero()) - Vec3(0, 1, 9)).norm(),
            1e-15);
  // T = M v.v / 2 + omega . I omega / 2 = 9 + (1 + 3) / 2 = 11.
  EXPECT_NEAR(calc_kinetic_energy(body, s), 11.0, 1e-14);
  EXPECT_NEAR(calc_gravity_potential(body, s, Vec3(0, 0, -9.81)), 0.0, 1e-15);
}

}  // namespace
}  // namespace tumble
