// The explicit time-stepping methods (dopri5, dop853, rk4, rkmk4; radau5 has radau5_test.cpp)
// against closed-form solutions: order of convergence, error against tolerance, the continuous
// extensions, step-size control by hand, landing on stop times, restarts, failures, and the
// evaluation counts each design implies.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "test_constants.hpp"
#include "test_math.hpp"
#include "tumble/integrators/integrator.hpp"

namespace tumble {
namespace {

using test::kEps;

// ---------------------------------------------------------------------------------------------
// Test systems with closed-form solutions.

// x'' = -x as y = (x, v): x(t) = x0 cos t + v0 sin t, v(t) = -x0 sin t + v0 cos t.
class Oscillator : public OdeSystem {
 public:
  Eigen::Index dimension() const override { return 2; }
  void derivative(double /*t*/, const VecX& y, VecX& dydt) const override {
    dydt[0] = y[1];
    dydt[1] = -y[0];
  }
  static VecX exact(double t, double t0, const VecX& y0) {
    const double c = std::cos(t - t0), s = std::sin(t - t0);
    VecX y(2);
    y << y0[0] * c + y0[1] * s, -y0[0] * s + y0[1] * c;
    return y;
  }
};

// y' = -y: y(t) = y0 exp(-(t - t0)).
class Decay : public OdeSystem {
 public:
  Eigen::Index dimension() const override { return 1; }
  void derivative(double /*t*/, const VecX& y, VecX& dydt) const override { dydt[0] = -y[0]; }
};

// y' = y^2, y(0) = 1: y = 1 / (1 - t), infinite at t = 1.
class BlowUp : public OdeSystem {
 public:
  Eigen::Index dimension() const override { return 1; }
  void derivative(double /*t*/, const VecX& y, VecX& dydt) const override { dydt[0] = y[0] * y[0]; }
};

// y' = -y until t = 0.3, then f is NaN (a model evaluated outside its domain).
class NanAfter : public OdeSystem {
 public:
  static constexpr double kTBad = 0.3;
  Eigen::Index dimension() const override { return 1; }
  void derivative(double t, const VecX& y, VecX& dydt) const override {
    dydt[0] = t > kTBad ? std::numeric_limits<double>::quiet_NaN() : -y[0];
  }
};

// y' = -50 y, whose solution stays positive, with f NaN for y < 0 (a model outside its domain):
// a step near the explicit methods' stability limit has stages that overshoot below 0.
class NanBelowZero : public OdeSystem {
 public:
  mutable int nan_evaluations = 0;
  Eigen::Index dimension() const override { return 1; }
  void derivative(double /*t*/, const VecX& y, VecX& dydt) const override {
    if (y[0] < 0.0) ++nan_evaluations;
    dydt[0] = y[0] < 0.0 ? std::numeric_limits<double>::quiet_NaN() : -50.0 * y[0];
  }
};

Quat quaternion_at(const VecX& y, Eigen::Index offset) {
  return Quat(y[offset], y[offset + 1], y[offset + 2], y[offset + 3]);
}

void set_quaternion(VecX& y, Eigen::Index offset, const Quat& q) {
  y.segment<4>(offset) << q.w(), q.x(), q.y(), q.z();
}

using test::quaternion_rate;

// The torque-free rotation of an axisymmetric rigid body, I = diag(I1, I1, I3), state
// (q (4), omega_B (3)): q' = q (x) (0, omega_B) / 2, I omega_B' = -omega_B x I omega_B.
// Closed form (e.g. Landau-Lifshitz, Mechanics, section 33): omega_B turns about the symmetry
// axis e3 at the rate -b, b = (I1 - I3) omega_3 / I1, and the attitude is a precession about the
// world angular momentum L_W at the rate |L| / I1 composed with a body spin b about e3:
//   R(t) = exp(|L|/I1 t [n_W]) R0 exp(b t [e3]),  n_W = L_W / |L|;
// differentiating gives R^T R' = [L_B(t)/I1 + b e3] = [omega_B(t)].
class AxisymmetricBody : public OdeSystem {
 public:
  static constexpr double kI1 = 2.0, kI3 = 1.0;  // kg m^2
  explicit AxisymmetricBody(bool projects = true) : projects_(projects) {}
  Eigen::Index dimension() const override { return 7; }
  std::span<const Eigen::Index> unit_quaternion_offsets() const override { return offsets_; }
  void derivative(double /*t*/, const VecX& y, VecX& dydt) const override {
    const Vec3 omega_B = y.segment<3>(4);
    quaternion_rate(y, 0, omega_B, dydt);
    const Vec3 inertia(kI1, kI1, kI3);
    const Vec3 L_B = inertia.cwiseProduct(omega_B);
    dydt.segment<3>(4) = (-omega_B.cross(L_B)).cwiseQuotient(inertia);
  }
  void project(double t, VecX& y) const override {
    if (projects_) OdeSystem::project(t, y);
  }
  static VecX initial_state() {
    VecX y(7);
    const Quat q0(Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, -0.5).normalized()));
    set_quaternion(y, 0, q0);
    y.segment<3>(4) = Vec3(0.4, -0.3, 1.5);  // rad/s
    return y;
  }
  static VecX exact(double t, const VecX& y0) {
    const Quat q0 = quaternion_at(y0, 0);
    const Vec3 omega0 = y0.segment<3>(4);
    const Vec3 L_W = q0 * Vec3(kI1 * omega0.x(), kI1 * omega0.y(), kI3 * omega0.z());
    const double b = (kI1 - kI3) * omega0.z() / kI1;
    const Quat precession(Eigen::AngleAxisd(L_W.norm() / kI1 * t, L_W.normalized()));
    const Quat spin(Eigen::AngleAxisd(b * t, Vec3::UnitZ()));
    VecX y(7);
    set_quaternion(y, 0, precession * q0 * spin);
    y.segment<3>(4) = Eigen::AngleAxisd(-b * t, Vec3::UnitZ()) * omega0;
    return y;
  }

