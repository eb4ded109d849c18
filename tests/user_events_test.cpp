// A scenario's own events (`events:`), each located by the driver as it locates the contacts'
// mode changes, against closed forms: a crate sliding with Coulomb friction stopped where it has
// slid d, at t = (v0 - sqrt(v0^2 - 2 mu g d)) / (mu g); the half-speed instant v0 / (2 mu g);
// the chapter's prism's first flip (the body-frame spin about k changing sign) at the 40-digit
// reference's time, integrated and in closed form (`integrator: exact`). Also: the direction of an
// expression's crossing, the errors' locations, and a run resumed from a checkpoint finding the
// same events.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <string>

#include "scenario_run.hpp"
#include "test_constants.hpp"
#include "test_files.hpp"
#include "tumble/exact/torque_free.hpp"
#include "tumble/simulation/table_run.hpp"
#include "tumble/sweep/outcome.hpp"
#include "tumble/sweep/sweep.hpp"

namespace tumble {
namespace {

using test::kG;
constexpr double kMu = 0.3, kV0 = 3.0;

std::string crate(const std::string& d, const std::string& events) {
  return R"(tumble: 1
parameters: {mu: 0.3, v0: 3, d: )" +
         d + R"(, g: 9.81}
gravity: [0, 0, -g]
bodies:
  crate: {shape: box, size: [0.4, 0.4, 0.4], mass: 5, position: [0, 0, 0.2], velocity: [v0, 0, 0]}
contacts:
  - {name: floor, type: plane, body: crate, plane: {point: [0, 0, 0], normal: [0, 0, 1]}, friction: mu}
events:
)" + events +
         R"(
simulate: {duration: 2, integrator: dop853, rtol: 1e-10, atol: 1e-12, output_every: 0.01}
)";
}

// While it slides, x = v0 t - mu g t^2 / 2 and vx = v0 - mu g t: the dense output of a quadratic
// is exact, so the event is located to the root finder's precision (a few ulps of t), far inside
// the 1e-12 asked here.
TEST(UserEvents, ACrateStoppedWhereItHasSlidD) {
  const double d = 1.0;
  const test::ScenarioRun run = test::run_inline_scenario(
      crate("1", "  - {name: slid_d, when: crate.x > d, stop: true}"), "slid_d");
  const double a = kMu * kG;
  const double t_d = (kV0 - std::sqrt(kV0 * kV0 - 2.0 * a * d)) / a;
  ASSERT_EQ(run.result.user_events.size(), 1u);
  EXPECT_EQ(run.result.user_events[0].name, "slid_d");
  EXPECT_TRUE(run.result.user_events[0].stopped);
  EXPECT_NEAR(run.result.user_events[0].t, t_d, 1e-12 * t_d);
  // The run ends there, with a row at the event.
  EXPECT_NEAR(run.result.report.t_reached, t_d, 1e-12 * t_d);
  ASSERT_FALSE(run.rows.empty());
  EXPECT_EQ(run.rows.back().t, run.result.user_events[0].t);
  EXPECT_NEAR(run.rows.back().states[0].r_G.x(), d, 1e-12);
}

// An expression's zero with a direction: vx - v0/2 falls through zero at v0 / (2 mu g) and never
// rises; `both` counts the fall; a condition that never holds (d beyond the stopping distance
// v0^2 / (2 mu g) = 1.53 m) never happens, and the run goes to its end.
TEST(UserEvents, AnExpressionsCrossingsCountInTheirDirection) {
  const test::ScenarioRun run = test::run_inline_scenario(
      crate("2", R"(  - {name: half, when: crate.vx - v0/2, direction: down}
  - {name: half_up, when: crate.vx - v0/2, direction: up}
  - {name: half_any, when: crate.vx - v0/2}
  - {name: slid_d, when: crate.x > d, stop: true})"),
      "half");
  const double t_half = kV0 / (2.0 * kMu * kG);
  ASSERT_EQ(run.result.user_events.size(), 2u);
  EXPECT_EQ(run.result.user_events[0].name, "half");
  EXPECT_NEAR(run.result.user_events[0].t, t_half, 1e-12 * t_half);
  EXPECT_EQ(run.result.user_events[1].name, "half_any");
  EXPECT_EQ(run.result.user_events[1].t, run.result.user_events[0].t);
  EXPECT_FALSE(run.result.user_events[0].stopped);
  EXPECT_EQ(run.result.report.t_reached, 2.0);
}

