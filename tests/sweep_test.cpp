// tumble sweep's pieces against closed forms: each reduction over a free fall's rows, an event's
// first time and count against the crate's slip stop, the grid's and the random points' order,
// sweep.csv the same bytes on 1 and 2 threads, and runs that fail or are invalid as rows.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>
#include <stdexcept>

#include "test_constants.hpp"
#include "test_files.hpp"
#include "tumble/scenario/scenario_document.hpp"
#include "tumble/sweep/parameter_space.hpp"
#include "tumble/sweep/sweep.hpp"

namespace tumble {
namespace {

using test::kG;

SweepSpec spec_for(const std::string& text, std::vector<std::string> varied,
                   const std::vector<std::string>& records) {
  SweepSpec spec;
  spec.text = text;
  spec.path = "sweep_test.yaml";
  spec.varied = std::move(varied);
  for (const std::string& r : records) spec.outcomes.push_back(parse_record(r));
  return spec;
}

// A ball dropped from z0 at rest: z = z0 - g t^2 / 2, vz = -g t, rows every h to T.
const char* const kFall = R"(tumble: 1
parameters: {z0: 10, T: 1, h: 0.01}
gravity: [0, 0, -9.81]
bodies:
  ball: {shape: sphere, radius: 0.1, mass: 2, position: [0, 0, z0]}
simulate: {duration: T, integrator: dop853, rtol: 1e-12, atol: 1e-14, output_every: h}
)";

TEST(SweepReductions, FreeFallAgainstItsClosedForms) {
  const SweepSpec spec =
      spec_for(kFall, {"z0"},
               {"zf=final(ball.z)", "ztop=max(ball.z)", "zlow=min(ball.z)", "zmean=mean(ball.z)",
                "tfast=time_of_max(-ball.vz)", "drop=max(ball.z) - final(ball.z)",
                "scaled=final(ball.vz / T)", "moving=min(abs(ball.vz)) < 1e-300"});
  SweepRunner runner(spec);
  const double z0 = 7.5;
  const RunRecord r = runner.run(std::vector<double>{z0});
  ASSERT_EQ(r.status, RunStatus::Ok) << r.message;
  ASSERT_EQ(r.values.size(), 8u);
  // The integrator is exact for a quadratic (dop853 to round-off): 1e-12 of the scale.
  const double T = 1.0;
  EXPECT_NEAR(r.values[0], z0 - kG * T * T / 2, 1e-12 * z0);
  EXPECT_NEAR(r.values[1], z0, 1e-12 * z0);
  EXPECT_NEAR(r.values[2], z0 - kG * T * T / 2, 1e-12 * z0);
  // The mean over time of the continuous solution, z0 - g T^2 / 6: the five-point rule on each
  // step is exact for a parabola (rows h apart with the trapezoidal rule would fall short by
  // h^2 g / 12 = 8e-5).
  EXPECT_NEAR(r.values[3], z0 - kG * T * T / 6, 1e-12 * z0);
  EXPECT_DOUBLE_EQ(r.values[4], T);  // the speed is greatest at the last row
  EXPECT_NEAR(r.values[5], kG * T * T / 2, 1e-12 * z0);
  EXPECT_NEAR(r.values[6], -kG * T / T, 1e-12 * kG);
  EXPECT_EQ(r.values[7], 1.0);  // at rest at t = 0: |vz| = 0 exactly in the first row
  // E is conserved to the integration's error.
  EXPECT_LT(r.energy_drift, 1e-12);
}

// The reductions read the continuous solution, not the rows: rows 0.3 s apart (4 in the second)
// give the same values as rows 0.01 s apart.
TEST(SweepReductions, TheRowsDoNotChangeThem) {
  const std::vector<std::string> records = {"top=max(ball.z)",
                                            "low=min(ball.z)",
                                            "mean=mean(ball.z)",
                                            "fast=time_of_max(-ball.vz)",
                                            "half=first(ball.z < z0 - 2)",
                                            "n=count(ball.vz < -3)"};
  std::vector<std::vector<double>> values;
  for (const char* h : {"0.01", "0.3"}) {
    SweepSpec spec = spec_for(kFall, {"z0"}, records);
    spec.fixed = {{"h", h}};
    SweepRunner runner(spec);
    const RunRecord r = runner.run(std::vector<double>{7.5});
    ASSERT_EQ(r.status, RunStatus::Ok) << r.message;
    values.push_back(r.values);
  }
  for (std::size_t i = 0; i < records.size(); ++i) {
    EXPECT_DOUBLE_EQ(values[0][i], values[1][i]) << records[i];
  }
  // z0 - g t^2 / 2 = z0 - 2 at t = sqrt(4 / g); vz = -g t = -3 at t = 3 / g.
  EXPECT_NEAR(values[1][4], std::sqrt(4 / kG), 1e-12);
  EXPECT_EQ(values[1][5], 1.0);
}

// A run whose outcomes read no row (no final()) costs its steps, not a row per output_every: with
// rows asked 0.1 ms apart it makes one at each step's end (and the start), where E_drift is taken,
// and its values are the closed form's. Reading a row, the same run makes every one.
TEST(SweepReductions, ARunThatReadsNoRowMakesOneAtEachStepNotOnePerOutputEvery) {
  SweepSpec spec = spec_for(kFall, {"z0"}, {"low=min(ball.z)", "mean=mean(ball.z)"});
  spec.fixed = {{"h", "1e-4"}};
  SweepRunner runner(spec);
  const double z0 = 7.5, T = 1.0;
  const RunRecord r = runner.run(std::vector<double>{z0});
  ASSERT_EQ(r.status, RunStatus::Ok) << r.message;
  EXPECT_EQ(r.rows, r.steps + 1);
  EXPECT_LT(r.steps, 100);
  EXPECT_NEAR(r.values[0], z0 - kG * T * T / 2, 1e-12 * z0);
  EXPECT_NEAR(r.values[1], z0 - kG * T * T / 6, 1e-12 * z0);
  EXPECT_LT(r.energy_drift, 1e-12);
  SweepSpec rows = spec_for(kFall, {"z0"}, {"zf=final(ball.z)"});
  rows.fixed = {{"h", "1e-4"}};
  SweepRunner row_runner(rows);
  const RunRecord every = row_runner.run(std::vector<double>{z0});
  ASSERT_EQ(every.status, RunStatus::Ok) << every.message;
  EXPECT_EQ(every.rows, 10001);
  EXPECT_NEAR(every.values[0], z0 - kG * T * T / 2, 1e-12 * z0);
}

TEST(SweepReductions, EventsFirstTimeAndCountAgainstTheCratesSlipStop) {
  const std::string text =
      test::read_file(std::string(TUMBLE_SOURCE_DIR) + "/examples/box_slides_to_rest.yaml");
  const SweepSpec spec = spec_for(text, {"v0"},
                                  {"stop=first(floor.stops)", "stops=count(floor.stops)",
                                   "lifts=count(floor.lifts)", "never=first(floor.impact)"});
  SweepRunner runner(spec);
  const double mu = 0.3;
  for (const double v0 : {1.0, 3.0}) {
    const RunRecord r = runner.run(std::vector<double>{v0});
    ASSERT_EQ(r.status, RunStatus::Ok) << r.message;
    // t_stop = v0 / (mu g), located by the slip-stop event to the integrator's precision.
    EXPECT_NEAR(r.values[0], v0 / (mu * kG), 1e-9 * v0 / (mu * kG)) << v0;
    EXPECT_EQ(r.values[1], 1.0);
    EXPECT_EQ(r.values[2], 0.0);
    EXPECT_TRUE(std::isnan(r.values[3]));  // no impact: first() of nothing is nan
  }
}

TEST(SweepReductions, MalformedOrUnknownIsRefusedWithTheText) {
  EXPECT_THROW(parse_record("x=final(ball.z"), std::invalid_argument);
  EXPECT_THROW(parse_record("x=max()"), std::invalid_argument);
  EXPECT_THROW(parse_record("x=ball.z"), std::invalid_argument);  // no reduction
  EXPECT_THROW(parse_record("=max(ball.z)"), std::invalid_argument);
  EXPECT_THROW(parse_record("1x=max(ball.z)"), std::invalid_argument);
  const Outcome o = parse_outcome("c", "max(abs(a.b)) > 1e-5 && count(f.slides) == 0");
  EXPECT_EQ(o.expression, "__r0 > 1e-5 && __r1 == 0");
  ASSERT_EQ(o.reductions.size(), 2u);
  EXPECT_EQ(o.reductions[0].argument, "abs(a.b)");
  EXPECT_EQ(o.reductions[1].kind, ReductionKind::Count);
  // A name that is no column, or an event the scenario cannot have, is refused when the run is
  // set up: the record's row says why (the command line refuses it before any run).
  const SweepSpec unknown = spec_for(kFall, {"z0"}, {"x=max(ball.zz)"});
  SweepRunner runner(unknown);
  const RunRecord r = runner.run(std::vector<double>{1.0});
  EXPECT_EQ(r.status, RunStatus::Invalid);
  EXPECT_NE(r.message.find("ball.zz"), std::string::npos) << r.message;
}

// What `tumble modes` says, read by a sweep with no integration: the top sleeping on its apex
// (modes_contact_test.cpp) with D = (I_a w)^2 - 4 I_t M g l. Below the critical spin (D < 0) its
// nutation grows at sqrt(-D) / (2 I_t); above it, it is stable, its slow precession at
// (I_a w - sqrt(D)) / (2 I_t) the lowest frequency. A modes.* name that is not one is refused, and
// a state that is not steady makes the run invalid, with the reason tumble modes gives.
TEST(SweepReductions, ModesOfEachRunAgainstTheSleepingTopsClosedForms) {
  const double r = 0.05, h = 0.04, M = 0.1, g = 9.81, l = 3 * h / 4;
  const double I_a = 3 * M * r * r / 10;
  const double I_t = 3 * M * r * r / 20 + 3 * M * h * h / 80 + M * l * l;
  SweepSpec spec = spec_for(
      test::read_file(test::example("modes/sleeping_top.yaml")), {"w"},
      {"growth=modes.growth_rate", "f=modes.frequency", "s=modes.stable", "u=modes.unstable"});
  SweepRunner runner(spec);
  for (const double w : {0.0, 40.0, 60.0, 100.0}) {
    const RunRecord rec = runner.run(std::vector<double>{w});
    ASSERT_EQ(rec.status, RunStatus::Ok) << rec.message;
    EXPECT_EQ(rec.steps, 0);  // no integration
    const double D = std::pow(I_a * w, 2) - 4 * I_t * M * g * l;
    if (D < 0) {
      const double growth = std::sqrt(-D) / (2 * I_t);
      EXPECT_NEAR(rec.values[0], growth, 1e-9 * growth) << w;
      EXPECT_TRUE(std::isnan(rec.values[1])) << w;  // its only oscillation grows
      EXPECT_EQ(rec.values[2], 0.0);
      EXPECT_EQ(rec.values[3], 1.0);
    } else {
      const double slow = (I_a * w - std::sqrt(D)) / (2 * I_t);
      EXPECT_EQ(rec.values[0], 0.0) << w;
      EXPECT_NEAR(rec.values[1], slow, 1e-9 * slow) << w;
      EXPECT_EQ(rec.values[2], 1.0);
      EXPECT_EQ(rec.values[3], 0.0);
    }
  }
  EXPECT_THROW(parse_record("x=modes.stability"), std::invalid_argument);
  const SweepSpec falling = spec_for(kFall, {"z0"}, {"x=modes.stable"});
  SweepRunner fall(falling);
  const RunRecord rec = fall.run(std::vector<double>{1.0});
  EXPECT_EQ(rec.status, RunStatus::Invalid);
  EXPECT_NE(rec.message.find("tumble modes: the initial state is neither an equilibrium"),
            std::string::npos)
      << rec.message;
}

// The chapter's bat (equations.md, 6.7) struck at d below its knob by an impulse P: its angular
// impulse about O gives w = P d / I_O, its COM then moves at w L, and the knob's reaction impulse
// on the bat is M w L - P = P (M L d / I_O - 1), zero at the centre of percussion; the kinetic
// energy goes from 0 to (P d)^2 / (2 I_O). jump() reads them at the blow; a field or a jump the
// scenario does not have is refused with the text.
TEST(SweepReductions, AJumpsReactionImpulseAndEnergiesAgainstTheBatsClosedForms) {
  const double M = 0.9, length = 0.84, r = 0.03, L = length / 2, P = 1.5;
  const double I_O = M * (3 * r * r + length * length) / 12 + M * L * L;
  const SweepSpec spec =
      spec_for(test::read_file(test::example("bat_struck.yaml")), {"d"},
               {"J=jump(impulse.ball, knob.Fx)", "Jz=jump(impulse.ball, knob.Fz)",
                "before=jump(impulse.ball, KE_before)", "after=jump(impulse.ball, KE_after)"});
  SweepRunner runner(spec);
  for (const double d : {0.3, I_O / (M * L), 0.8}) {
    const RunRecord rec = runner.run(std::vector<double>{d});
    ASSERT_EQ(rec.status, RunStatus::Ok) << rec.message;
    EXPECT_NEAR(rec.values[0], P * (M * L * d / I_O - 1), 1e-12 * P) << d;
    EXPECT_NEAR(rec.values[1], 0.0, 1e-12 * P) << d;
    EXPECT_NEAR(rec.values[2], 0.0, 1e-12 * P * P / M) << d;
    EXPECT_NEAR(rec.values[3], P * P * d * d / (2 * I_O), 1e-12 * P * P / M) << d;
  }
  EXPECT_THROW(parse_record("x=jump(impulse.ball)"), std::invalid_argument);
  for (const char* refused : {"x=jump(impulse.bat, knob.Fx)", "x=jump(impulse.ball, knob.Fw)",
                              "x=jump(impulse.ball, elbow.Fx)", "x=jump(floor.rolls, KE_after)"}) {
    const SweepSpec bad_spec =
        spec_for(test::read_file(test::example("bat_struck.yaml")), {"d"}, {refused});
    SweepRunner bad(bad_spec);
    const RunRecord rec = bad.run(std::vector<double>{0.5});
    EXPECT_EQ(rec.status, RunStatus::Invalid) << refused;
    EXPECT_NE(rec.message.find("jump("), std::string::npos) << rec.message;
  }
}

// after(EVENT, X) reads X in the state just after EVENT's first occurrence, against three closed
// forms: the bat's COM after the blow moves at w L = P d L / I_O; the chapter's disk thrown with
// backspin keeps its angular momentum about the contact line (friction and the normal force act
// there), M R vx + I wy, so once its slip stops it rolls at vx = (2 v0 - R w0) / 3; a ball dropped
// from h leaves its first impact at vz = e sqrt(2 g h). An event the scenario cannot have, or no
// expression, is refused with the text.
// The bat hanging at rest, struck by P at d below the knob at t = 0.1 s: a condition the blow
// turns is at the blow's instant exactly, and the swing it starts, w0 = P d / I_O, rises to the
// angle where M g L (1 - cos theta) = I_O w0^2 / 2, read between the rows (1 ms apart here).
TEST(SweepReductions, AConditionAJumpTurnsIsAtItsInstantAndTheSwingPeaksBetweenRows) {
  const double M = 0.9, length = 0.84, r = 0.03, L = length / 2, P = 1.5, d = 0.5, g = 9.81;
  const double I_O = M * (3 * r * r + length * length) / 12 + M * L * L;
  const double w0 = P * d / I_O;
  const double theta_max = std::acos(1 - I_O * w0 * w0 / (2 * M * g * L));
  const SweepSpec spec = spec_for(test::read_file(test::example("bat_struck.yaml")), {"d"},
                                  {"hit=first(bat.speed > 1e-3)", "swing=max(abs(knob.angle))",
                                   "at=time_of_max(abs(knob.angle))"});
  SweepRunner runner(spec);
  const RunRecord rec = runner.run(std::vector<double>{d});
  ASSERT_EQ(rec.status, RunStatus::Ok) << rec.message;
  EXPECT_EQ(rec.values[0], 0.1);
  // rtol 1e-8 on the swing: the peak angle to 1e-7 (rows 1 ms apart alone: 2e-6 rad off).
  EXPECT_NEAR(rec.values[1], theta_max, 1e-7 * theta_max);
  EXPECT_GT(rec.values[2], 0.1);
}

// The bat whirling over its knob in the plane, its angle counted on past each turn: it first
// passes 20 rad (some three turns on) at t = integral of d(theta) / w(theta) from energy,
// w^2 = w0^2 - (2 M g L / I_O)(1 - cos theta), theta from hanging (the angle column starts at
// pi/2 there). Just over the top (w0 = 8.5 rad/s; 8.37 would stop there), its rate swings from
// 8.5 to 1.5 rad/s each turn: the angle where the condition turns must be counted on from the
// sample just before, not from one turns earlier (a rate's trapezoid over a few steps misses it
// by more than half a turn).
TEST(SweepReductions, AWhirlingPendulumsCountedAngleIsReadWhereItPassesAValue) {
  const double M = 0.9, length = 0.84, r = 0.03, L = length / 2, g = 9.81, w0 = 8.5;
  const double I_O = M * (3 * r * r + length * length) / 12 + M * L * L;
  const double theta_end = 20.0 - std::numbers::pi / 2;
  // Simpson's rule on a smooth integrand: its error falls as the step^4, far below 1e-12 here.
  const int n = 200000;
  const double h = theta_end / n;
  double sum = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double theta = i * h;
    const double f = 1.0 / std::sqrt(w0 * w0 - 2 * M * g * L / I_O * (1 - std::cos(theta)));
    sum += (i == 0 || i == n ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0)) * f;
  }
  const double t_passes = sum * h / 3;
  const char* const text = R"(tumble: 1