 private:
  static constexpr Eigen::Index offsets_[1] = {0};
  bool projects_;
};

// A body spinning at a constant omega_B, with one plain component x' = cos t beside the
// quaternion: q(t) = q0 (x) exp(t omega_B / 2), x(t) = x0 + sin t.
class ConstantSpin : public OdeSystem {
 public:
  static inline const Vec3 kOmega_B{0.3, -1.1, 2.0};  // rad/s
  Eigen::Index dimension() const override { return 5; }
  std::span<const Eigen::Index> unit_quaternion_offsets() const override { return offsets_; }
  void derivative(double t, const VecX& y, VecX& dydt) const override {
    dydt[0] = std::cos(t);
    quaternion_rate(y, 1, kOmega_B, dydt);
  }
  static VecX initial_state() {
    VecX y(5);
    y[0] = 0.25;
    set_quaternion(y, 1, Quat(Eigen::AngleAxisd(1.2, Vec3(0.0, 1.0, 1.0).normalized())));
    return y;
  }
  static VecX exact(double t, const VecX& y0) {
    VecX y(5);
    y[0] = y0[0] + std::sin(t);
    const Quat turn(Eigen::AngleAxisd(kOmega_B.norm() * t, kOmega_B.normalized()));
    set_quaternion(y, 1, quaternion_at(y0, 1) * turn);
    return y;
  }

 private:
  static constexpr Eigen::Index offsets_[1] = {1};
};

// Wraps a system and counts what the integrator asks of it, to check the reported statistics.
class Counting : public OdeSystem {
 public:
  explicit Counting(OdeSystem& inner) : inner_(inner) {}
  Eigen::Index dimension() const override { return inner_.dimension(); }
  std::span<const Eigen::Index> unit_quaternion_offsets() const override {
    return inner_.unit_quaternion_offsets();
  }
  void derivative(double t, const VecX& y, VecX& dydt) const override {
    ++evaluations;
    inner_.derivative(t, y, dydt);
  }
  void project(double t, VecX& y) const override {
    const VecX before = y;
    inner_.project(t, y);
    if (y != before) ++projections_that_moved;
  }
  mutable long evaluations = 0;
  mutable long projections_that_moved = 0;

 private:
  OdeSystem& inner_;
};

// ---------------------------------------------------------------------------------------------
// Helpers.

StepControl tolerances(double rtol, double atol) {
  StepControl control;
  control.rtol = rtol;
  control.atol = atol;
  return control;
}

StepControl fixed(double h) {
  StepControl control;
  control.fixed_step = h;
  return control;
}

// Quaternion distance that ignores the sign (q and -q are one rotation).
double quaternion_error(const VecX& y, const VecX& exact, Eigen::Index offset) {
  const Eigen::Vector4d q = y.segment<4>(offset), q_exact = exact.segment<4>(offset);
  return std::min((q - q_exact).cwiseAbs().maxCoeff(), (q + q_exact).cwiseAbs().maxCoeff());
}

double state_error(const VecX& y, const VecX& exact, bool has_quaternion_at_0) {
  if (!has_quaternion_at_0) return (y - exact).cwiseAbs().maxCoeff();
  return std::max(quaternion_error(y, exact, 0),
                  (y.tail(y.size() - 4) - exact.tail(exact.size() - 4)).cwiseAbs().maxCoeff());
}

// Steps to t_end, calling visit(integrator) after every accepted step; fails the test on any
// outcome other than Ok.
template <typename Visit>
void run(Integrator& integrator, OdeSystem& system, double t0, const VecX& y0, double t_end,
         Visit visit) {
  integrator.start(system, t0, y0, t_end);
  while (integrator.t() < t_end) {
    ASSERT_EQ(integrator.step(t_end), StepOutcome::Ok) << " at t = " << integrator.t();
    ASSERT_LE(integrator.t(), t_end);
    visit(integrator);
  }
}

// The largest error at the step ends of a run against `exact`.
template <typename Exact>
double max_step_error(Integrator& integrator, OdeSystem& system, const VecX& y0, double t_end,
                      Exact exact, bool quaternion) {
  double worst = 0.0;
  run(integrator, system, 0.0, y0, t_end, [&](const Integrator& it) {
    worst = std::max(worst, state_error(it.y(), exact(it.t()), quaternion));
  });
  return worst;
}

// ---------------------------------------------------------------------------------------------
// Fixed-step methods: order 4.

// Global error at t_end for h, h/2, h/4, h/8: e(h) = C h^4 + O(h^5), so e(h) / e(h/2) = 16
// (1 + O(h)). The bracket [12, 20] allows the O(h) term a 25 % share, and the steps are chosen
// in the asymptotic range (measured errors 1.5e-4 .. 8e-11, far above round-off).
template <typename Exact>
void expect_fourth_order(const std::string& method, OdeSystem& system, const VecX& y0, double t_end,
                         double h0, Exact exact, bool quaternion) {
  std::vector<double> errors;
  for (double h = h0; h > h0 / 10.0; h /= 2.0) {
    auto integrator = make_integrator(method, fixed(h));
    integrator->start(system, 0.0, y0, t_end);
    while (integrator->t() < t_end) ASSERT_EQ(integrator->step(t_end), StepOutcome::Ok);
    errors.push_back(state_error(integrator->y(), exact(t_end), quaternion));
    std::printf("[   info   ] %s h %.4g: global error %.3g\n", method.c_str(), h, errors.back());
  }
  for (std::size_t i = 1; i < errors.size(); ++i) {
    const double ratio = errors[i - 1] / errors[i];
    EXPECT_GT(ratio, 12.0) << method << " halving " << i << ": errors " << errors[i - 1] << " -> "
                           << errors[i];
    EXPECT_LT(ratio, 20.0) << method << " halving " << i << ": errors " << errors[i - 1] << " -> "
                           << errors[i];
  }
}

