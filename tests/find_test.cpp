// tumble find reproduces the chapter's critical values (equations.md, 6.8): the Cubli's wheel
// speed, the critical friction of a rolling sphere, cylinder and ring, and the mast's spring,
// each to 1e-6 of the closed form or better; a maximum read between the rows; and it refuses a
// range whose ends agree.
#include <gtest/gtest.h>

#include <cmath>

#include <fmt/format.h>

#include "test_files.hpp"
#include "tumble/scenario/scenario_document.hpp"
#include "tumble/sweep/find.hpp"

namespace tumble {
namespace {

SweepSpec find_spec(const std::string& example, std::vector<ParameterOverride> fixed,
                    const std::string& parameter, const std::string& condition) {
  SweepSpec spec;
  spec.path = std::string(TUMBLE_SOURCE_DIR) + "/examples/" + example;
  spec.text = read_scenario_file(spec.path);
  spec.fixed = std::move(fixed);
  spec.varied = {parameter};
  spec.outcomes = {parse_outcome("condition", condition)};
  return spec;
}

double middle(const FindResult& found) {
  return found.lo + 0.5 * (found.hi - found.lo);
}

TEST(FindCritical, CubliWheelSpeed) {
  // w0_crit = sqrt((sqrt(2) - 1) (M + m) g L I_total) / (m R^2), I_total about the corner with
  // the wheel locked (equations.md, 6), for the example's values.
  const double M = 0.8, m = 0.3, L = 0.15, R = 0.06, g = 9.81;
  const double I_total = M * L * L / 3 + (M + m) * L * L / 2 + m * R * R;
  const double w0_crit = std::sqrt((std::sqrt(2.0) - 1) * (M + m) * g * L * I_total) / (m * R * R);
  // The brake locks at 1 ns: gravity takes about 7e-9 of the angular momentum before it (the
  // example's 1 ms takes 0.7%). The frame passes upright where the corner hinge's angle passes
  // pi/4 (it turns about -y to rise); one that falls back never reaches it.
  const SweepSpec spec =
      find_spec("cubli.yaml", {{"t_lock", "1e-9"}}, "w0", "min(corner.angle) < -pi/4");
  const FindResult found = find_change(spec, 0.9 * w0_crit, 1.1 * w0_crit, 1e-8 * w0_crit);
  EXPECT_FALSE(found.at_lo);
  EXPECT_TRUE(found.at_hi);
  EXPECT_LE(found.hi - found.lo, 1e-8 * w0_crit);
  EXPECT_NEAR(middle(found), w0_crit, 1e-6 * w0_crit);
  EXPECT_LT(found.runs, 40);
}

// mu_crit = tan(theta) I_G / (I_G + M R^2): 2/7, 1/3, 1/2 of tan(theta) (equations.md, 2). Below
// it the body slides from the start.
void expect_critical_friction(const char* contact, double fraction) {
  const double mu_crit = fraction * std::tan(M_PI / 6);
  const SweepSpec spec = find_spec("sweeps/ramp_critical_friction.yaml", {}, "mu",
                                   std::string("count(") + contact + ".slides) > 0");
  const FindResult found = find_change(spec, 0.05, 0.5, 5e-7 * mu_crit);
  EXPECT_TRUE(found.at_lo) << contact;
  EXPECT_FALSE(found.at_hi) << contact;
  EXPECT_NEAR(middle(found), mu_crit, 1e-6 * mu_crit) << contact;
}

TEST(FindCritical, RollingSphereFriction) {
  expect_critical_friction("ramp_sphere", 2.0 / 7);
}
TEST(FindCritical, RollingCylinderFriction) {
  expect_critical_friction("ramp_cylinder", 1.0 / 3);
}
TEST(FindCritical, RollingRingFriction) {
  expect_critical_friction("ramp_ring", 1.0 / 2);
}

TEST(FindCritical, MastSpring) {
  // Upright is stable only for k > M g L / 2 (equations.md, 3).
  const double k_crit = 3.0 * 9.81 * 2.0 / 2;
  const SweepSpec spec =
      find_spec("sweeps/mast_critical_spring.yaml", {}, "k", "max(abs(base.angle)) > theta_seen");
  const FindResult found = find_change(spec, 20.0, 40.0, 1e-7 * k_crit);
  EXPECT_TRUE(found.at_lo);
  EXPECT_FALSE(found.at_hi);
  EXPECT_NEAR(middle(found), k_crit, 1e-6 * k_crit);
}

// The same spring by what tumble modes says, with no nudge and no integration: upright is
// stable for k > M g L / 2, marginal at it (nothing restores the angle), unstable below.
TEST(FindByModes, MastSpringWhereItsModesTurnStable) {
  const double k_crit = 3.0 * 9.81 * 2.0 / 2;
  const SweepSpec spec = find_spec("modes/inverted_mast.yaml", {}, "k", "modes.stable");
  const FindResult found = find_change(spec, 20.0, 40.0, 1e-9 * k_crit);
  EXPECT_FALSE(found.at_lo);
  EXPECT_TRUE(found.at_hi);
  EXPECT_NEAR(middle(found), k_crit, 1e-9 * k_crit);
}

// The bat's centre of percussion, I_O / (M L), where the knob's reaction impulse at the blow
// changes sign (it is P (M L d / I_O - 1), linear in d): from the jump's numbers, exact whatever
// the rows (0.01 s apart here).
TEST(FindByJump, TheBatsCentreOfPercussionWhereTheKnobFeelsNoImpulse) {
  const double M = 0.9, length = 0.84, r = 0.03, L = length / 2;
  const double d_star = (M * (3 * r * r + length * length) / 12 + M * L * L) / (M * L);
  SweepSpec spec = find_spec("bat_struck.yaml", {}, "d", "jump(impulse.ball, knob.Fx) > 0");
  const std::string rows = "output_every: 0.001";
  spec.text.replace(spec.text.find(rows), rows.size(), "output_every: 0.01");
  const FindResult found = find_change(spec, 0.4, 0.7, 1e-10 * d_star);
  EXPECT_FALSE(found.at_lo);
  EXPECT_TRUE(found.at_hi);
  EXPECT_NEAR(middle(found), d_star, 1e-9 * d_star);
}

// A compound pendulum (the chapter's bat on its pivot) released at rest from theta0 pulls on the
// pivot hardest at the bottom of its swing: there its COM, L below the pivot, turns at w with
// w^2 = 2 M g L (1 - cos theta0) / I_O (energy) and no tangential acceleration, so the pivot's
// reaction is knob.Fz = M g + M L w^2. find brackets the release angle at which that pull reaches
// F on the continuous solution, not the rows: the same angle with rows 1 ms apart, 1 us apart,
// and 0.1 s apart (four rows, none near the bottom at 0.376 s), to the closed form.
const char* const kPendulumPull = R"yaml(tumble: 1
parameters: {M: 0.9, length: 0.84, r: 0.03, L: length/2, theta0: 0.3, g: 9.81, h: 0.001}
gravity: [0, 0, -g]
bodies:
  bat:
    shape: cylinder
    radius: r
    length: length
    mass: M
    position: ["-L*sin(theta0)", 0, "-L*cos(theta0)"]
    orientation: {axis: [0, 1, 0], angle: theta0}
joints:
  knob: {type: hinge, body: bat, at: [0, 0, 0], axis: [0, 1, 0]}
simulate: {duration: 0.4, integrator: dopri5, rtol: 1e-12, atol: 1e-14, output_every: h}
)yaml";

TEST(FindOnTheSolution, ThePendulumsPullAtTheBottomWhateverTheRows) {
  const double M = 0.9, length = 0.84, r = 0.03, L = length / 2, g = 9.81;
  const double I_O = M * (3 * r * r + length * length) / 12 + M * L * L;
  const double theta_star = 0.3;
  const double F = M * g + M * L * 2 * M * g * L * (1 - std::cos(theta_star)) / I_O;
  std::vector<double> found_at;
  for (const char* h : {"0.001", "1e-6", "0.1"}) {
    SweepSpec spec;
    spec.text = kPendulumPull;
    spec.path = "pendulum_pull.yaml";
    spec.fixed = {{"h", h}};
    spec.varied = {"theta0"};
    spec.outcomes = {parse_outcome("condition", fmt::format("max(knob.Fz) > {:.17g}", F))};
    const FindResult found = find_change(spec, 0.29, 0.31, 3e-10 * theta_star);
    EXPECT_FALSE(found.at_lo) << h;
    EXPECT_TRUE(found.at_hi) << h;
    // rtol 1e-12 gives w^2 to about 1e-12, which moves the angle by 1e-12 / (d ln(F - M g) /
    // d theta0) ~ 1e-13: the bracket's width sets the bound.
    EXPECT_NEAR(middle(found), theta_star, 1e-9 * theta_star) << h;
    found_at.push_back(middle(found));
  }
  EXPECT_NEAR(found_at[1], found_at[0], 1e-9 * theta_star);
  EXPECT_NEAR(found_at[2], found_at[0], 1e-9 * theta_star);
}

TEST(FindCritical, RefusesARangeWhoseEndsAgree) {
  const SweepSpec spec =
      find_spec("sweeps/mast_critical_spring.yaml", {}, "k", "max(abs(base.angle)) > theta_seen");
  try {
    find_change(spec, 31.0, 40.0, 1e-6);
    FAIL() << "no error";
  } catch (const FindError& e) {
    EXPECT_TRUE(e.same_at_both_ends());
    EXPECT_NE(std::string(e.what()).find("false at both ends"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tumble
