// Stiff systems with the implicit method (`integrator: radau5`): its Jacobian, taken by automatic
// differentiation of the one physics (modes/state_jacobian.hpp), against the run's own equations;
// the stiff mount (examples/stiff_mount.yaml) against its closed form in a few hundred steps,
// where an explicit method's stability asks for thousands (and 150,000 a second); the chapter's
// prism against its 40-digit reference; what it does not take yet, refused where the scenario
// says it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "jacobian_checks.hpp"
#include "prism_reference.hpp"
#include "scenario_run.hpp"
#include "test_files.hpp"
#include "tumble/integrators/tolerances.hpp"
#include "tumble/modes/state_jacobian.hpp"
#include "tumble/multibody/articulated_formulation.hpp"
#include "tumble/scenario/scenario_document.hpp"
#include "tumble/simulation/simulation.hpp"

namespace tumble {
namespace {

// A box of 1 kg on a rail, held by a mount of k = 1e9 N/m with a damper of c = 1e6 N s/m, let go
// 1 mm from its rest: overdamped, its modes at about -k/c = -1000 s^-1 and -c/m = -1e6 s^-1.
constexpr char kMount[] = R"(tumble: 1
name: a stiff overdamped mount
parameters: {m: 1, k: 1e9, c: 1e6, x0: 1e-3, v0: 0}
gravity: [0, 0, 0]
bodies:
  box: {shape: box, size: [0.1, 0.1, 0.1], mass: m, position: [x0, 0, 0], velocity: [v0, 0, 0]}
joints:
  rail: {type: prismatic, body: box, at: [0, 0, 0], axis: [1, 0, 0]}
forces:
  - {type: spring, name: mount, bodies: [ground, box], at: [[-1, 0, 0], [x0, 0, 0]],
     stiffness: k, rest_length: 1, damping: c}
simulate: {duration: 1, integrator: radau5, rtol: 1e-8, atol: 1e-12, output_every: 0.01}
)";

// Two links on hinges, a stiff torsional spring at the knee, swinging.
constexpr char kDoublePendulum[] = R"(tumble: 1
name: a double pendulum with a stiff knee
gravity: [0, 0, -9.81]
bodies:
  upper: {shape: box, size: [0.05, 0.05, 1], mass: 2, position: [0.3, 0, -0.45],
          orientation: {axis: [0, 1, 0], angle: -0.6}, angular_velocity: [0, 1.5, 0]}
  lower: {shape: box, size: [0.05, 0.05, 1], mass: 1, position: [0.3, 0, -1.45],
          orientation: {axis: [0, 1, 0], angle: -0.6}, angular_velocity: [0, 1.5, 0]}
joints:
  hip: {type: hinge, body: upper, at: [0.3, 0, 0.05], axis: [0, 1, 0]}
  knee: {type: hinge, bodies: [upper, lower], at: [0.3, 0, -0.95], axis: [0, 1, 0]}
forces:
  - {type: torsional_spring, bodies: [upper, lower], stiffness: 1e6, damping: 10}
simulate: {duration: 0.1, integrator: radau5, rtol: 1e-8, atol: 1e-10}
)";

// A top on a ball joint, spinning and leaning, on a torsional spring to ground.
constexpr char kTop[] = R"(tumble: 1
name: a top on a ball joint
gravity: [0, 0, -9.81]
bodies:
  top: {shape: cylinder, radius: 0.3, length: 0.1, mass: 1, position: [0.1, 0, 0.5],
        orientation: {axis: [0, 1, 0], angle: 0.2}, angular_velocity: [0.3, -0.2, 40]}
joints:
  tip: {type: ball, body: top, at: [0, 0, 0]}
forces:
  - {type: torsional_spring, bodies: [ground, top], stiffness: 1e4, damping: 1}
simulate: {duration: 0.1, integrator: radau5, rtol: 1e-8, atol: 1e-10}
)";