TEST(FixedStep, Rk4AndRkmk4AreFourthOrderOnTheOscillator) {
  Oscillator system;
  VecX y0(2);
  y0 << 1.0, 0.5;
  auto exact = [&](double t) { return Oscillator::exact(t, 0.0, y0); };
  // Without quaternions rkmk4 is RK4 itself.
  expect_fourth_order("rk4", system, y0, 10.0, 0.2, exact, false);
  expect_fourth_order("rkmk4", system, y0, 10.0, 0.2, exact, false);
}

TEST(FixedStep, Rk4AndRkmk4AreFourthOrderOnTheFreeAxisymmetricBody) {
  AxisymmetricBody system;
  const VecX y0 = AxisymmetricBody::initial_state();
  auto exact = [&](double t) { return AxisymmetricBody::exact(t, y0); };
  // omega_B turns, so the rotation does not commute with itself over a step: a wrong sign or a
  // missing term in dexp^{-1} would drop rkmk4 to order 1 or 2.
  expect_fourth_order("rk4", system, y0, 4.0, 0.08, exact, true);
  expect_fourth_order("rkmk4", system, y0, 4.0, 0.08, exact, true);
}

TEST(FixedStep, Rkmk4IsExactForAConstantSpin) {
  ConstantSpin system;
  const VecX y0 = ConstantSpin::initial_state();
  auto rkmk4 = make_integrator("rkmk4", fixed(0.05));
  auto rk4 = make_integrator("rk4", fixed(0.05));
  const double t_end = 50.0;  // 1000 steps, 17 turns
  double error_rkmk4 = 0.0, error_rk4 = 0.0;
  run(*rkmk4, system, 0.0, y0, t_end, [&](const Integrator& it) {
    error_rkmk4 =
        std::max(error_rkmk4, quaternion_error(it.y(), ConstantSpin::exact(it.t(), y0), 1));
  });
  run(*rk4, system, 0.0, y0, t_end, [&](const Integrator& it) {
    error_rk4 = std::max(error_rk4, quaternion_error(it.y(), ConstantSpin::exact(it.t(), y0), 1));
  });
  // Every Theta_i is parallel to omega_B, so each step is the exact rotation exp(h omega_B / 2);
  // what is left is round-off in 1000 quaternion products and in the reference's own AngleAxis
  // (each ~ a few eps): 1000 * 4 eps = 9e-13 bounds it.
  EXPECT_LT(error_rkmk4, 1000 * 4 * kEps);
  // RK4 (with projection) makes a truncation error many orders larger at this step.
  EXPECT_GT(error_rk4, 1e3 * error_rkmk4);
  // The plain component x' = cos t takes ordinary RK4 steps: global error ~ h^4 / 180 * t.
  EXPECT_NEAR(rkmk4->y()[0], ConstantSpin::exact(t_end, y0)[0], 1e-6);
}

TEST(FixedStep, Rkmk4KeepsUnitQuaternionsWithoutProjection) {
  AxisymmetricBody system(/*projects=*/false);  // project() does nothing
  const VecX y0 = AxisymmetricBody::initial_state();
  auto rkmk4 = make_integrator("rkmk4", fixed(0.02));
  double worst_step_drift = 0.0;
  double norm_before = quaternion_at(y0, 0).norm();
  run(*rkmk4, system, 0.0, y0, 40.0, [&](const Integrator& it) {
    const double norm = quaternion_at(it.y(), 0).norm();
    worst_step_drift = std::max(worst_step_drift, std::abs(norm - norm_before));
    norm_before = norm;
  });
  // One step multiplies by a unit quaternion computed from cos and sin: its norm is 1 to an ulp
  // or two, so |q| changes by at most ~2 eps = 4.4e-16 per step (measured: 2.2e-16).
  EXPECT_LE(worst_step_drift, 2 * kEps);

  const double drift_rkmk4 = std::abs(quaternion_at(rkmk4->y(), 0).norm() - 1.0);
  // After 2000 steps the drift is a sum of such round-offs, at worst 2000 eps = 4.4e-13
  // (measured: 4.3e-15, a random walk).
  EXPECT_LT(drift_rkmk4, 2000 * kEps);

  // RK4 without projection leaves the sphere at its truncation error (measured 2.5e-10 here).
  auto rk4 = make_integrator("rk4", fixed(0.02));
  run(*rk4, system, 0.0, y0, 40.0, [](const Integrator&) {});
  const double drift_rk4 = std::abs(quaternion_at(rk4->y(), 0).norm() - 1.0);
  EXPECT_GT(drift_rk4, 1e-11);
  EXPECT_GT(drift_rk4, 100 * drift_rkmk4);
  std::printf("[   info   ] |q| - 1 after 2000 steps: rkmk4 %.3g (worst step %.3g), rk4 %.3g\n",
              drift_rkmk4, worst_step_drift, drift_rk4);
}

