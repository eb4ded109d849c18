// tumble modes against closed forms (equations.md, section 6.8): the eigenvalues of the
// linearisation to 1e-9 relative, where the closed form is exact for the model (the chapter's
// small-angle equations are the linearisation itself). The Jacobian is exact to round-off
// (automatic differentiation), so the eigenvalues are good to ~1e-14; 1e-9 is the issue's bar.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "modes_checks.hpp"
#include "run_tumble.hpp"
#include "scenario_run.hpp"
#include "test_files.hpp"
#include "tumble/math/rotation.hpp"
#include "tumble/modes/mode_shape_rows.hpp"
#include "tumble/modes/scenario_modes.hpp"
#include "tumble/multibody/articulated_formulation.hpp"
#include "tumble/multibody/joints/joint_kind.hpp"

namespace tumble {
namespace {

using test::example;
using test::expect_relative;
using test::modes_of;

// examples/modes/inverted_mast.yaml: a cylinder hinged at its base O, held up by a torsional
// spring of k_ratio times the critical stiffness M g length/2.
struct Mast {
  static constexpr double M = 3, length = 2, r = 0.01, g = 9.81;
  static constexpr double I_O = M * (3 * r * r + length * length) / 12 + M * length * length / 4;
  static constexpr double critical = M * g * length / 2;  // N m/rad
};

// The mode of the given kind with the largest |lambda| (or the first), failing if none.
const Mode& first_of(const ModalAnalysis& analysis, Mode::Kind kind) {
  for (const Mode& mode : analysis.modes) {
    if (mode.kind == kind) return mode;
  }
  ADD_FAILURE() << "no mode of kind " << kind_name(kind);
  return analysis.modes.front();
}

TEST(Modes, InvertedMastStandsWithTheChaptersFrequency) {
  for (const double k_ratio : {2.0, 1.5, 1.01}) {
    const double k = k_ratio * Mast::critical;
    const ScenarioModes modes =
        modes_of(example("modes/inverted_mast.yaml"), {{"k_ratio", std::to_string(k_ratio)}});
    ASSERT_EQ(modes.analysis.modes.size(), 1U);
    const Mode& mode = modes.analysis.modes[0];
    EXPECT_EQ(mode.kind, Mode::Kind::Oscillating);
    expect_relative(mode.natural_frequency, std::sqrt((k - Mast::critical) / Mast::I_O));
    EXPECT_EQ(mode.growth_rate, 0.0);
    EXPECT_EQ(modes.analysis.verdict, ModalAnalysis::Verdict::Stable);
    // The shape: the angle, and the rate a quarter period ahead.
    EXPECT_NEAR(std::abs(mode.shape(1)), mode.natural_frequency, 1e-12 * mode.natural_frequency);
  }
}

TEST(Modes, InvertedMastFallsBelowTheCriticalStiffness) {
  for (const double k_ratio : {0.9, 0.5, 0.0}) {
    const double k = k_ratio * Mast::critical;
    const ScenarioModes modes =
        modes_of(example("modes/inverted_mast.yaml"), {{"k_ratio", std::to_string(k_ratio)}});
    EXPECT_EQ(modes.analysis.verdict, ModalAnalysis::Verdict::Unstable);
    EXPECT_EQ(modes.analysis.deciding_mode, 0U);
    expect_relative(modes.analysis.modes[0].growth_rate,
                    std::sqrt((Mast::critical - k) / Mast::I_O));
    EXPECT_NE(modes.analysis.verdict_text.find("mode 1 grows"), std::string::npos);
  }
  // Exactly critical: nothing restores the angle.
  const ScenarioModes critical = modes_of(example("modes/inverted_mast.yaml"), {{"k_ratio", "1"}});
  EXPECT_EQ(critical.analysis.verdict, ModalAnalysis::Verdict::Marginal);
  EXPECT_NE(critical.analysis.verdict_text.find("base.angle"), std::string::npos);
}

// A free mast held to ground by a torsional spring alone (no hinge; no gravity): its moment is
// -k theta_n for the turn theta_n from rest, so it turns about each principal axis at
// sqrt(k / I_i). Linearised right after the hinged mast (two coordinates), as a fuzzing run did:
// ground's dual-number state was then a shared constant that Eigen's AutoDiff had resized to
// the hinged mast's two derivatives, and this twelve-coordinate linearisation read past them.
TEST(Modes, AFreeMastOnATorsionalSpringToGroundTurnsAtSqrtKOverI) {
  (void)modes_of(example("modes/inverted_mast.yaml"));
  const double M = 3, r = 0.01, length = 2, k = 50;
  const ScenarioModes modes = modes_of_scenario(test::load_inline_scenario(R"(tumble: 1
gravity: [0, 0, 0]
bodies:
  mast: {shape: cylinder, radius: 0.01, length: 2, mass: 3, position: [0, 0, 1]}
forces:
  - {type: torsional_spring, name: spring, bodies: [ground, mast], stiffness: 50}
simulate: {duration: 1, integrator: dopri5, rtol: 1e-8, atol: 1e-10}
)",
                                                                           "free_spring"));
  std::vector<double> found;
  for (const Mode& mode : modes.analysis.modes) {
    if (mode.kind == Mode::Kind::Oscillating) found.push_back(mode.natural_frequency);
  }
  const double I_side = M * (3 * r * r + length * length) / 12, I_axis = M * r * r / 2;
  std::vector<double> expected = {std::sqrt(k / I_side), std::sqrt(k / I_side),
                                  std::sqrt(k / I_axis)};
  std::sort(found.begin(), found.end());
  std::sort(expected.begin(), expected.end());
  ASSERT_EQ(found.size(), expected.size());
  for (std::size_t i = 0; i < found.size(); ++i) expect_relative(found[i], expected[i]);
}

// The animation page's rows of the mast's mode (tumble modes --animate): the angle swings to
// 0.2 rad and the rate moves with it, as the undamped mode theta = 0.2 cos(omega t + phi) has it:
// theta^2 + (theta_dot / omega)^2 = 0.2^2 at every row (the eigenvalue is i omega to ~1e-12; the
// angle is read back through log_so3, ~1e-16), and the KE is (1/2) I_O theta_dot^2. The rows'
// speeds were the initial state's (zero) before: omega and KE plotted flat.
TEST(ModesPage, TheMastsRowsSwingItsRateWithItsAngle) {
  const ScenarioModes modes = modes_of(example("modes/inverted_mast.yaml"));
  const double omega = std::sqrt(Mast::critical / Mast::I_O);  // k = 2 M g length / 2
  std::vector<ShownMode> shown;
  const RecordedTrajectory rows = mode_shape_rows(modes, Mast::length, shown);
  ASSERT_EQ(shown.size(), 1U);
  ASSERT_GT(rows.rows(), 100U);
  std::vector<double> angle(rows.rows()), rate(rows.rows());
  for (std::size_t r = 0; r < rows.rows(); ++r) {
    const BodyState& mast = rows.state(r, 0);
    angle[r] = log_so3(mast.R_WB).y();  // R0 = I: the hinge turns it about world y
    rate[r] = mast.omega_W.y();
    EXPECT_NEAR(angle[r] * angle[r] + rate[r] * rate[r] / (omega * omega), 0.04, 1e-12)
        << "row " << r;
    EXPECT_NEAR(rows.quantities(r).kinetic_energy, 0.5 * Mast::I_O * rate[r] * rate[r],
                1e-12 * Mast::I_O * 0.04 * omega * omega);
  }
  // And it is the angle's rate, in the rows' time: the rate has the sign of the angle's change.
  for (std::size_t r = 1; r + 1 < rows.rows(); ++r) {
    if (std::abs(rate[r]) > 0.05 * omega) {
      EXPECT_GT(rate[r] * (angle[r + 1] - angle[r - 1]), 0.0) << "row " << r;
    }
  }
}

// The page's rows of a free prism's modes (set-aside turns shown by speed / lambda, up to 0.2 rad):
// every orientation a rotation to round-off, the turns exact, not the linearisation's first-order
// R0 (1 + [r]x), which would shear the prism by |r|^2 (4e-2 at 0.2 rad).
TEST(ModesPage, APrismsRowsTurnItByRotations) {
  const ScenarioModes modes = modes_of(example("modes/prism_axes.yaml"));
  std::vector<ShownMode> shown;
  const RecordedTrajectory rows = mode_shape_rows(modes, 1.0, shown);
  ASSERT_FALSE(shown.empty());
  double largest_turn = 0.0;
  for (std::size_t r = 0; r < rows.rows(); ++r) {
    for (std::size_t b = 0; b < rows.body_count(); ++b) {
      const Mat3& R = rows.state(r, b).R_WB;
      EXPECT_LE(orthonormality_error(R), 1e-14) << "row " << r;
      largest_turn =
          std::max(largest_turn, log_so3(Mat3(rows.state(0, b).R_WB.transpose() * R)).norm());
    }
  }
  EXPECT_GT(largest_turn, 0.1);  // the rows do turn it
}

TEST(Modes, DampedMastDecaysWithItsDampingRatio) {
  const double c = 1.5, k = 2 * Mast::critical;  // the example's k_ratio 2
  const ScenarioModes modes =
      modes_of(example("modes/inverted_mast.yaml"), {{"damping", std::to_string(c)}});
  const Mode& mode = modes.analysis.modes.at(0);
  EXPECT_EQ(mode.kind, Mode::Kind::DampedOscillation);
  // I_O theta'' + c theta' + (k - M g L/2) theta = 0.
  const double omega_n = std::sqrt((k - Mast::critical) / Mast::I_O);
  expect_relative(mode.natural_frequency, omega_n);
  expect_relative(mode.damping_ratio, c / (2 * Mast::I_O * omega_n));
  EXPECT_EQ(modes.analysis.verdict, ModalAnalysis::Verdict::Stable);
}

TEST(Modes, BatSwingsWithTheCompoundPendulumsPeriod) {
  const double M = 0.9, length = 0.84, r = 0.03, L = length / 2, g = 9.81;
  const double I_O = M * (3 * r * r + length * length) / 12 + M * L * L;
  const ScenarioModes modes = modes_of(example("modes/bat.yaml"));
  ASSERT_EQ(modes.analysis.modes.size(), 1U);
  expect_relative(modes.analysis.modes[0].period(),
                  2 * std::numbers::pi * std::sqrt(I_O / (M * g * L)));
  // The compound pendulum example hung straight down is the same bat.
  const ScenarioModes hung = modes_of(example("compound_pendulum.yaml"), {{"theta0", "0"}});
  expect_relative(hung.analysis.modes.at(0).period(), modes.analysis.modes[0].period());
}

TEST(Modes, DoublePendulumHasBothNormalModes) {
  const double l = 0.5, m = 0.5, r = 0.005, g = 9.81, c = l / 2;
  const double I = m * (3 * r * r + l * l) / 12 + m * c * c;  // each rod about its own hinge
  // det(K - x M) = 0 with M = [I + m l^2, m l c; m l c, I], K = g [m c + m l, 0; 0, m c].
  const double M11 = I + m * l * l, M12 = m * l * c, M22 = I;
  const double K11 = g * (m * c + m * l), K22 = g * m * c;
  const double a = M11 * M22 - M12 * M12, b = K11 * M22 + K22 * M11, k = K11 * K22;
  const double slow = std::sqrt((b - std::sqrt(b * b - 4 * a * k)) / (2 * a));
  const double fast = std::sqrt((b + std::sqrt(b * b - 4 * a * k)) / (2 * a));
  const ScenarioModes modes = modes_of(example("modes/double_pendulum.yaml"));
  ASSERT_EQ(modes.analysis.modes.size(), 2U);
  expect_relative(modes.analysis.modes[0].natural_frequency, slow);
  expect_relative(modes.analysis.modes[1].natural_frequency, fast);
  // Shapes: in the slow mode the rods swing together, in the fast one against each other, with
  // theta2 / theta1 = (K11 - x M11) / (x M12) for the rods' angles from the vertical; the
  // elbow's angle is the lower rod's relative to the upper, theta2 - theta1.
  for (const auto& [index, omega] : {std::pair{0, slow}, std::pair{1, fast}}) {
    const Mode& mode = modes.analysis.modes[static_cast<std::size_t>(index)];
    const double x = omega * omega;
    const double ratio = (mode.shape(1) / mode.shape(0)).real() + 1.0;
    EXPECT_NEAR(ratio, (K11 - x * M11) / (x * M12), 1e-9 * std::abs(ratio));
    EXPECT_NEAR((mode.shape(1) / mode.shape(0)).imag(), 0.0, 1e-12);
  }
  EXPECT_GT((modes.analysis.modes[0].shape(1) / modes.analysis.modes[0].shape(0)).real(), 0.0);
  EXPECT_LT((modes.analysis.modes[1].shape(1) / modes.analysis.modes[1].shape(0)).real(), 0.0);
}

TEST(Modes, SpringAndMassOnASlider) {
  const double m = 2, k = 800, zeta = 0.1;
  const ScenarioModes modes = modes_of(example("modes/spring_slider.yaml"));
  ASSERT_EQ(modes.analysis.modes.size(), 1U);
  const Mode& mode = modes.analysis.modes[0];
  const double omega_n = std::sqrt(k / m);
  expect_relative(mode.natural_frequency, omega_n);
  expect_relative(mode.damping_ratio, zeta);
  expect_relative(mode.growth_rate, -zeta * omega_n);
  expect_relative(mode.damped_frequency, omega_n * std::sqrt(1 - zeta * zeta));
  // (zeta = 1 is left out: there the two eigenvalues coincide with one shape, and a defective
  // eigenvalue is computed only to sqrt(round-off).)
  for (const double ratio : {0.0, 0.5}) {
    const ScenarioModes other =
        modes_of(example("modes/spring_slider.yaml"), {{"zeta", std::to_string(ratio)}});
    expect_relative(other.analysis.modes.at(0).natural_frequency, omega_n);
  }
}

// The chapter's prism, I = diag(5, 20, 17), spun at Omega about each body axis.
TEST(Modes, PrismNutatesAboutItsMajorAndMinorAxesAndTumblesAboutTheIntermediate) {
  const std::array<double, 3> I{5, 20, 17};
  for (const double Omega : {1.0, 2.5}) {
    for (int axis = 0; axis < 3; ++axis) {
      const double Is = I[static_cast<std::size_t>(axis)];
      const double Ia = I[static_cast<std::size_t>((axis + 1) % 3)];
      const double Ib = I[static_cast<std::size_t>((axis + 2) % 3)];
      const ScenarioModes modes =
          modes_of(example("modes/prism_axes.yaml"),
                   {{"axis", std::to_string(axis + 1)}, {"Omega", std::to_string(Omega)}});
      // Its place and turn are ignorable (no force): Euler's equations are what is left. Set
      // aside, its turn about the spin axis still moves, at Omega: a steady motion, not an
      // equilibrium.
      EXPECT_EQ(modes.linearisation.ignorable.size(), 6U);
      EXPECT_FALSE(modes.linearisation.equilibrium());
      ASSERT_EQ(modes.linearisation.drifting.size(), 1U);
      const DriftingCoordinate& turn = modes.linearisation.drifting[0];
      EXPECT_EQ(turn.name, fmt::format("prism.r{}", "xyz"[axis]));
      EXPECT_NEAR(turn.rate, Omega, 1e-15 * Omega);
      if (axis == 2) {
        // I1 < I2 < I3 with the spin about I2 = 17: lambda = Omega sqrt((I2-I1)(I3-I2)/(I1 I3)).
        const double lambda = Omega * std::sqrt((17.0 - 5.0) * (20.0 - 17.0) / (5.0 * 20.0));
        EXPECT_EQ(modes.analysis.verdict, ModalAnalysis::Verdict::Unstable);
        test::expect_undamped_twins(modes.analysis);
        expect_relative(modes.analysis.modes[0].growth_rate, lambda);
        expect_relative(modes.analysis.modes[1].growth_rate, -lambda);
        EXPECT_NEAR(lambda, 0.6 * Omega, 1e-15);
      } else {
        const double nu = Omega * std::sqrt((Is - Ia) * (Is - Ib) / (Ia * Ib));
        EXPECT_EQ(modes.analysis.verdict, ModalAnalysis::Verdict::Stable);
        const Mode& nutation = first_of(modes.analysis, Mode::Kind::Oscillating);
        expect_relative(nutation.damped_frequency, nu);
      }
    }
  }
}

// The chapter's worked example 7: the wheel on its axle, pivoted, in steady precession.
TEST(Modes, GyroscopeNutatesAboutItsSteadyPrecession) {
  const double M = 1, R = 0.1, h = 0.02, d = 0.1, g = 9.81;
  const double I_a = M * R * R / 2;
  const double I_t = M * (3 * R * R + h * h) / 12 + M * d * d;  // about the pivot, across the axle
  for (const double w_s : {100.0, 40.0}) {
    const ScenarioModes modes = modes_of(example("gyroscope.yaml"), {{"w_s", std::to_string(w_s)}});
    const double Omega = M * g * d / (I_a * w_s);
    // Steady: the wheel spins at w_s and the whole turns about the vertical at Omega.
    ASSERT_EQ(modes.linearisation.symmetries.size(), 2U);
    expect_relative(modes.linearisation.symmetry_rates(0), w_s);
    expect_relative(modes.linearisation.symmetry_rates(1), Omega);
    // Nutation about steady precession with the axle horizontal (theta = pi/2 in Euler angles):
    // I_t eps'' + (I_t Omega^2 + (I_a w_s)^2 / I_t) eps = 0.
    const double nutation = std::sqrt(Omega * Omega + std::pow(I_a * w_s / I_t, 2));
    EXPECT_EQ(modes.analysis.verdict, ModalAnalysis::Verdict::Stable);
    const Mode& mode = first_of(modes.analysis, Mode::Kind::Oscillating);
    expect_relative(mode.damped_frequency, nutation);
    // The rest are neutral: a neighbouring steady precession.
    for (const Mode& other : modes.analysis.modes) {
      if (&other != &mode) {
        EXPECT_EQ(other.kind, Mode::Kind::Neutral);
      }
    }
  }
}

TEST(Modes, AStateThatIsNeitherSaysWhichRateAndByHowMuch) {
  // The mast example starts with a nudge of 0.01 rad/s.
  try {
    modes_of(example("inverted_mast.yaml"));
    FAIL() << "no NotSteady";
  } catch (const NotSteady& e) {
    EXPECT_NE(std::string(e.what()).find("base.angle moves at 0.01 rad/s"), std::string::npos)
        << e.what();
  }
  // Released without precession, the gyroscope's axle starts to fall: its angular velocity
  // changes at M g d / I_t.
  try {
    modes_of(example("gyroscope.yaml"), {{"precession", "0"}});
    FAIL() << "no NotSteady";
  } catch (const NotSteady& e) {
    EXPECT_NE(std::string(e.what()).find("pivot.w"), std::string::npos) << e.what();
  }
  // Contacts are not linearised yet: said so, not guessed.
  EXPECT_THROW(modes_of(example("backspin_disk.yaml")), NotSteady);
}

// The modal equations are the Newton-Euler equations projected onto the joints' speeds, a
// different algorithm from the articulated-body passes that integrate the model: at states far
// from equilibrium, with springs, dampers, loads and motors, both give the same accelerations.
void expect_same_accelerations(const Scenario& scenario) {
  const std::shared_ptr<const ModalEquations> eq = modal_equations_of(scenario);
  const ArticulatedModel& model = eq->model();
  ArticulatedFormulation formulation(eq->shared_model());
  const VecX& y0 = eq->y0();
  formulation.begin(0.0, y0);
  VecX dydt(y0.size());
  formulation.derivative(0.0, y0, dydt);
  const VecX rates = eq->rates<double>(VecX::Zero(eq->layout().size()));
  const double scale = 1.0 + dydt.cwiseAbs().maxCoeff();
  for (std::size_t k = 0; k < model.tree.size(); ++k) {
    const TreeJoint& joint = model.tree[k];
    const Eigen::Index so = eq->layout().speed_offset[k];
    if (so < 0) continue;
    const double sign = eq->layout().sign[k];
    if (joint.type == JointType::Free) {
      const Mat3 R = rotation_at(y0, joint.q + 3);
      const Vec3 omega = y0.segment<3>(joint.v), v = y0.segment<3>(joint.v + 3);
      const Vec3 a_G = R * (dydt.segment<3>(joint.v + 3) + omega.cross(v));
      EXPECT_LT((rates.segment<3>(so) - a_G).norm(), 1e-12 * scale) << scenario.file;
      EXPECT_LT((rates.segment<3>(so + 3) - dydt.segment<3>(joint.v)).norm(), 1e-12 * scale);
      continue;
    }
    for (int i = 0; i < joint.nv; ++i) {
      EXPECT_NEAR(rates(so + i), sign * dydt(joint.v + i), 1e-12 * scale)
          << scenario.file << " joint " << k;
    }
  }
}

TEST(Modes, ProjectedNewtonEulerAgreesWithTheArticulatedBodyPasses) {
  expect_same_accelerations(load_scenario(example("pendulum_chain.yaml"), {}));
  expect_same_accelerations(load_scenario(example("gyroscope.yaml"), {{"precession", "0.3"}}));
  expect_same_accelerations(load_scenario(example("reaction_wheel.yaml"), {}));
  expect_same_accelerations(load_scenario(example("inverted_mast.yaml"), {{"omega0", "2"}}));
  expect_same_accelerations(load_scenario_text(R"(tumble: 1
gravity: [0, -3, -9.81]
bodies:
  top: {shape: box, size: [0.4, 0.2, 0.1], mass: 2, position: [0, 0, -0.3],
        orientation: {axis: [1, 2, 3], angle: 0.4}, angular_velocity: [0.5, -1, 2]}
  rider: {shape: sphere, radius: 0.05, mass: 0.5, position: [0.1, 0, -0.3]}
  flier: {shape: cylinder, radius: 0.1, length: 0.3, mass: 1.5, position: [1, 1, 1],
          velocity: [0.3, -0.2, 0.4], angular_velocity: [3, 1, -2]}
  hinged: {shape: box, size: [0.3, 0.05, 0.05], mass: 0.7, position: [0.15, 0, -0.5]}
joints:
  pivot: {type: ball, body: top, at: [0, 0, 0]}
  rail: {type: prismatic, bodies: [top, rider], at: [0.1, 0, -0.3], axis: [1, 0, 0],
         motor: {force: 0.3}}
  elbow: {type: hinge, bodies: [hinged, top], at: [0, 0, -0.5], axis: [0, 1, 0],
          motor: {torque: 0.2}}
forces:
  - {type: torsional_spring, bodies: [ground, top], stiffness: 3, damping: 0.4,
     rest: {axis: [0, 1, 0], angle: 0.3}}
  - {type: spring, bodies: [ground, rider], at: [[0.5, 0.5, 0], [0.1, 0, -0.3]], stiffness: 20,
     rest_length: 0.2, damping: 1.5}
  - {type: spring, bodies: [flier, hinged], at: [[1, 1, 1.1], [0.3, 0, -0.5]], stiffness: 5,
     damping: 0.3}
  - {type: torsional_spring, bodies: [top, hinged], stiffness: 2, damping: 0.1, rest: 0.2}
  - {type: force, body: flier, at: [1.05, 1, 1], value: [0.2, 0.1, 0.3], frame: body}
  - {type: torque, body: top, value: [0.1, 0, 0.05]}
simulate: {duration: 1, rtol: 1e-8, atol: 1e-10}
)",
                                               "<many elements>", {}));
}