planar: true
parameters: {M: 0.9, length: 0.84, r: 0.03, L: length/2, g: 9.81, w0: 8.5}
gravity: [0, -g]
bodies:
  bat:
    shape: rod
    length: length
    mass: M
    inertia: [M*r^2/2, M*(3*r^2 + length^2)/12, M*(3*r^2 + length^2)/12]
    position: [0, -L]
    angle: 90 deg
    angular_velocity: w0
joints:
  knob: {type: hinge, body: bat, at: [0, 0]}
simulate: {duration: 6, integrator: dop853, rtol: 1e-11, atol: 1e-13, output_every: 0.5}
)";
  const SweepSpec spec = spec_for(text, {"w0"}, {"at=first(bat.angle > 20)"});
  SweepRunner runner(spec);
  const RunRecord rec = runner.run(std::vector<double>{w0});
  ASSERT_EQ(rec.status, RunStatus::Ok) << rec.message;
  // rtol 1e-11 over some 180 steps: the time to 1e-9 of itself.
  EXPECT_NEAR(rec.values[0], t_passes, 1e-9 * t_passes);
}

TEST(SweepReductions, AfterAnEventReadsTheStateItLeaves) {
  {
    const double M = 0.9, length = 0.84, r = 0.03, L = length / 2, P = 1.5;
    const double I_O = M * (3 * r * r + length * length) / 12 + M * L * L;
    const SweepSpec spec =
        spec_for(test::read_file(test::example("bat_struck.yaml")), {"d"},
                 {"v=after(impulse.ball, bat.speed)", "never=after(knob.lock, t)"});
    SweepRunner runner(spec);
    const RunRecord rec = runner.run(std::vector<double>{0.5});
    ASSERT_EQ(rec.status, RunStatus::Invalid) << "the bat has no lock: " << rec.message;
    EXPECT_NE(rec.message.find("after(knob.lock, t)"), std::string::npos) << rec.message;
    const SweepSpec good = spec_for(test::read_file(test::example("bat_struck.yaml")), {"d"},
                                    {"v=after(impulse.ball, bat.speed)"});
    SweepRunner bat(good);
    for (const double d : {0.3, 0.8}) {
      const RunRecord hit = bat.run(std::vector<double>{d});
      ASSERT_EQ(hit.status, RunStatus::Ok) << hit.message;
      // The jump is exact (one linear solve): round-off.
      EXPECT_NEAR(hit.values[0], P * d * L / I_O, 1e-12 * P / M) << d;
    }
  }
  {
    const double v0 = 2, R = 0.1, w0 = 60, rtol = 1e-10;
    const SweepSpec spec = spec_for(test::read_file(test::example("backspin_disk.yaml")), {"v0"},
                                    {"v=after(floor.rolls, disk.vx)", "t=first(floor.rolls)"});
    SweepRunner runner(spec);
    const RunRecord rec = runner.run(std::vector<double>{v0});
    ASSERT_EQ(rec.status, RunStatus::Ok) << rec.message;
    EXPECT_GT(rec.values[1], 1.0);  // not the start's "slides"
    // The slide's speeds are integrated to rtol and its end located to it: 10 rtol of v0.
    EXPECT_NEAR(rec.values[0], (2 * v0 - R * w0) / 3, 10 * rtol * v0);
  }
  {
    const double h = 1, e = 0.75, rtol = 1e-10;
    const SweepSpec spec = spec_for(test::read_file(test::example("bouncing_ball.yaml")), {"h"},
                                    {"up=after(floor.impact, ball.vz)"});
    SweepRunner runner(spec);
    const RunRecord rec = runner.run(std::vector<double>{h});
    ASSERT_EQ(rec.status, RunStatus::Ok) << rec.message;
    // The fall of the spinning ball is integrated, and its touchdown located, to rtol (events.csv's
    // approach speed is 1e-11 off sqrt(2 g h) in this example); the impact law is exact: 10 rtol.
    EXPECT_NEAR(rec.values[0], e * std::sqrt(2 * kG * h), 10 * rtol * std::sqrt(2 * kG * h));
  }
  EXPECT_THROW(parse_record("x=after(floor.rolls)"), std::invalid_argument);
}