// A condition whose zero falls exactly on a step's end: `t > 10` with rk4 steps of 0.25 was
// reported at 9.75, where it is false (the bracketing took g = 0 at the step's end for the side g
// came from); `t >= 2` with `stop: true` and duration 2 ended the run short of 2 (1.99 with
// dopri5). Each is at its instant exactly, and the stopped run ends at its duration.
TEST(UserEvents, AnEventAtAStepsEndIsAtItsInstantExactly) {
  const std::string fixed = R"(tumble: 1
gravity: [0, 0, 0]
bodies:
  ball: {shape: sphere, radius: 0.1, mass: 1, velocity: [1, 0, 0]}
events:
  - {name: ten, when: t > 10}
simulate: {duration: 12, integrator: rk4, step: 0.25}
)";
  const test::ScenarioRun stepped = test::run_inline_scenario(fixed, "at_step_end");
  ASSERT_EQ(stepped.result.user_events.size(), 1u);
  EXPECT_EQ(stepped.result.user_events[0].t, 10.0);
  for (const char* integrator : {"dopri5", "dop853"}) {
    const test::ScenarioRun stopped =
        test::run_inline_scenario(fmt::format(R"(tumble: 1
gravity: [0, 0, -9.81]
bodies:
  ball: {{shape: sphere, radius: 0.1, mass: 1, velocity: [1, 0, 5]}}
events:
  - {{name: end, when: t >= 2, stop: true}}
simulate: {{duration: 2, integrator: {}, output_every: 0.1}}
)",
                                              integrator),
                                  std::string("stop_at_end_") + integrator);
    ASSERT_EQ(stopped.result.user_events.size(), 1u) << integrator;
    EXPECT_EQ(stopped.result.user_events[0].t, 2.0) << integrator;
    EXPECT_TRUE(stopped.result.user_events[0].stopped) << integrator;
    EXPECT_EQ(stopped.result.report.t_reached, 2.0) << integrator;
    // The schedule's rows, 0 to 2 s, once each: the one at the event is the last.
    ASSERT_EQ(stopped.rows.size(), 21u) << integrator;
    EXPECT_EQ(stopped.rows.back().t, 2.0) << integrator;
  }
}

// A condition that a jump makes true: the bat, at rest, is struck at t = 0.1 (its angular
// velocity jumps from 0 to -P d / I_O about y), so `bat.wy < -0.1` turns true at the blow. The
// steps after it saw it already true: the event was not reported at the blow, only (wrongly) at
// the next swing. It is at the blow's instant exactly, and once.
TEST(UserEvents, AConditionAJumpMakesTrueIsAtTheJump) {
  std::string text = test::read_file(std::string(TUMBLE_SOURCE_DIR) + "/examples/bat_struck.yaml");
  const std::string simulate = "simulate:";
  ASSERT_NE(text.find(simulate), std::string::npos);
  text.insert(text.find(simulate), "events:\n  - {name: struck, when: bat.wy < -0.1}\n");
  text.replace(text.find("duration: 2"), std::string("duration: 2").size(), "duration: 0.3");
  const test::ScenarioRun run = test::run_inline_scenario(text, "struck");
  ASSERT_EQ(run.result.user_events.size(), 1u);
  EXPECT_EQ(run.result.user_events[0].name, "struck");
  EXPECT_EQ(run.result.user_events[0].t, 0.1);
}

// The chapter's prism (examples/sweeps/prism_flip_time.yaml at its tilt of 0.01 rad/s, dop853 at
// rtol 1e-12): the event `prism.w3 < 0` at the reference's 9.664094834075236 s. The event is
// located on the integrator's continuous extension, whose error at rtol 1e-12, grown by
// exp(lambda t) ~ 300 along the unstable spin over the 9.7 s, bounds the time to about 1e-9 s.
TEST(UserEvents, ThePrismsFlipAtTheReferencesTime) {
  std::string text =
      test::read_file(std::string(TUMBLE_SOURCE_DIR) + "/examples/sweeps/prism_flip_time.yaml");
  text.replace(text.find("simulate:"), 0, "events:\n  - {name: flip, when: prism.w3 < 0}\n");
  const test::ScenarioRun run = test::run_inline_scenario(text, "flip");
  ASSERT_EQ(run.result.user_events.size(), 2u);  // and again a period later, at 48.3 s
  EXPECT_EQ(run.result.user_events[0].name, "flip");
  EXPECT_NEAR(run.result.user_events[0].t, 9.664094834075236, 1e-9);
}