// A free box hung by a stiff spring from a point above its top, at rest where the spring holds
// its weight.
constexpr char kHung[] = R"(tumble: 1
name: a box hung on a stiff spring
parameters: {m: 1, g: 9.81, k: 1e6}
gravity: [0, 0, -g]
bodies:
  box: {shape: box, size: [0.2, 0.1, 0.1], mass: m, position: [0, 0, 0]}
forces:
  - {type: spring, bodies: [ground, box], at: [[0.05, 0, 1], [0.05, 0, 0.05]], stiffness: k,
     rest_length: 0.95 - m*g/k, damping: 0}
simulate: {duration: 0.1, integrator: radau5, rtol: 1e-8, atol: 1e-10}
)";

// A chain of twenty points on hinges, bent into a zigzag: forty modal coordinates, more than a
// dual number carries (kDualSeeds), so its Jacobian is taken in two evaluations.
std::string zigzag_chain() {
  std::string yaml = "tumble: 1\nbodies:\n";
  std::string joints = "joints:\n";
  double x = 0.0, z = 0.0;
  for (int i = 1; i <= 20; ++i) {
    const double angle = i % 2 == 0 ? 0.4 : -0.3;  // rad from the downward vertical
    const double x_end = x + 0.1 * std::sin(angle), z_end = z - 0.1 * std::cos(angle);
    yaml += fmt::format("  p{}: {{shape: point, mass: {}, position: [{}, 0, {}]}}\n", i,
                        0.1 + 0.01 * i, x_end, z_end);
    joints +=
        fmt::format("  j{}: {{type: hinge, bodies: [{}, p{}], at: [{}, 0, {}], axis: [0, 1, 0]}}\n",
                    i, i == 1 ? std::string("ground") : fmt::format("p{}", i - 1), i, x, z);
    x = x_end;
    z = z_end;
  }
  return yaml + joints + "simulate: {duration: 1, integrator: radau5}\n";
}

// examples/stiff_mount.yaml's box let go x0 from its rest: x(t) = a e^(r1 t) + b e^(r2 t), r the
// roots of m r^2 + c r + k = 0, and the largest departure of a run's rows from it (from row
// `first` on).
constexpr double kMountX0 = 1e-3;
double mount_stretch(double t) {
  const double m = 1.0, k = 1e9, c = 1e6;
  const double root = std::sqrt(c * c - 4.0 * k * m);
  const double r1 = (-c + root) / (2.0 * m), r2 = (-c - root) / (2.0 * m);
  const double b = -r1 * kMountX0 / (r2 - r1), a = kMountX0 - b;
  return a * std::exp(r1 * t) + b * std::exp(r2 * t);
}
double mount_departure(const test::ScenarioRun& run, std::size_t first = 0) {
  double worst = 0.0;
  for (std::size_t i = first; i < run.rows.size(); ++i) {
    worst = std::max(worst, std::abs(run.rows[i].states[0].r_G.x() - mount_stretch(run.rows[i].t)));
  }
  return worst;
}

TEST(StateJacobian, IsTheRunsOwnAlongEveryModalDirection) {
  // Wrong by a term (a sign, a coupling, a frame) would be wrong by O(1) of some column; central
  // differences agree with the exact derivative to about 1e-9 of the largest entry here.
  EXPECT_LT(test::largest_jacobian_departure(test::replaced(kMount, "v0: 0", "v0: 0.3"), "mount"),
            1e-7);
  EXPECT_LT(test::largest_jacobian_departure(kDoublePendulum, "double_pendulum"), 1e-7);
  EXPECT_LT(test::largest_jacobian_departure(kTop, "top"), 1e-7);
  EXPECT_LT(test::largest_jacobian_departure(kHung, "hung"), 1e-7);
  // The same box thrown sideways and spinning, off its rest: its speeds, kept in its turning
  // axes, are curved in the modal coordinates (JointKind::add_modal_curvature), by terms of the
  // size of omega and of its acceleration (1e3 m/s^2 from the spring stretched 1 mm).
  EXPECT_LT(test::largest_jacobian_departure(
                test::replaced(kHung, "position: [0, 0, 0]}",
                               "position: [0, 0, -0.001], velocity: [0.5, -0.3, 0.2], "
                               "angular_velocity: [3, -5, 7]}"),
                "hung_spinning"),
            1e-7);
  static_assert(40 > kDualSeeds);
  EXPECT_LT(test::largest_jacobian_departure(zigzag_chain(), "zigzag_chain"), 1e-7);
}