TEST(FixedStep, DenseOutputIsHermiteAndKeepsQuaternionsUnit) {
  AxisymmetricBody system;
  const VecX y0 = AxisymmetricBody::initial_state();
  for (const std::string method : {"rk4", "rkmk4"}) {
    const double h = 0.05;
    auto integrator = make_integrator(method, fixed(h));
    double worst_dense = 0.0, worst_end = 0.0, worst_unit = 0.0;
    VecX y_mid(7);
    run(*integrator, system, 0.0, y0, 4.0, [&](const Integrator& it) {
      worst_end =
          std::max(worst_end, state_error(it.y(), AxisymmetricBody::exact(it.t(), y0), true));
      for (const double s : {0.25, 0.5, 0.75}) {
        const double t = it.t_previous() + s * (it.t() - it.t_previous());
        it.dense_output(t, y_mid);
        worst_dense =
            std::max(worst_dense, state_error(y_mid, AxisymmetricBody::exact(t, y0), true));
        if (method == "rkmk4") {
          worst_unit = std::max(worst_unit, std::abs(quaternion_at(y_mid, 0).norm() - 1.0));
        }
      }
    });
    // The Hermite cubic's own error is O(h^4) locally, the same order as the global error of
    // the steps: within a factor 2 of it here.
    EXPECT_LT(worst_dense, 2.0 * worst_end + 1e-12) << method;
    std::printf("[   info   ] %s Hermite dense/step error ratio %.3g\n", method.c_str(),
                worst_dense / worst_end);
    EXPECT_LT(worst_unit, 4 * kEps) << method;  // normalised: unit to round-off
  }
}

// ---------------------------------------------------------------------------------------------
// Adaptive methods: error against tolerance, cost, continuous extension.

// Global error on the oscillator over 10 s (1.6 periods), atol = rtol 1e-3 so that rtol governs
// (|y| ~ 1). The largest errors at the step ends, as multiples of rtol, measured:
//   dopri5: 1e-6 -> 0.58, 1e-8 -> 0.51, 1e-10 -> 0.48  (63, 155, 389 steps);
//   dop853: 1e-6 -> 0.73, 1e-8 -> 0.70, 1e-10 -> 0.69  (14, 22, 35 steps).
// The bounds [0.05, 2] rtol leave room for another platform's rounding, yet a wrong coefficient
// or norm (which breaks the proportionality to rtol by orders of magnitude) fails them.
TEST(Adaptive, GlobalErrorOnTheOscillatorIsASmallMultipleOfRtol) {
  Oscillator system;
  VecX y0(2);
  y0 << 1.0, 0.0;
  auto exact = [&](double t) { return Oscillator::exact(t, 0.0, y0); };
  for (const std::string method : {"dopri5", "dop853"}) {
    for (const double rtol : {1e-6, 1e-8, 1e-10}) {
      auto integrator = make_integrator(method, tolerances(rtol, rtol * 1e-3));
      const double error = max_step_error(*integrator, system, y0, 10.0, exact, false);
      EXPECT_LT(error, 2.0 * rtol) << method << " rtol " << rtol;
      // And not absurdly small either: the control does not waste steps (a wrong norm that
      // over-estimated the error by 100x would show here).
      EXPECT_GT(error, 0.05 * rtol) << method << " rtol " << rtol;
      std::printf("[   info   ] %s rtol %.0e: max error %.3g = %.2f rtol, %ld steps\n",
                  method.c_str(), rtol, error, error / rtol, integrator->stats().accepted_steps);
    }
  }
}

TEST(Adaptive, Dop853TakesFarFewerStepsThanDopri5AtTightTolerance) {
  Oscillator system;
  VecX y0(2);
  y0 << 1.0, 0.0;
  auto dopri5 = make_integrator("dopri5", tolerances(1e-10, 1e-13));
  auto dop853 = make_integrator("dop853", tolerances(1e-10, 1e-13));
  run(*dopri5, system, 0.0, y0, 10.0, [](const Integrator&) {});
  run(*dop853, system, 0.0, y0, 10.0, [](const Integrator&) {});
  // Steps scale as rtol^(-1/(p+1)): at 1e-10 the 8th-order method needs several times fewer
  // (measured: 389 vs 35 accepted, 2341 vs 422 evaluations). Fewer evaluations too, despite 12 per
  // step against 6.
  EXPECT_LT(4 * dop853->stats().accepted_steps, dopri5->stats().accepted_steps);
  EXPECT_LT(dop853->stats().rhs_evaluations, dopri5->stats().rhs_evaluations);
  std::printf("[   info   ] rtol 1e-10: dopri5 %ld steps %ld evaluations, dop853 %ld steps %ld\n",
              dopri5->stats().accepted_steps, dopri5->stats().rhs_evaluations,
              dop853->stats().accepted_steps, dop853->stats().rhs_evaluations);
}

