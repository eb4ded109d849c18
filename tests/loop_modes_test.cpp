// `tumble modes` on a closed loop: the Grashof four-bar (examples/four_bar.yaml's links) hanging
// at its stable equilibrium, against the closed form of its one-freedom linearisation.
//
// With the crank angle q as the coordinate, the coupler's and the rocker's angles follow from the
// loop r2 e^{iq} + r3 e^{i t3} = g + r4 e^{i t4}; differentiating it gives their rates per unit
// of q's, k3 = t3' and k4 = t4', and differentiating again k3' and k4'. The energy is then
//   T = M(q) q'^2 / 2,  M = I_crank,O2 + m3 |v_G3 / q'|^2 + I_G3 k3^2 + I_rocker,O4 k4^2,
//   V = g (m2 y_G2 + m3 y_G3 + m4 y_G4),
// and about an equilibrium q*, V'(q*) = 0, the small oscillation has omega^2 = V''(q*) / M(q*)
// (the M' q'^2 term is of second order). Everything here is closed form but q*, the root of V'
// (bisection to round-off).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <string>

#include "modes_checks.hpp"
#include "scenario_run.hpp"
#include "test_constants.hpp"
#include "test_files.hpp"
#include "tumble/modes/not_steady.hpp"

namespace tumble {
namespace {

using test::kPi;

struct FourBar {
  double r2 = 0.2, r3 = 0.6, r4 = 0.5, ground = 0.6;  // m: crank, coupler, rocker, O2-O4
  double m2 = 1.0, m3 = 2.0, m4 = 1.5, g = 9.81;      // kg, m/s^2: uniform rods