TEST(Radau5Runs, TheStiffMountFollowsItsClosedFormInAFewHundredSteps) {
  // examples/stiff_mount.yaml: 10 ms, ten of the slow mode's time constants.
  const test::ScenarioRun run =
      test::run_scenario(load_scenario(test::example("stiff_mount.yaml"), {}));
  ASSERT_EQ(run.rows.size(), 1001u);
  // Every row within 1e-8 of the initial stretch: the example's atol, which the error estimate
  // and with it the rows' continuous extension are held to (rtol 1e-7 of |x| adds less).
  EXPECT_LT(mount_departure(run), 1e-8 * kMountX0);
  // An explicit method's stability along the fast mode (about 3.3 / 1e6 s a step for dopri5, 6 /
  // 1e6 s for dop853) would take 1,600 steps at least; the slow mode's accuracy takes under 300.
  EXPECT_LE(run.result.report.stats.accepted_steps, 300);
}

TEST(AutoRuns, TheStiffMountIsDop853UntilItsStabilityHoldsTheStepsThenRadau5) {
  // examples/stiff_mount.yaml with `integrator: auto`, beside the same with dop853.
  Scenario scenario = load_scenario(test::example("stiff_mount.yaml"), {});
  scenario.simulate.integrator = "auto";
  const test::ScenarioRun automatic = test::run_scenario(scenario);
  scenario.simulate.integrator = "dop853";
  const test::ScenarioRun dop853 = test::run_scenario(scenario);
  ASSERT_EQ(automatic.rows.size(), 1001u);
  ASSERT_EQ(dop853.rows.size(), 1001u);
  // Until its switch auto is DOP853, row for row; the switch comes once fifteen of DOP853's
  // steps are held at its stability edge, 6.1 / 1e6 s each once the fast mode has died out
  // (about 1e-5 s): within the first millisecond.
  std::size_t first_own = 0;
  while (first_own < automatic.rows.size() &&
         automatic.rows[first_own].states[0].r_G == dop853.rows[first_own].states[0].r_G) {
    ++first_own;
  }
  ASSERT_LT(automatic.rows[first_own].t, 1e-3);
  ASSERT_GT(first_own, 1u);
  // From there on, radau5's rows: within 1e-8 of the initial stretch (the example's atol), as
  // radau5 alone (TheStiffMountFollowsItsClosedFormInAFewHundredSteps). (Before it, DOP853's
  // rows inside its steps beyond the stability edge carry its continuous extension's error of
  // the fast mode: 2.8e-11 m at 40 us, against 1.8e-13 m at its steps' ends.)
  EXPECT_LT(mount_departure(automatic, first_own), 1e-8 * kMountX0);
  // Fewer steps than radau5 alone (229): DOP853's are cheaper through the transient.
  EXPECT_LE(automatic.result.report.stats.accepted_steps, 229);
  EXPECT_GT(dop853.result.report.stats.accepted_steps, 1600);
}