TEST(Adaptive, ContinuousExtensionIsAsAccurateAsTheSteps) {
  Oscillator system;
  VecX y0(2);
  y0 << 1.0, 0.0;
  for (const std::string method : {"dopri5", "dop853"}) {
    const double rtol = 1e-8;
    auto integrator = make_integrator(method, tolerances(rtol, rtol * 1e-3));
    double worst_dense = 0.0, worst_end = 0.0, worst_join = 0.0, worst_local_dense = 0.0;
    VecX y_out(2);
    run(*integrator, system, 0.0, y0, 10.0, [&](const Integrator& it) {
      worst_end =
          std::max(worst_end, (it.y() - Oscillator::exact(it.t(), 0.0, y0)).cwiseAbs().maxCoeff());
      for (const double s : {0.1, 0.3, 0.5, 0.7, 0.9}) {
        const double t = it.t_previous() + s * (it.t() - it.t_previous());
        it.dense_output(t, y_out);
        worst_dense =
            std::max(worst_dense, (y_out - Oscillator::exact(t, 0.0, y0)).cwiseAbs().maxCoeff());
        // Against the exact flow from the step's start: the interpolant's own error.
        const VecX local = Oscillator::exact(t, it.t_previous(), it.y_previous());
        worst_local_dense = std::max(worst_local_dense, (y_out - local).cwiseAbs().maxCoeff());
      }
      // The extension joins the step ends (continuity across steps for event location).
      it.dense_output(it.t_previous(), y_out);
      worst_join = std::max(worst_join, (y_out - it.y_previous()).cwiseAbs().maxCoeff());
      it.dense_output(it.t(), y_out);
      worst_join = std::max(worst_join, (y_out - it.y()).cwiseAbs().maxCoeff());
    });
    // Inside the steps the error is that of the step ends: measured worst_dense / worst_end
    // = 1.0 (dopri5) and 1.8 (dop853); 3 bounds both.
    EXPECT_LT(worst_dense, 3.0 * worst_end) << method;
    // The interpolant's own (local) error: dopri5's extension has order 4 like the embedded
    // solution whose error the control keeps below rtol (measured: 0.09 rtol); dop853's has
    // order 7, one below its step, and the long steps its control allows leave it near rtol
    // (measured: 1.24 rtol). 3 rtol bounds both.
    EXPECT_LT(worst_local_dense, 3.0 * rtol) << method;
    std::printf("[   info   ] %s dense/step error ratio %.3g, local dense error %.3g rtol\n",
                method.c_str(), worst_dense / worst_end, worst_local_dense / rtol);
    EXPECT_LT(worst_join, 4 * kEps) << method;  // exact at both ends up to round-off
  }
}

// The continuous extensions at their orders: with the step pinned to h (max_step = initial_step
// = h, and rtol 1e-3 far looser than the errors, so no step is rejected or shortened) the local
// interpolation error against the exact flow from each step's start is C h^(q+1), q = 4 for
// dopri5 and 7 for dop853: halving h divides it by 32 and 256. Measured ratios: dopri5 35, 33
// (h = 0.4, 0.2, 0.1); dop853 255, 255 (h = 0.8, 0.4, 0.2). The brackets allow the next term of
// the expansion a ~30 % share.
TEST(Adaptive, ContinuousExtensionsConvergeAtTheirOrders) {
  Oscillator system;
  VecX y0(2);
  y0 << 1.0, 0.0;
  struct Case {
    const char* method;
    double h_largest;
    double ratio_low, ratio_high;
  };
  for (const Case c : {Case{"dopri5", 0.4, 24.0, 44.0}, Case{"dop853", 0.8, 180.0, 330.0}}) {
    std::vector<double> errors;
    for (const double h : {c.h_largest, c.h_largest / 2, c.h_largest / 4}) {
      StepControl control;
      control.max_step = control.initial_step = h;
      auto integrator = make_integrator(c.method, control);
      double worst = 0.0;
      VecX y_out(2);
      run(*integrator, system, 0.0, y0, 9.6, [&](const Integrator& it) {
        EXPECT_NEAR(it.t() - it.t_previous(), h, 1e-12);
        for (const double s : {0.1, 0.3, 0.5, 0.7, 0.9}) {
          const double t = it.t_previous() + s * h;
          it.dense_output(t, y_out);
          const VecX local = Oscillator::exact(t, it.t_previous(), it.y_previous());
          worst = std::max(worst, (y_out - local).cwiseAbs().maxCoeff());
        }
      });
      EXPECT_EQ(integrator->stats().rejected_steps, 0);
      errors.push_back(worst);
    }
    for (std::size_t i = 1; i < errors.size(); ++i) {
      EXPECT_GT(errors[i - 1] / errors[i], c.ratio_low) << c.method << " " << errors[i];
      EXPECT_LT(errors[i - 1] / errors[i], c.ratio_high) << c.method << " " << errors[i];
    }
  }
}

TEST(Adaptive, BackwardIntegration) {
  Decay system;
  const VecX y0 = VecX::Constant(1, 1.0);
  for (const std::string method : {"dopri5", "dop853"}) {
    auto integrator = make_integrator(method, tolerances(1e-9, 1e-12));
    integrator->start(system, 0.0, y0, -3.0);
    while (integrator->t() > -3.0) ASSERT_EQ(integrator->step(-3.0), StepOutcome::Ok);
    EXPECT_EQ(integrator->t(), -3.0);
    // Relative error of a few rtol (y grows to e^3 = 20).
    EXPECT_NEAR(integrator->y()[0] / std::exp(3.0), 1.0, 5e-9) << method;
  }
}

// ---------------------------------------------------------------------------------------------
// Step-size control by hand (ode45's rules) and the evaluation counts.

// dopri5's stability polynomials, derived from its tableau (R(z) = 1 + sum_k z^k b^T A^(k-1) 1):
// the 5th-order solution R5 and the embedded 4th-order R4 (which uses k7 = f(y_new)). For
// y' = -y from y0 = 1, one step of h gives R5(-h) and the error estimate R5(-h) - R4(-h).
double dopri5_r5(double z) {
  return 1 + z + z * z / 2 + std::pow(z, 3) / 6 + std::pow(z, 4) / 24 + std::pow(z, 5) / 120 +
         std::pow(z, 6) / 600;
}
// R5 - R4 = -97/120000 z^5 + 39/120000 z^6 - z^7/24000, written out so that the error estimate
// is not the difference of two nearly equal numbers.
double dopri5_r5_minus_r4(double z) {
  return -97.0 / 120000 * std::pow(z, 5) + 39.0 / 120000 * std::pow(z, 6) - std::pow(z, 7) / 24000;
}