// The Jacobian is exact: central differences of the same equations agree to their own error.
TEST(Modes, JacobianAgreesWithCentralDifferences) {
  const std::shared_ptr<const ModalEquations> eq =
      modal_equations_of(load_scenario(example("modes/double_pendulum.yaml"), {}));
  const Eigen::Index n = eq->layout().size();
  const MatX J = jacobian_at_zero([&](const VecXOf<Dual>& z) { return eq->rates<Dual>(z); }, n);
  // Hinges only: their chart is exact away from zero, so differences may step off it.
  for (Eigen::Index j = 0; j < n; ++j) {
    const double h = 1e-5;
    VecX plus = VecX::Zero(n), minus = VecX::Zero(n);
    plus(j) = h;
    minus(j) = -h;
    const VecX column = (eq->rates<double>(plus) - eq->rates<double>(minus)) / (2 * h);
    EXPECT_LT((column - J.col(j)).cwiseAbs().maxCoeff(), 1e-7 * (1 + J.cwiseAbs().maxCoeff()));
  }
}

TEST(ModesCommand, WritesTheModesCsvAndThePageAndSaysWhyNot) {
  const std::filesystem::path out = test::fresh_test_dir("ModesCommand", "WritesTheModesCsv");
  const test::CommandResult ok = test::run_tumble("modes " + example("modes/double_pendulum.yaml") +
                                                  " --animate --out " + out.string());
  ASSERT_EQ(ok.status, 0) << ok.out;
  EXPECT_NE(ok.out.find("verdict: stable"), std::string::npos) << ok.out;
  std::ifstream csv(out / "double_pendulum_modes.csv");
  std::string header, row;
  std::getline(csv, header);
  std::getline(csv, row);
  EXPECT_EQ(header.rfind("mode,kind,eigenvalue_real,eigenvalue_imag,", 0), 0U) << header;
  EXPECT_NE(header.find("elbow.angle.amplitude,elbow.angle.phase_deg"), std::string::npos);
  EXPECT_EQ(row.rfind("1,\"oscillating\",0,", 0), 0U) << row;
  EXPECT_TRUE(std::filesystem::exists(out / "double_pendulum_modes.html"));

  // The prism spun about its intermediate axis: a steady motion (its turn moves, set aside), a
  // growing mode and its decaying twin. Neither has a period; the twin has no damping ratio.
  const test::CommandResult prism = test::run_tumble("modes " + example("modes/prism_axes.yaml") +
                                                     " --set axis=3 --out " + out.string());
  ASSERT_EQ(prism.status, 0) << prism.out;
  EXPECT_NE(prism.out.find("about: a steady motion"), std::string::npos) << prism.out;
  EXPECT_NE(prism.out.find("prism.rz (ignorable) moving at 1 rad/s"), std::string::npos)
      << prism.out;
  EXPECT_NE(prism.out.find("decaying twin of 1"), std::string::npos) << prism.out;
  std::ifstream prism_csv(out / "prism_axes_modes.csv");
  std::vector<std::vector<std::string>> fields;
  for (std::string line; std::getline(prism_csv, line);) {
    fields.emplace_back();
    std::stringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) fields.back().push_back(cell);
  }
  ASSERT_GE(fields.size(), 3U);
  EXPECT_EQ(fields[0][6], "period_s");
  EXPECT_EQ(fields[0][7], "damping_ratio");
  EXPECT_EQ(fields[1][1], "\"growing\"");
  EXPECT_EQ(fields[1][6], "");
  EXPECT_EQ(fields[1][7], "-1");
  EXPECT_EQ(fields[2][1], "\"decaying twin\"");
  EXPECT_EQ(fields[2][6], "");
  EXPECT_EQ(fields[2][7], "");

  const test::CommandResult neither =
      test::run_tumble("modes " + example("inverted_mast.yaml") + " --out " + out.string());
  EXPECT_EQ(neither.status, 6) << neither.out;
  EXPECT_NE(neither.out.find("neither an equilibrium nor a steady motion"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(out / "inverted_mast_modes.csv"));

  const test::CommandResult bad =
      test::run_tumble("modes " + example("modes/bat.yaml") + " --set M=-1 --out " + out.string());
  EXPECT_EQ(bad.status, 3) << bad.out;
  std::filesystem::remove_all(out);
}

}  // namespace
}  // namespace tumble