TEST(SweepPoints, GridOrderEndsAndRandomDraws) {
  const std::vector<VaryRange> ranges = {parse_vary("a=0:1:3", true),
                                         parse_vary("b=30 deg:pi/2:2", true)};
  const auto grid = grid_points(ranges, 1000);
  ASSERT_EQ(grid.size(), 6u);
  // The first range varies slowest; the ends are exactly START and STOP.
  EXPECT_EQ(grid[0], (std::vector<double>{0.0, M_PI / 6}));
  EXPECT_EQ(grid[1], (std::vector<double>{0.0, M_PI / 2}));
  EXPECT_EQ(grid[2][0], 0.5);
  EXPECT_EQ(grid[5], (std::vector<double>{1.0, M_PI / 2}));
  EXPECT_THROW(grid_points(ranges, 5), std::invalid_argument);
  EXPECT_EQ(grid_points(std::vector<VaryRange>{parse_vary("a=2:2:1", true)}, 10)[0][0], 2.0);

  const std::vector<VaryRange> bounds = {parse_vary("a=-1:1", false), parse_vary("b=5:6", false)};
  const auto draws = random_points(bounds, 1000, 42);
  EXPECT_EQ(draws, random_points(bounds, 1000, 42));
  EXPECT_NE(draws, random_points(bounds, 1000, 43));
  double mean = 0.0;
  for (const auto& p : draws) {
    EXPECT_GE(p[0], -1.0);
    EXPECT_LT(p[0], 1.0);
    EXPECT_GE(p[1], 5.0);
    EXPECT_LT(p[1], 6.0);
    mean += p[0] / 1000.0;
  }
  // Uniform on [-1, 1): the mean of 1000 draws has standard deviation 1/sqrt(3000) = 0.018.
  EXPECT_LT(std::abs(mean), 5 * 0.0183);

  for (const char* bad : {"a=1:0", "a=1:1", "a", "a=1", "a=x:1"}) {
    EXPECT_THROW(parse_vary(bad, false), std::invalid_argument) << bad;
  }
  for (const char* bad : {"a=0:1:0", "a=0:1", "a=1:1:2", "a=0:1:2.5", "a=0:1:-3"}) {
    EXPECT_THROW(parse_vary(bad, true), std::invalid_argument) << bad;
  }
}