TEST(StepControl, Dopri5FollowsOde45OnDecayOverTheUnitInterval) {
  // ode45 defaults rtol 1e-3, atol 1e-6 on y' = -y, y0 = 1, t in [0, 1]:
  //   h_max = 0.1 |tspan| = 0.1; rh = |f0| / max(|y0|, atol/rtol) / (0.8 rtol^(1/5))
  //   = 1 / (0.8 * 0.2512) = 4.98; h_max rh = 0.498 < 1, so h0 = h_max = 0.1.
  // The error of a 0.1 step is |R5 - R4|(-0.1) ~ 8e-9 << rtol, so each step would grow five-fold
  // but h_max holds it at 0.1: ten steps, no rejection, 1 + 6 * 10 evaluations.
  Decay system;
  auto integrator = make_integrator("dopri5", StepControl{});
  integrator->start(system, 0.0, VecX::Constant(1, 1.0), 1.0);
  EXPECT_EQ(integrator->step_size(), 0.1);
  int steps = 0;
  while (integrator->t() < 1.0) {
    ASSERT_EQ(integrator->step(1.0), StepOutcome::Ok);
    ++steps;
    // 0.1 up to the rounding of t (and the last step lands on 1 exactly).
    EXPECT_NEAR(integrator->t() - integrator->t_previous(), 0.1, 1e-15);
  }
  EXPECT_EQ(steps, 10);
  EXPECT_EQ(integrator->t(), 1.0);
  EXPECT_EQ(integrator->stats().accepted_steps, 10);
  EXPECT_EQ(integrator->stats().rejected_steps, 0);
  EXPECT_EQ(integrator->stats().rhs_evaluations, 61);
  // Ten steps of R5(-0.1) = e^-0.1 (1 + (1/600 - 1/720) 0.1^6 + O(0.1^7)): the result is e^-1
  // (1 + 10 * 2.8e-10), i.e. 1.02e-9 above e^-1.
  EXPECT_NEAR(integrator->y()[0], std::pow(dopri5_r5(-0.1), 10), 1e-15);
  EXPECT_NEAR(integrator->y()[0] - std::exp(-1.0), 10 * 1e-6 / 3600 * std::exp(-1.0), 0.2e-9);
}

TEST(StepControl, Dopri5FirstStepsOnALongSpanFollowOde45) {
  // Over [0, 10] h_max = 1 and h_max rh = 4.98 > 1, so h0 = 1 / rh = 0.8 rtol^(1/5).
  Decay system;
  const double rtol = 1e-3;
  auto integrator = make_integrator("dopri5", StepControl{});
  integrator->start(system, 0.0, VecX::Constant(1, 1.0), 10.0);
  const double h0 = 0.8 * std::pow(rtol, 0.2);
  EXPECT_NEAR(integrator->step_size(), h0, 4 * kEps);

  // Step 1: y1 = R5(-h0); err = |R5 - R4|(-h0) / max(|y0|, |y1|, atol/rtol) (= / 1) is below
  // rtol, so the step is accepted and the next is h0 / max(0.2, 1.25 (err/rtol)^(1/5)).
  ASSERT_EQ(integrator->step(10.0), StepOutcome::Ok);
  EXPECT_NEAR(integrator->t(), h0, 4 * kEps);
  EXPECT_NEAR(integrator->y()[0], dopri5_r5(-h0), 4 * kEps);
  const double err1 = std::abs(dopri5_r5_minus_r4(-h0));
  const double h1 = h0 / std::max(0.2, 1.25 * std::pow(err1 / rtol, 0.2));
  // The method's estimate h sum e_i k_i sums terms ~5e-2 that cancel to ~1e-6: relative
  // round-off ~1e-11 in err, which the 1/5 power shrinks to ~2e-12 in h; 1e-11 bounds it.
  EXPECT_NEAR(integrator->step_size(), h1, 1e-11);

  // Step 2 from y1 (linear problem: the same polynomials scale by y1), at most h_max = 1.
  ASSERT_EQ(integrator->step(10.0), StepOutcome::Ok);
  const double h1_taken = std::min(h1, 1.0);
  EXPECT_NEAR(integrator->t(), h0 + h1_taken, 1e-11);
  const double y1 = dopri5_r5(-h0);
  const double y2 = y1 * dopri5_r5(-h1_taken);
  EXPECT_NEAR(integrator->y()[0], y2, 1e-11);  // |y'| < 1 times the error in h1
  const double err2 = std::abs(y1 * dopri5_r5_minus_r4(-h1_taken)) / std::max({y1, y2, 1e-3});
  ASSERT_LE(err2, rtol);  // the hand computation says step 2 is accepted too
  const double h2 = std::min(1.0, h1_taken / std::max(0.2, 1.25 * std::pow(err2 / rtol, 0.2)));
  EXPECT_NEAR(std::min(1.0, integrator->step_size()), h2, 1e-9);
  EXPECT_EQ(integrator->stats().rejected_steps, 0);
  EXPECT_EQ(integrator->stats().rhs_evaluations, 1 + 6 * 2);
}