TEST(AutoRuns, AnRtolBelowRoundOffIsRaisedAndTheStiffnessStillFound) {
  // examples/stiff_mount.yaml with `integrator: auto` at rtol 1e-14: raised to 100 eps with a
  // warning at the key. At so tight a tolerance DOP853's controller keeps its steps just inside
  // its stability edge (|h lambda| 4 to 6, one attempt in three rejected), where Hairer's test
  // alone (above 6.1) never fires and DOP853 took 2,192 steps; the rejected attempts near the
  // edge find the stiffness, and radau5 takes the slow motion. With the example's atol (1e-11 m)
  // setting the error's scale of the position at either rtol, the run takes about the steps of
  // rtol 1e-10 (617 against 498 measured: radau5's are a little shorter where the speed's rtol
  // share is 1e-4 of the looser one's), and is as close to the closed form.
  const std::string path = test::example("stiff_mount.yaml");
  auto with_rtol = [&](const std::string& rtol) {
    const std::string text =
        test::replaced(read_scenario_file(path), "rtol: 1e-7", "rtol: " + rtol);
    Scenario scenario = load_scenario_text(text, path, {});
    scenario.simulate.integrator = "auto";
    return scenario;
  };
  const Scenario tight = with_rtol("1e-14");
  EXPECT_EQ(tight.simulate.rtol, tolerances::kMinRtol);
  ASSERT_EQ(tight.warnings.size(), 1u);
  EXPECT_NE(tight.warnings[0].find("simulate.rtol: rtol 1e-14 is below what round-off allows"),
            std::string::npos)
      << tight.warnings[0];
  const test::ScenarioRun floor = test::run_scenario(tight);
  const test::ScenarioRun loose = test::run_scenario(with_rtol("1e-10"));
  ASSERT_EQ(floor.rows.size(), 1001u);
  EXPECT_LT(mount_departure(floor), 1e-8 * kMountX0);
  const long steps = floor.result.report.stats.accepted_steps;
  EXPECT_LE(steps, 1.3 * static_cast<double>(loose.result.report.stats.accepted_steps));
  EXPECT_LT(steps, 1000);
}

TEST(TrBdf2Runs, TheStiffMountFollowsItsClosedFormAtEngineeringTolerances) {
  // examples/stiff_mount.yaml through trbdf2 (order 2, L-stable) at rtol 1e-4 and 1e-6, atol
  // 1e-4 rtol x0 (the example's ratio): every row within 10 rtol x0 of the closed form (the
  // steps' errors, each held to the tolerance, add up over a hundred steps or so before the slow
  // mode's decay damps them), in a tenth (rtol 1e-4: 130 steps) and a third (1e-6: 570; an
  // order-2 method's steps grow as rtol^(-1/3)) of dop853's, which its stability holds at about
  // 1,570 whatever the tolerance.
  for (const auto& [rtol, most_steps] : {std::pair{1e-4, 157L}, std::pair{1e-6, 785L}}) {
    Scenario scenario = load_scenario(test::example("stiff_mount.yaml"), {});
    scenario.simulate.integrator = "trbdf2";
    scenario.simulate.rtol = rtol;
    scenario.simulate.atol = 1e-4 * rtol * 1e-3;
    const test::ScenarioRun run = test::run_scenario(scenario);
    EXPECT_LT(mount_departure(run), 10.0 * rtol * kMountX0) << rtol;
    EXPECT_LT(run.result.report.stats.accepted_steps, most_steps) << rtol;
  }
}

// The largest distance, over the rows and the arms' and the slider's positions, between two runs
// of the flyball governor (the same rows).
double flyball_departure(const test::ScenarioRun& run, const test::ScenarioRun& reference) {
  EXPECT_EQ(run.rows.size(), reference.rows.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < std::min(run.rows.size(), reference.rows.size()); ++i) {
    for (std::size_t body = 1; body < 4; ++body) {  // arm1, arm2, slider
      worst = std::max(worst, (run.rows[i].states[body].r_G - reference.rows[i].states[body].r_G)
                                  .cwiseAbs()
                                  .maxCoeff());
    }
  }
  return worst;
}