std::string csv_of(const SweepSpec& spec, const std::vector<std::vector<double>>& points,
                   int threads) {
  const std::vector<RunRecord> records = run_points(spec, points, threads);
  std::string csv = sweep_csv_header(spec);
  for (std::size_t i = 0; i < points.size(); ++i) {
    csv += sweep_csv_line(i, points[i], records[i], spec.outcomes.size());
  }
  return csv;
}

TEST(SweepThreads, SameBytesOnOneAndTwoThreads) {
  for (const char* stem : {"tumbling_prism", "backspin_disk"}) {
    const std::string text =
        test::read_file(std::string(TUMBLE_SOURCE_DIR) + "/examples/" + stem + ".yaml");
    const bool prism = std::string(stem) == "tumbling_prism";
    const SweepSpec spec =
        spec_for(text, {prism ? "a" : "v0"},
                 {prism ? "w3=min(prism.w3)" : "roll=first(floor.rolls)", "E=final(E)"});
    const auto points =
        grid_points(std::vector<VaryRange>{parse_vary(prism ? "a=3:5:6" : "v0=1:4:6", true)}, 100);
    const std::string one = csv_of(spec, points, 1);
    EXPECT_EQ(one, csv_of(spec, points, 2)) << stem;
    EXPECT_EQ(one, csv_of(spec, points, 5)) << stem;  // more threads than a core
    EXPECT_EQ(std::count(one.begin(), one.end(), '\n'), 7) << one;
    EXPECT_EQ(one.find("failed"), std::string::npos) << one;
  }
}