TEST(StepControl, EvaluationCountsMatchEachDesign) {
  Oscillator oscillator;
  AxisymmetricBody body;
  VecX y_osc(2);
  y_osc << 1.0, 0.0;
  const VecX y_body = AxisymmetricBody::initial_state();

  // dopri5, no projection: 1 at start + 6 per attempted step (FSAL).
  {
    Counting system(oscillator);
    auto integrator = make_integrator("dopri5", tolerances(1e-7, 1e-10));
    run(*integrator, system, 0.0, y_osc, 10.0, [](const Integrator&) {});
    const IntegratorStats& s = integrator->stats();
    EXPECT_EQ(s.rhs_evaluations, system.evaluations);
    EXPECT_EQ(s.rhs_evaluations, 1 + 6 * (s.accepted_steps + s.rejected_steps));
    EXPECT_EQ(system.projections_that_moved, 0);
  }
  // dopri5 on a quaternion state: projections that only renormalise the quaternion rescale
  // FSAL's k_7 instead of evaluating f again, so still 1 + 6 per attempted step.
  {
    Counting system(body);
    auto integrator = make_integrator("dopri5", tolerances(1e-7, 1e-10));
    run(*integrator, system, 0.0, y_body, 10.0, [](const Integrator&) {});
    const IntegratorStats& s = integrator->stats();
    EXPECT_EQ(s.rhs_evaluations, system.evaluations);
    EXPECT_GT(system.projections_that_moved, 0);
    EXPECT_EQ(s.rhs_evaluations, 1 + 6 * (s.accepted_steps + s.rejected_steps));
  }
  // dop853: 2 at start (Hairer's starting step), 11 per attempt, 1 per accepted step, and 3
  // more in each step whose continuous extension is used (once, however many times).
  {
    Counting system(body);
    auto integrator = make_integrator("dop853", tolerances(1e-9, 1e-12));
    long dense_steps = 0;
    VecX y_out(7);
    run(*integrator, system, 0.0, y_body, 10.0, [&](const Integrator& it) {
      if (it.stats().accepted_steps % 3 == 0) {
        it.dense_output(0.5 * (it.t_previous() + it.t()), y_out);
        it.dense_output(0.25 * it.t_previous() + 0.75 * it.t(), y_out);
        ++dense_steps;
      }
    });
    const IntegratorStats& s = integrator->stats();
    EXPECT_EQ(s.rhs_evaluations, system.evaluations);
    EXPECT_EQ(s.rhs_evaluations,
              2 + 11 * (s.accepted_steps + s.rejected_steps) + s.accepted_steps + 3 * dense_steps);
  }
  // rk4 and rkmk4: 1 at start + 4 per step.
  for (const std::string method : {"rk4", "rkmk4"}) {
    Counting system(body);
    auto integrator = make_integrator(method, fixed(0.01));
    run(*integrator, system, 0.0, y_body, 1.0, [](const Integrator&) {});
    const IntegratorStats& s = integrator->stats();
    EXPECT_EQ(s.accepted_steps, 100) << method;  // 1.0 / 0.01 with no sliver step at the end
    EXPECT_EQ(s.rejected_steps, 0) << method;
    EXPECT_EQ(s.rhs_evaluations, system.evaluations) << method;
    EXPECT_EQ(s.rhs_evaluations, 1 + 4 * s.accepted_steps) << method;
  }
}

// ---------------------------------------------------------------------------------------------
// Stops, restarts, failures.

TEST(Stops, EveryMethodLandsExactlyOnTheStopTime) {
  Oscillator system;
  VecX y0(2);
  y0 << 1.0, 0.0;
  for (const std::string method : {"dopri5", "dop853", "rk4", "rkmk4"}) {
    StepControl control = tolerances(1e-8, 1e-11);
    control.fixed_step = 0.03;
    auto integrator = make_integrator(method, control);
    integrator->start(system, 0.0, y0, 10.0);
    // Stops off the grid of rk4 and at no particular place for the adaptive methods.
    for (const double t_stop : {0.37, 0.371, 2.0 / 3.0, 5.0, 10.0}) {
      while (integrator->t() < t_stop) {
        ASSERT_EQ(integrator->step(t_stop), StepOutcome::Ok);
        ASSERT_LE(integrator->t(), t_stop) << method;
      }
      EXPECT_EQ(integrator->t(), t_stop) << method;
    }
    // Landing does not cost accuracy (tolerance: 10 rtol, or RK4 at h = 0.03 over 10 s).
    EXPECT_LT((integrator->y() - Oscillator::exact(10.0, 0.0, y0)).cwiseAbs().maxCoeff(), 1e-6)
        << method;
    // A stop that is not ahead is a programming error.
    EXPECT_THROW(integrator->step(10.0), std::invalid_argument) << method;
  }
}

TEST(Stops, RestartKeepsStatisticsAndContinuesFromTheNewState) {
  Oscillator system;
  VecX y0(2);
  y0 << 1.0, 0.0;
  for (const std::string method : {"dopri5", "dop853", "rk4", "rkmk4"}) {
    StepControl control = tolerances(1e-9, 1e-12);
    control.fixed_step = 0.01;
    auto integrator = make_integrator(method, control);
    integrator->start(system, 0.0, y0, 6.0);
    while (integrator->t() < 2.0) ASSERT_EQ(integrator->step(2.0), StepOutcome::Ok);
    const IntegratorStats before = integrator->stats();
    const double h_before = integrator->step_size();

    // A jump in the state at t = 2 (an impact reversing and doubling the velocity).
    VecX y_jump = integrator->y();
    y_jump[1] = -2.0 * y_jump[1];
    integrator->restart(2.0, y_jump);
    EXPECT_EQ(integrator->stats().accepted_steps, before.accepted_steps) << method;
    EXPECT_EQ(integrator->stats().rhs_evaluations, before.rhs_evaluations + 1) << method;
    EXPECT_EQ(integrator->step_size(), h_before) << method;  // kept as the first guess
    EXPECT_EQ(integrator->t(), 2.0);
    EXPECT_EQ(integrator->y(), y_jump);
    VecX y_out(2);
    integrator->dense_output(2.0, y_out);  // no step yet: the extension is the state
    EXPECT_EQ(y_out, y_jump);

    while (integrator->t() < 6.0) ASSERT_EQ(integrator->step(6.0), StepOutcome::Ok);
    EXPECT_GT(integrator->stats().accepted_steps, before.accepted_steps);
    // From the new state: error of ~rtol per unit amplitude (amplitude ~2 here), or RK4's
    // h^4-level error at h = 0.01 (1e-9).
    EXPECT_LT((integrator->y() - Oscillator::exact(6.0, 2.0, y_jump)).cwiseAbs().maxCoeff(), 2e-8)
        << method;
  }
}