// The same flip with `integrator: exact` (examples/tumbling_prism.yaml, whose 20 s see it once):
// the event is located on the closed form (the Euler-Poinsot solution, whose flip is 1.1e-14 s
// from the reference's: tests/torque_free_test.cpp), which the exact integrator evaluates through
// the scenario's events as through the formulation alone. A run stopped before the flip and
// resumed (the integrator moved onto the new run's events) finds it at the same instant.
TEST(UserEvents, ThePrismsFlipOnTheClosedForm) {
  std::string text =
      test::read_file(std::string(TUMBLE_SOURCE_DIR) + "/examples/tumbling_prism.yaml");
  const std::string dopri5 = "integrator: dopri5";
  ASSERT_NE(text.find(dopri5), std::string::npos);
  text.replace(text.find(dopri5), dopri5.size(), "integrator: exact");
  text.replace(text.find("simulate:"), 0, "events:\n  - {name: flip, when: prism.w3 < 0}\n");
  const test::ScenarioRun run = test::run_inline_scenario(text, "exact_flip");
  ASSERT_EQ(run.result.user_events.size(), 1u);
  EXPECT_EQ(run.result.user_events[0].name, "flip");
  EXPECT_NEAR(run.result.user_events[0].t, 9.664094834075236, 1e-9);
  EXPECT_EQ(run.result.report.t_reached, 20.0);

  // Over 60 s the spin turns back (at 29 s) and flips again a period of omega_B later: the
  // events are looked for at the ends of steps that turn the prism by an eighth of a turn at
  // most, not at the end of one step over the run (whose ends see no sign change).
  std::string longer = text;
  longer.replace(longer.find("duration: 20"), 12, "duration: 60");
  const test::ScenarioRun twice = test::run_inline_scenario(longer, "exact_flips");
  ASSERT_EQ(twice.result.user_events.size(), 2u);
  EXPECT_EQ(twice.result.user_events[0].t, run.result.user_events[0].t);
  const double period =
      TorqueFreeMotion(Vec3(5.0, 20.0, 17.0).asDiagonal(), Mat3::Identity(), Vec3(0.0, 0.01, 1.0))
          .period();
  EXPECT_NEAR(twice.result.user_events[1].t, run.result.user_events[0].t + period, 1e-9);

  const std::shared_ptr<const SimulationModel> model = build_simulation_model(run.scenario);
  TableRunOptions stop;
  stop.stop_at = 5.0;
  const TableRun before = run_into_table(run.scenario, *model, stop);
  ASSERT_TRUE(before.state.has_value());
  EXPECT_TRUE(before.result.user_events.empty());
  TableRunOptions resume;
  resume.start = &*before.state;
  const TableRun after = run_into_table(run.scenario, *model, resume);
  ASSERT_EQ(after.result.user_events.size(), 1u);
  EXPECT_EQ(after.result.user_events[0].t, run.result.user_events[0].t);
}

TEST(UserEvents, AnUnknownNameOrAMisplacedDirectionIsLocated) {
  test::expect_error(crate("1", "  - {name: e1, when: crate.velocity > 1}"), 9, 22,
                     "events[0].when", "unknown name 'crate.velocity'");
  test::expect_error(crate("1", "  - {name: e1, when: crate.x > d, direction: up}"), 9, 46,
                     "events[0].direction", "a comparison says its own direction");
  test::expect_error(crate("1", "  - {name: e1, when: crate.x > d && t > 1}"), 9, 22,
                     "events[0].when", "one expression (box.x - d), not &&");
  test::expect_error(crate("1", "  - {name: e1, when: crate.x == d}"), 9, 22, "events[0].when",
                     "not ==");
  test::expect_error(crate("1", "  - {name: floor, when: crate.x > d}"), 9, 12, "events[0].name",
                     "names a contact");
}