TEST(SweepRows, AFailedOrInvalidRunIsARowAndTheSweepGoesOn) {
  const char* const text = R"(tumble: 1
parameters: {m: 1, n: 100000}
bodies:
  ball: {shape: sphere, radius: 0.1, mass: m, position: [0, 0, 1], angular_velocity: [0, 0, 1]}
gravity: [0, 0, -9.81]
simulate: {duration: 1, integrator: dopri5, max_steps: n, output_every: 0.5}
)";
  const SweepSpec spec = spec_for(text, {"m", "n"}, {"z=final(ball.z)"});
  const std::vector<std::vector<double>> points = {{1.0, 100000.0}, {-1.0, 100000.0}, {1.0, 1.0}};
  const std::vector<RunRecord> records = run_points(spec, points, 2);
  EXPECT_EQ(records[0].status, RunStatus::Ok);
  EXPECT_NEAR(records[0].values[0], 1.0 - kG / 2, 1e-9);
  EXPECT_EQ(records[1].status, RunStatus::Invalid);
  EXPECT_NE(records[1].message.find("sweep_test.yaml:4:"), std::string::npos)
      << records[1].message;  // located, as tumble run would say it
  EXPECT_EQ(records[2].status, RunStatus::Failed);
  EXPECT_NE(records[2].message.find("max_steps"), std::string::npos) << records[2].message;
  const std::string line = sweep_csv_line(1, points[1], records[1], 1);
  EXPECT_EQ(line.substr(0, 18), "1,-1,100000,invali");
  EXPECT_NE(line.find(",,\""), std::string::npos) << line;  // an empty outcome, then why
}

}  // namespace
}  // namespace tumble