TEST(Failures, BlowUpEndsInStepSizeUnderflowNearTheSingularity) {
  BlowUp system;
  for (const std::string method : {"dopri5", "dop853"}) {
    auto integrator = make_integrator(method, StepControl{});
    integrator->start(system, 0.0, VecX::Constant(1, 1.0), 2.0);
    StepOutcome outcome = StepOutcome::Ok;
    for (int i = 0; i < 100000 && outcome == StepOutcome::Ok; ++i) outcome = integrator->step(2.0);
    EXPECT_EQ(outcome, StepOutcome::StepSizeUnderflow) << method;
    // The numerical solution is close to 1 / (t* - t) with t* off 1 by the global error at
    // rtol 1e-3 (measured: 1 - 3e-5 for dopri5, 1 + 4e-6 for dop853); the step shrinks with
    // t* - t until it falls below 16 eps(1) = 3.6e-15, where y ~ 1e14.
    EXPECT_NEAR(integrator->t(), 1.0, 1e-3) << method;
    EXPECT_GT(integrator->y()[0], 1e12) << method;
    EXPECT_TRUE(std::isfinite(integrator->y()[0])) << method;
  }
}

TEST(Failures, NanFromTheSystemIsReportedAsNonFiniteState) {
  NanAfter system;
  for (const std::string method : {"dopri5", "dop853", "rk4", "rkmk4"}) {
    StepControl control;
    control.fixed_step = 0.05;
    auto integrator = make_integrator(method, control);
    integrator->start(system, 0.0, VecX::Constant(1, 1.0), 1.0);
    StepOutcome outcome = StepOutcome::Ok;
    for (int i = 0; i < 1000 && outcome == StepOutcome::Ok; ++i) outcome = integrator->step(1.0);
    EXPECT_EQ(outcome, StepOutcome::NonFiniteState) << method;
    // The state stays at the last good step, before f turned NaN.
    EXPECT_LE(integrator->t(), NanAfter::kTBad) << method;
    EXPECT_TRUE(integrator->y().allFinite()) << method;
  }
}

TEST(Failures, AStepWhoseStagesGoNonFiniteIsRetriedShorter) {
  // The run goes on past the steps whose stages left the domain, and stays accurate.
  for (const std::string method : {"dopri5", "dop853"}) {
    NanBelowZero system;
    auto integrator = make_integrator(method, StepControl{});
    integrator->start(system, 0.0, VecX::Constant(1, 1.0), 1.0);
    StepOutcome outcome = StepOutcome::Ok;
    for (int i = 0; i < 100000 && integrator->t() < 1.0 && outcome == StepOutcome::Ok; ++i) {
      outcome = integrator->step(1.0);
    }
    EXPECT_EQ(outcome, StepOutcome::Ok) << method;
    EXPECT_EQ(integrator->t(), 1.0) << method;
    EXPECT_GT(system.nan_evaluations, 0) << method;
    // Default tolerances (rtol 1e-3, atol 1e-6): the decayed solution is within atol of 0.
    EXPECT_NEAR(integrator->y()[0], std::exp(-50.0), 1e-5) << method;
  }
}

// ---------------------------------------------------------------------------------------------
// The factory.

TEST(Factory, MakesEachMethodByName) {
  StepControl control;
  control.fixed_step = 0.1;
  struct Expected {
    const char* name;
    int order;
    bool adaptive;
  };
  for (const Expected e :
       {Expected{"dopri5", 5, true}, Expected{"dop853", 8, true}, Expected{"rk4", 4, false},
        Expected{"rkmk4", 4, false}, Expected{"radau5", 5, true}}) {
    auto integrator = make_integrator(e.name, control);
    EXPECT_EQ(integrator->name(), e.name);
    EXPECT_EQ(integrator->order(), e.order);
    EXPECT_EQ(integrator->adaptive(), e.adaptive);
  }
}

// The message of the std::invalid_argument that make_integrator throws, or "" if none.
std::string factory_error(const std::string& name, const StepControl& control) {
  try {
    make_integrator(name, control);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

TEST(Factory, RejectsUnknownNamesAndBadControlsWithAHelpfulMessage) {
  StepControl control;
  EXPECT_EQ(
      factory_error("euler", control),
      "unknown integrator 'euler'; valid names: dopri5, dop853, rk4, rkmk4, radau5, trbdf2, auto");
  for (const std::string method : {"rk4", "rkmk4"}) {
    EXPECT_NE(factory_error(method, control).find("fixed_step = 0"), std::string::npos) << method;
    control.fixed_step = -0.1;
    EXPECT_NE(factory_error(method, control).find("fixed_step = -0.1"), std::string::npos);
    control.fixed_step = 0.0;
  }
  control.rtol = 0.0;
  EXPECT_NE(factory_error("dopri5", control).find("dopri5: rtol = 0"), std::string::npos);
  control.rtol = 1e-6;
  control.atol = -1.0;
  EXPECT_NE(factory_error("dop853", control).find("dop853: atol = -1"), std::string::npos);
  EXPECT_NE(factory_error("radau5", control).find("radau5: atol = -1"), std::string::npos);
}

TEST(Factory, StartRejectsAStateOfTheWrongSize) {
  Oscillator system;
  auto integrator = make_integrator("dopri5", StepControl{});
  try {
    integrator->start(system, 0.0, VecX::Zero(3), 1.0);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& error) {
    EXPECT_STREQ(error.what(),
                 "dopri5: y0 has 3 components but the system has dimension 2; pass a state of "
                 "the system's dimension");
  }
}

}  // namespace
}  // namespace tumble