// An event's condition only reads: `crate.x = -5` wrote into the row that the later events read
// (red-team finding: slid_d then never happened). Every form of assignment is refused at its
// `when:`; == is refused as before.
TEST(UserEvents, AConditionThatAssignsIsLocated) {
  const std::string refused = "'=' would assign a value; an expression only reads its names";
  test::expect_error(crate("1",
                           "  - {name: spoil, when: crate.x = -5}\n"
                           "  - {name: slid_d, when: crate.x > d, stop: true}"),
                     9, 25, "events[0].when", "expression 'crate.x = -5': " + refused);
  test::expect_error(crate("1",
                           "  - {name: slid_d, when: crate.x > d, stop: true}\n"
                           "  - {name: spoil, when: crate.vx - (crate.x = 0)}"),
                     10, 25, "events[1].when", "expression 'crate.vx - (crate.x = 0)': " + refused);
  test::expect_error(crate("1", "  - {name: e1, when: crate.x > (d = 0)}"), 9, 22, "events[0].when",
                     "expression 'crate.x > (d = 0)': " + refused);
  test::expect_error(crate("1", "  - {name: e1, when: crate.x += 1}"), 9, 22, "events[0].when",
                     refused);
  test::expect_error(crate("1", "  - {name: e1, when: crate.x == d}"), 9, 22, "events[0].when",
                     "not ==");
}

}  // namespace
}  // namespace tumble

namespace tumble {
namespace {

// A sweep records a scenario's event: first(event.slid_d) against the closed form over the
// friction (each run's event located to the integrator's precision, not the rows').
// The crate with `events`, swept over one parameter, recording `records`.
SweepSpec crate_sweep(const std::string& events, const std::string& varied,
                      const std::vector<std::string>& records) {
  SweepSpec spec;
  spec.text = crate("1", events);
  spec.path = "events_sweep.yaml";
  spec.varied = {varied};
  for (const std::string& record : records) spec.outcomes.push_back(parse_record(record));
  return spec;
}

TEST(UserEvents, ASweepRecordsTheFirstOccurrence) {
  const SweepSpec spec = crate_sweep("  - {name: slid_d, when: crate.x > d}", "mu",
                                     {"td=first(event.slid_d)", "n=count(event.slid_d)"});
  const std::vector<std::vector<double>> points = {{0.1}, {0.2}, {0.3}, {0.4}};
  const std::vector<RunRecord> records = run_points(spec, points, 2);
  for (std::size_t i = 0; i < points.size(); ++i) {
    ASSERT_EQ(records[i].status, RunStatus::Ok) << records[i].message;
    const double a = points[i][0] * kG;
    const double t_d = (kV0 - std::sqrt(kV0 * kV0 - 2.0 * a)) / a;
    EXPECT_NEAR(records[i].values[0], t_d, 1e-12 * t_d) << points[i][0];
    EXPECT_EQ(records[i].values[1], 1.0);
  }
  SweepSpec unknown = spec;
  unknown.outcomes = {parse_record("td=first(event.slid)")};
  const std::vector<RunRecord> refused = run_points(unknown, points, 1);
  EXPECT_EQ(refused[0].status, RunStatus::Invalid);
  EXPECT_NE(refused[0].message.find("has no event slid"), std::string::npos) << refused[0].message;
}

// An event's condition reads the parameters when a run compiles it: a sweep over a parameter it
// names (here v0, which also sets the initial velocity) reads each run's own scenario rather than
// share one model, and each run's half-speed instant is v0 / (2 mu g) at its own v0.
TEST(UserEvents, ASweepOverAParameterAnEventNamesDoesNotShareTheModel) {
  const SweepSpec spec = crate_sweep("  - {name: half, when: crate.vx - v0/2, direction: down}",
                                     "v0", {"th=first(event.half)"});
  SweepRunner runner(spec);
  for (const double v0 : {2.0, 3.0, 4.0}) {
    const RunRecord record = runner.run(std::vector<double>{v0});
    ASSERT_EQ(record.status, RunStatus::Ok) << record.message;
    const double t_half = v0 / (2.0 * kMu * kG);
    EXPECT_NEAR(record.values[0], t_half, 1e-12 * t_half) << v0;
  }
  EXPECT_FALSE(runner.shares_model());
}

}  // namespace
}  // namespace tumble