namespace tumble {
namespace {

// first(CONDITION): the prism's first flip, the body-frame spin about k changing sign, located
// between rows 0.01 s apart by the crossing of prism.w3 - 0. omega_3 is odd about its zero (a
// Jacobi elliptic function there), so a straight line through the rows either side errs by
// O(h^3 omega_3''' / omega_3') ~ 1e-7 s at most, against the 40-digit reference's 9.6640948340752.
// Each decade less tilt adds ln(10) / lambda, lambda = Omega sqrt((I_k - I_i)(I_j - I_k) /
// (I_i I_j)) = 0.6 rad/s, to 1e-12 of it (the departure from the linearised growth is of order
// tilt^2).
TEST(SweepReductions, PrismFirstFlipTimeAgainstTheReferenceAndTheGrowthRate) {
  const std::string text =
      test::read_file(std::string(TUMBLE_SOURCE_DIR) + "/examples/sweeps/prism_flip_time.yaml");
  const SweepSpec spec =
      spec_for(text, {"decades"}, {"flip=first(prism.w3 < 0)", "flips=count(prism.w3 < 0)"});
  const std::vector<std::vector<double>> points = {{2.0}, {6.0}, {8.0}};
  const std::vector<RunRecord> r = run_points(spec, points, 2);
  for (const RunRecord& record : r) ASSERT_EQ(record.status, RunStatus::Ok) << record.message;
  // Located on the continuous solution, as the scenario's event `prism.w3 < 0` is: to the
  // reference's 9.664094834075236 s within the integration's 1e-9 s (UserEvents.
  // ThePrismsFlipAtTheReferencesTime); rows 0.01 s apart would give it only to 1e-7 s.
  EXPECT_NEAR(r[0].values[0], 9.664094834075236, 1e-9);
  EXPECT_EQ(r[0].values[1], 2.0);  // it flips back at 9.664 + 2 K / lambda = 36.2 s, and again
  EXPECT_EQ(r[2].values[1], 1.0);  // by 60 s only once
  const double lambda = std::sqrt((17.0 - 5.0) * (20.0 - 17.0) / (5.0 * 20.0));
  EXPECT_NEAR((r[2].values[0] - r[1].values[0]) / 2.0, std::log(10.0) / lambda,
              1e-6 * std::log(10.0) / lambda);
}

}  // namespace
}  // namespace tumble