  // At crank angle q: the coupler's and the rocker's angles (B to the left of A -> O4, where
  // the example assembles it), their rates per unit of q's, and those rates' derivatives.
  struct Pose {
    std::complex<double> A, B;
    double t3 = 0, t4 = 0, k3 = 0, k4 = 0, k3d = 0, k4d = 0;
  };
  Pose pose(double q) const {
    using C = std::complex<double>;
    const C i(0.0, 1.0);
    Pose p;
    p.A = r2 * std::exp(i * q);
    const C O4(ground, 0.0);
    const double d = std::abs(O4 - p.A);
    const C along = (O4 - p.A) / d;
    const double a = (r3 * r3 - r4 * r4 + d * d) / (2.0 * d);
    p.B = p.A + a * along + std::sqrt(r3 * r3 - a * a) * i * along;
    p.t3 = std::arg(p.B - p.A);
    p.t4 = std::arg(p.B - O4);
    const double s34 = std::sin(p.t3 - p.t4);
    p.k3 = r2 * std::sin(p.t4 - q) / (r3 * s34);
    p.k4 = r2 * std::sin(p.t3 - q) / (r4 * s34);
    // d/dq of r2 i e^{iq} + r3 k3 i e^{i t3} - r4 k4 i e^{i t4} = 0:
    //   i (r3 k3' e^{i t3} - r4 k4' e^{i t4}) = -c,
    //   c = -r2 e^{iq} - r3 k3^2 e^{i t3} + r4 k4^2 e^{i t4}.
    const C c = -r2 * std::exp(i * q) - r3 * p.k3 * p.k3 * std::exp(i * p.t3) +
                r4 * p.k4 * p.k4 * std::exp(i * p.t4);
    p.k3d = std::real(c * std::exp(-i * p.t4)) / (r3 * s34);
    p.k4d = std::real(c * std::exp(-i * p.t3)) / (r4 * s34);
    return p;
  }
  // dV/dq and d2V/dq2.
  double dV(double q) const {
    const Pose p = pose(q);
    return g * ((m2 / 2 + m3) * r2 * std::cos(q) + m3 * r3 / 2 * std::cos(p.t3) * p.k3 +
                m4 * r4 / 2 * std::cos(p.t4) * p.k4);
  }
  double d2V(double q) const {
    const Pose p = pose(q);
    return g * (-(m2 / 2 + m3) * r2 * std::sin(q) +
                m3 * r3 / 2 * (std::cos(p.t3) * p.k3d - std::sin(p.t3) * p.k3 * p.k3) +
                m4 * r4 / 2 * (std::cos(p.t4) * p.k4d - std::sin(p.t4) * p.k4 * p.k4));
  }
  double mass(double q) const {
    const Pose p = pose(q);
    const double v_G3_squared =
        r2 * r2 + r3 * r3 * p.k3 * p.k3 / 4 + r2 * r3 * p.k3 * std::cos(q - p.t3);
    return m2 * r2 * r2 / 3 + m3 * v_G3_squared + m3 * r3 * r3 / 12 * p.k3 * p.k3 +
           m4 * r4 * r4 / 3 * p.k4 * p.k4;
  }
  // An equilibrium, a root of V' by bisection from a scan: the stable one (V' rising through
  // zero, V'' > 0) or the unstable one (falling).
  double equilibrium(bool stable) const {
    const int n = 720;
    const double sign = stable ? 1.0 : -1.0;
    for (int j = 0; j < n; ++j) {
      double lo = 2 * kPi * j / n, hi = 2 * kPi * (j + 1) / n;
      if (!(sign * dV(lo) < 0 && sign * dV(hi) > 0)) continue;
      for (int k = 0; k < 200 && hi - lo > 1e-16; ++k) {
        const double mid = (lo + hi) / 2;
        (sign * dV(mid) < 0 ? lo : hi) = mid;
      }
      return (lo + hi) / 2;
    }
    ADD_FAILURE() << "no " << (stable ? "stable" : "unstable") << " equilibrium";
    return 0.0;
  }
};

// The planar statement (examples/planar/four_bar.yaml) posed at crank angle q, from rest.
std::string four_bar_at(const FourBar& bar, double q) {
  const FourBar::Pose p = bar.pose(q);
  return fmt::format(
      R"yaml(tumble: 1
planar: true
parameters: {{xA: {:.17g}, yA: {:.17g}, xB: {:.17g}, yB: {:.17g}}}
bodies:
  crank: {{shape: rod, length: {}, mass: {}, position: [xA/2, yA/2], angle: {:.17g}}}
  coupler: {{shape: rod, length: {}, mass: {}, position: ["(xA + xB)/2", "(yA + yB)/2"],
            angle: {:.17g}}}
  rocker: {{shape: rod, length: {}, mass: {}, position: ["({} + xB)/2", yB/2], angle: {:.17g}}}
joints:
  O2: {{type: hinge, body: crank, at: [0, 0]}}
  A: {{type: hinge, bodies: [crank, coupler], at: [xA, yA]}}
  O4: {{type: hinge, body: rocker, at: [{}, 0]}}
  B: {{type: hinge, bodies: [coupler, rocker], at: [xB, yB]}}
simulate: {{duration: 1}}
)yaml",
      p.A.real(), p.A.imag(), p.B.real(), p.B.imag(), bar.r2, bar.m2, q, bar.r3, bar.m3, p.t3,
      bar.r4, bar.m4, bar.ground, p.t4, bar.ground);
}

TEST(LoopModes, AFourBarSwingsAboutItsStableEquilibriumAtItsOneFreedomsFrequency) {
  const FourBar bar;
  const double q = bar.equilibrium(true);
  ASSERT_GT(bar.d2V(q), 0.0);
  const double omega = std::sqrt(bar.d2V(q) / bar.mass(q));
  const ScenarioModes modes =
      modes_of_scenario(test::load_inline_scenario(four_bar_at(bar, q), "four_bar_hanging"));
  // One freedom: one oscillation, on the loop's tangent space (the tree has three angles).
  EXPECT_TRUE(modes.linearisation.equilibrium());
  test::expect_oscillating_at(modes.analysis, {omega}, test::kModesRelative);
  EXPECT_EQ(modes.analysis.verdict, ModalAnalysis::Verdict::Stable);
}

TEST(LoopModes, AFourBarBalancedAtItsTopFallsAtItsOneFreedomsRate) {
  // The other root of V' (V'' < 0): one real pair +-sqrt(-V''/M), the linkage falls.
  const FourBar bar;
  const double q = bar.equilibrium(false);
  ASSERT_LT(bar.d2V(q), 0.0);
  const double rate = std::sqrt(-bar.d2V(q) / bar.mass(q));
  const ScenarioModes modes =
      modes_of_scenario(test::load_inline_scenario(four_bar_at(bar, q), "four_bar_balanced"));
  ASSERT_EQ(modes.analysis.modes.size(), 2U);
  test::expect_undamped_twins(modes.analysis);
  for (const Mode& mode : modes.analysis.modes) {
    EXPECT_NEAR(std::abs(mode.eigenvalue.real()), rate, test::kModesRelative * rate);
    EXPECT_EQ(mode.eigenvalue.imag(), 0.0);
  }
  EXPECT_EQ(modes.analysis.verdict, ModalAnalysis::Verdict::Unstable);
}

TEST(LoopModes, AMechanismItsDriveAndItsLoopHoldHasNoModes) {
  // The Hooke shafts: the input driven at a speed, the output's turn fixed by the loop. Nothing
  // is left to move: no linearisation, and `tumble modes` says so (exit 6).
  try {
    modes_of_scenario(load_scenario(test::example("hooke_shafts.yaml"), {}));
    ADD_FAILURE() << "modes of a mechanism with no freedom";
  } catch (const NotSteady& error) {
    EXPECT_NE(std::string(error.what()).find("nothing can move"), std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace tumble