TEST(AutoRuns, TheFlyballGovernorTakesATwentiethOfDopri5sStepsForABetterAnswer) {
  // examples/flyball_governor.yaml (IFToMM A05's proportions: couplers of 8e5 N/m and 4e4 N s/m)
  // over its first second, against dop853 at rtol 1e-12: auto (the example's rtol 1e-8) within
  // 1e-8 m, rtol of the 1 m arms, at every row; dopri5 at rtol 1e-4, the loosest that still
  // follows the swing, held to more than ten times auto's steps by its stability along the
  // couplers' damping, and further off.
  Scenario scenario = load_scenario(test::example("flyball_governor.yaml"), {});
  scenario.simulate.duration = 1.0;
  ASSERT_EQ(scenario.simulate.integrator, "auto");
  const test::ScenarioRun automatic = test::run_scenario(scenario);
  scenario.simulate.integrator = "dopri5";
  scenario.simulate.rtol = 1e-4;
  scenario.simulate.atol = 1e-6;
  const test::ScenarioRun dopri5 = test::run_scenario(scenario);
  scenario.simulate.integrator = "dop853";
  scenario.simulate.rtol = 1e-12;
  scenario.simulate.atol = 1e-14;
  const test::ScenarioRun reference = test::run_scenario(scenario);

  const double auto_error = flyball_departure(automatic, reference);
  const double dopri5_error = flyball_departure(dopri5, reference);
  EXPECT_LT(auto_error, 1e-8);
  EXPECT_GT(dopri5_error, auto_error);
  EXPECT_GT(dopri5.result.report.stats.accepted_steps,
            10 * automatic.result.report.stats.accepted_steps);
  // No torque about the shaft's axis: Lz is kept, to the tolerance's order.
  const double lz0 = automatic.rows.front().quantities.angular_momentum_about_origin.z();
  for (const test::Row& row : automatic.rows) {
    EXPECT_NEAR(row.quantities.angular_momentum_about_origin.z(), lz0, 1e-7 * std::abs(lz0));
  }
}

TEST(Radau5Runs, OverASecondTheStepsAreTheSlowModesOnly) {
  // A thousand of the slow mode's time constants: 150,000 steps at least by stability alone.
  const test::ScenarioRun run = test::run_inline_scenario(kMount, "mount");
  EXPECT_LT(run.result.report.stats.accepted_steps, 1500);
  EXPECT_LT(std::abs(run.rows.back().states[0].r_G.x()), 1e-9 * 1e-3);  // settled: exp(-1000)
}

TEST(Radau5Runs, TheTextbookFormulationIsRefusedAtTheIntegrator) {
  // The chapter's [R; omega] form has no Jacobian (the modal equations are the articulated
  // form's); contacts in every mode have one.
  const std::string ball = R"(tumble: 1
bodies:
  ball: {shape: sphere, radius: 0.1, mass: 1, position: [0, 0, 0.1]}
simulate: {duration: 1, integrator: radau5, formulation: textbook}
)";
  test::expect_error(ball, 4, 37, "simulate.integrator", "not in formulation: textbook");
  test::expect_error(test::replaced(ball, "integrator: radau5", "integrator: trbdf2"), 4, 37,
                     "simulate.integrator", "trbdf2, an implicit method for stiff systems");
}

TEST(Radau5Runs, TheChaptersPrismAgainstItsFortyDigitReference) {
  // examples/tumbling_prism.yaml through radau5 (its free body in the articulated form, whose
  // Jacobian the modal equations give): the state at t = 20 s, after the flip, against the
  // Jacobi elliptic reference, within 10 rtol (dop853 at these tolerances ends 8e-11 off;
  // radau5, whose order-3 estimate is held to rtol, takes 1,243 steps to its 51 and ends 6e-13
  // off: it is not the method for a body that is not stiff, but it is right on it).
  Scenario scenario = load_scenario(test::example("tumbling_prism.yaml"), {});
  scenario.simulate.integrator = "radau5";
  scenario.simulate.rtol = 1e-10;
  scenario.simulate.atol = 1e-12;
  const test::ScenarioRun run = test::run_scenario(scenario);
  const testing::ReferenceState& at_20 = testing::prism_case("unstable").states[0];
  ASSERT_DOUBLE_EQ(run.rows.back().t, at_20.t);
  const BodyState& end = run.rows.back().states[0];
  EXPECT_LT(testing::state_error(end.R_WB, end.omega_W, at_20), 10 * scenario.simulate.rtol);
  EXPECT_LT(run.result.conservation.max_relative_energy_drift, 1e-9);
}

}  // namespace
}  // namespace tumble