namespace tumble {
namespace {

// Runs whose varied parameters reach only the bodies' initial velocities share one model and
// compute only y0 (VelocityOnlyRuns): their rows are the same bytes as runs that each read the
// document and build their own model, including runs that are invalid at their values, and a
// parameter that reaches the model (a size, a mass, a duration) is not shared.
std::string csv_of_runner(const SweepSpec& spec, const std::vector<std::vector<double>>& points,
                          bool* shared = nullptr) {
  SweepRunner runner(spec);
  std::string csv = sweep_csv_header(spec);
  for (std::size_t i = 0; i < points.size(); ++i) {
    csv += sweep_csv_line(i, points[i], runner.run(points[i]), spec.outcomes.size());
  }
  if (shared != nullptr) *shared = runner.shares_model();
  return csv;
}

void expect_shared_equals_unshared(SweepSpec spec, const std::vector<std::vector<double>>& points,
                                   bool shared_expected) {
  bool shared = false;
  spec.share_models = true;
  const std::string with_sharing = csv_of_runner(spec, points, &shared);
  EXPECT_EQ(shared, shared_expected) << spec.varied.front();
  spec.share_models = false;
  const std::string without = csv_of_runner(spec, points);
  EXPECT_EQ(with_sharing, without);
  EXPECT_EQ(without.find("failed"), std::string::npos) << without;
}

TEST(SweepSharedModel, VelocityOnlyRunsAreTheBytesOfRunsThatReadTheirOwn) {
  const std::string disk =
      test::read_file(std::string(TUMBLE_SOURCE_DIR) + "/examples/backspin_disk.yaml");
  const std::vector<std::vector<double>> speeds = {{1.5, 60.0}, {2.0, 30.0}, {2.5, 80.0}};
  expect_shared_equals_unshared(
      spec_for(disk, {"v0", "w0"}, {"roll=first(floor.rolls)", "v=final(disk.vx)"}), speeds, true);
  // The floor's friction reaches the contact, not the state.
  expect_shared_equals_unshared(spec_for(disk, {"mu"}, {"roll=first(floor.rolls)"}),
                                {{0.1}, {0.2}, {0.3}}, false);

  const std::string prism =
      test::read_file(std::string(TUMBLE_SOURCE_DIR) + "/examples/sweeps/prism_flip_time.yaml");
  SweepSpec tilt = spec_for(prism, {"decades"}, {"flip=first(prism.w3 < 0)", "w=min(prism.w3)"});
  tilt.fixed = {{"a", "4"}};
  expect_shared_equals_unshared(tilt, {{2.0}, {3.5}, {5.0}}, true);
  expect_shared_equals_unshared(spec_for(prism, {"a"}, {"w=min(prism.w3)"}), {{3.9}, {4.1}}, false);
  // A planar statement's spin is one number, about z.
  const std::string planar =
      test::read_file(std::string(TUMBLE_SOURCE_DIR) + "/examples/planar/backspin_disk.yaml");
  expect_shared_equals_unshared(
      spec_for(planar, {"v0", "w0"}, {"roll=first(floor.rolls)", "turned=final(disk.angle)"}),
      speeds, true);
}

// Parameters defined from a varied one (in the file, or by --set) follow it; an initial state the
// checks refuse, or an expression that fails at some values, gives the same located message.
TEST(SweepSharedModel, DerivedParametersAndInvalidRunsAreTheSameBytes) {
  const char* const text = R"(tumble: 1
parameters: {w0: 2, spin: 3 * w0, lean: 0, v: 1}
gravity: [0, 0, 0]
bodies:
  top:
    shape: cylinder
    radius: 0.2
    length: 0.1
    mass: 1
    velocity: [sqrt(v), 0, 0]
    angular_velocity: [lean, 0.5 * w0, spin^3]
simulate: {duration: 0.5, integrator: dop853, rtol: 1e-10, atol: 1e-12, output_every: 0.05}
)";
  SweepSpec spec = spec_for(text, {"w0", "v"}, {"w=final(top.w3)", "x=final(top.x)"});
  spec.fixed = {{"lean", "w0 / 10"}};
  expect_shared_equals_unshared(spec, {{1.0, 1.0}, {-2.0, 4.0}, {0.5, 0.25}}, true);
  // sqrt(-1) in the middle run: its read says where; the runs either side share the model.
  SweepSpec bad = spec;
  bool shared = false;
  const std::string with_sharing =
      csv_of_runner(bad, {{1.0, 1.0}, {1.0, -1.0}, {2.0, 1.0}}, &shared);
  EXPECT_TRUE(shared);
  bad.share_models = false;
  EXPECT_EQ(with_sharing, csv_of_runner(bad, {{1.0, 1.0}, {1.0, -1.0}, {2.0, 1.0}}));
  EXPECT_NE(with_sharing.find("sweep_test.yaml:10:"), std::string::npos) << with_sharing;
  // A spin whose kinetic energy overflows is refused by the initial state's checks, at the body.
  const std::string overflow = csv_of_runner(spec, {{1.0, 1.0}, {1e90, 1.0}});
  spec.share_models = false;
  EXPECT_EQ(overflow, csv_of_runner(spec, {{1.0, 1.0}, {1e90, 1.0}}));
  EXPECT_NE(overflow.find("invalid"), std::string::npos) << overflow;
  EXPECT_NE(overflow.find("overflows"), std::string::npos) << overflow;
}

}  // namespace
}  // namespace tumble
