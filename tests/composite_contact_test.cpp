// A composite body touching with its parts (`part:`), against closed forms:
//  - a hammer (a rod and a sphere, parts of one body) on a hinge, turning at w0 with no gravity,
//    strikes a frictionless anvil with its head: the head's centre is L from the hinge, so it
//    touches where it has turned by theta = asin(h / L) (h the anvil's depth below the head's
//    lowest point at the start), at t = theta / w0; the joint leaves one freedom, so the impact
//    reverses the rate times e (w = -e w0 after it, exactly: no moment acts before or after) and
//    takes (1 - e^2) of the kinetic energy;
//  - a block of a turned box and a sphere above it rests on its box's face: the floor carries the
//    whole weight, M g, and nothing moves. The box's corners are the part's, turned by the part's
//    orientation and placed about the body's COM: were they not turned, the block would start a
//    twentieth of a metre above the floor and fall;
//  - a block of a turned tetrahedron (a mesh part) and a sphere rests on the tetrahedron's face,
//    placed and turned as a box part's corners are.
//  - a wheelset (two disk parts on a rod, their axes turned across the body) rolls down a ramp on
//    both wheels at a = g sin(alpha) M / (M + I_a / R^2), I_a = 2 (m R^2 / 2) its moment about
//    the axle (the rod's is none): energy, or Newton-Euler along the ramp with the friction that
//    spins the wheels up;
//  - a round part turned in its body moves as the same shape alone: the spinning cone of
//    examples/top_lands_on_its_side.yaml restated as a composite's one part (its axes the
//    example's turn, the body's the world's) lands on its side, pivots and rolls through the same
//    eleven events, each within 1e-9 s of the example's, every row within 1e-8 m and m/s (the
//    two integrate different coordinates: round-off and the steps apart, at rtol 1e-10);
//  - `tumble modes` on a disk rolling upright as a composite's part, placed off the body's frame
//    and turned in it: its wobble at the closed form's frequency (modes_contact_test.cpp's
//    formula), to 1e-9.
//  - a ball striking one of a free dumbbell's two ball parts takes the impulse's closed form
//    (below), each of the dumbbell's balls a contact of its own with the ball.
// And the reader: without `part:` each part that can touch is a contact of its own, NAME_PART;
// `part:` names one or lists several; a part named twice, an empty list, a part that cannot (a
// rod), a part it lacks, and `part:` on a body of one shape are refused at the key.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "modes_checks.hpp"
#include "scenario_run.hpp"
#include "test_constants.hpp"
#include "test_files.hpp"
#include "tumble/scenario/scenario_document.hpp"

namespace tumble {
namespace {

std::string hammer(double e) {
  return fmt::format(R"(tumble: 1
parameters: {{L: 0.6, r: 0.05, w0: 2, rest: {}, h: 0.3}}
gravity: [0, 0, 0]
bodies:
  hammer:
    parts:
      - {{name: handle, shape: rod, length: L, mass: 0.3, position: [L/2, 0, 0]}}
      - {{name: head, shape: sphere, radius: r, mass: 1, position: [L, 0, 0]}}
    position: [0, 0, 0]
    angular_velocity: [0, w0, 0]
joints:
  pivot: {{type: hinge, body: hammer, at: [0, 0, 0], axis: [0, 1, 0]}}
contacts:
  - {{name: anvil, type: plane, body: hammer, part: head,
     plane: {{point: [0, 0, -r - h], normal: [0, 0, 1]}}, friction: 0, restitution: rest}}
simulate: {{duration: 0.6, integrator: dop853, rtol: 1e-12, atol: 1e-14, output_every: 0.01}}
)",
                     e);
}

// A block of two parts, `base` (named base) touching the floor, the body's frame `z` up.
std::string block_on_the_floor(const std::string& base, const std::string& knob, double z) {
  return fmt::format(R"(tumble: 1
gravity: [0, 0, -{}]
bodies:
  block:
    parts:
      - {}
      - {}
    position: [0, 0, {}]
contacts:
  - {{name: floor, type: plane, body: block, part: base,
     plane: {{point: [0, 0, 0], normal: [0, 0, 1]}}, friction: 0.5}}
simulate: {{duration: 1, integrator: dop853, rtol: 1e-12, atol: 1e-14, output_every: 0.05}}
)",
                     test::kG, base, knob, z);
}

// A body of mass M at rest on its first contact: sticking, the floor carrying M g, nothing moving.
void expect_resting_on_the_floor(const test::ScenarioRun& run, double M) {
  const Vec3 r0 = run.rows.front().states[0].r_G;
  for (const test::Row& row : run.rows) {
    EXPECT_EQ(row.extras.contacts[0].mode, 2) << "t " << row.t;
    EXPECT_NEAR(row.extras.contacts[0].normal_force, M * test::kG, 1e-12 * M * test::kG)
        << "t " << row.t;
    EXPECT_NEAR((row.states[0].r_G - r0).norm(), 0.0, 1e-12) << "t " << row.t;
  }
}

TEST(CompositeContact, AHammersHeadStrikesAnAnvilAndReboundsAtEOfItsRate) {
  const double L = 0.6, h = 0.3, w0 = 2.0;
  const double t_strike = std::asin(h / L) / w0;
  for (const double e : {0.3, 0.5, 1.0}) {
    const test::ScenarioRun run = test::run_inline_scenario(hammer(e), "hammer");
    ASSERT_EQ(run.contact_events.size(), 1u) << "e " << e;
    EXPECT_EQ(run.contact_events[0].what.rfind("impact", 0), 0u) << run.contact_events[0].what;
    EXPECT_NEAR(run.contact_events[0].t, t_strike, 1e-12) << "e " << e;
    const double KE0 = run.rows.front().quantities.total_energy;
    for (const test::Row& row : run.rows) {
      const double w = row.states[0].omega_W.y();
      if (row.t < t_strike) {
        EXPECT_NEAR(w, w0, 1e-12 * w0) << "e " << e << ", t " << row.t;
      } else {
        EXPECT_NEAR(w, -e * w0, 1e-12 * w0) << "e " << e << ", t " << row.t;
        EXPECT_NEAR(row.quantities.total_energy, e * e * KE0, 1e-12 * KE0) << "e " << e;
      }
    }
  }
}

TEST(CompositeContact, ABlockRestsOnItsTurnedBoxPartWithTheFloorCarryingItsWeight) {
  // 0.4 x 0.2 x 0.1 turned a quarter about x: 0.2 high, its bottom face 0.1 below its centre.
  const test::ScenarioRun run = test::run_inline_scenario(
      block_on_the_floor("{name: base, shape: box, size: [0.4, 0.2, 0.1], mass: 2, "
                         "position: [0, 0, 0.1], orientation: {axis: [1, 0, 0], angle: 90 deg}}",
                         "{name: knob, shape: sphere, radius: 0.05, mass: 1, "
                         "position: [0.1, 0, 0.3]}",
                         0.0),
      "block");
  expect_resting_on_the_floor(run, 3.0);
}

TEST(CompositeContact, ABlockRestsOnItsTurnedMeshPartWithTheFloorCarryingItsWeight) {
  // tests/data/meshes/tetrahedron.obj (legs 2, 3 and 1.5 along x, y and z from its right-angled
  // corner) as a part placed at its COM and turned a quarter turn about -y: its face on the
  // plane x = corner, 0.5 from the COM, comes down, and its vertices there lie at z = -0.5 in the
  // body, whose frame is placed 0.5 m up. Were its vertices not turned (its z face, 0.375 from the
  // COM, down) it would start 0.125 m above the floor; a sphere part above keeps the COM over the
  // face.
  const std::string tetrahedron = std::string(TUMBLE_TEST_DATA_DIR) + "/meshes/tetrahedron.obj";
  const test::ScenarioRun run = test::run_inline_scenario(
      block_on_the_floor("{name: base, shape: mesh, file: \"" + tetrahedron +
                             "\", mass: 2, position: [0, 0, 0], "
                             "orientation: {axis: [0, 1, 0], angle: -90 deg}}",
                         "{name: knob, shape: sphere, radius: 0.2, mass: 1, position: [0, 0, 0.8]}",
                         0.5),
      "mesh_block");
  EXPECT_NEAR(run.rows.front().states[0].r_G.z(), 0.5 + 1.0 * 0.8 / 3.0, 1e-15);
  expect_resting_on_the_floor(run, 3.0);
}

TEST(CompositeContact, AWheelsetOfTwoDiskPartsRollsDownARampAtTheClosedFormsAcceleration) {
  const double alpha = 15.0 * std::numbers::pi / 180.0, R = 0.1, b = 0.2, m = 0.5, m_axle = 0.3;
  const test::ScenarioRun run = test::run_inline_scenario(fmt::format(R"(tumble: 1
parameters: {{alpha: 15 deg, R: {}, b: {}, m: {}, ma: {}}}
gravity: [0, 0, -{}]
bodies:
  wheelset:
    parts:
      - {{name: left, shape: disk, radius: R, mass: m, position: [0, b, 0],
         orientation: {{axis: [1, 0, 0], angle: 90 deg}}}}
      - {{name: right, shape: disk, radius: R, mass: m, position: [0, -b, 0],
         orientation: {{axis: [1, 0, 0], angle: 90 deg}}}}
      - {{name: axle, shape: rod, length: 2*b, mass: ma, orientation: {{axis: [0, 0, 1], angle: 90 deg}}}}
    position: [R*sin(alpha), 0, R*cos(alpha)]
contacts:
  - {{name: left_rail, type: plane, body: wheelset, part: left, friction: 0.8,
     plane: {{point: [0, 0, 0], normal: [sin(alpha), 0, cos(alpha)]}}}}
  - {{name: right_rail, type: plane, body: wheelset, part: right, friction: 0.8,
     plane: {{point: [0, 0, 0], normal: [sin(alpha), 0, cos(alpha)]}}}}
simulate: {{duration: 1, integrator: dop853, rtol: 1e-12, atol: 1e-14, output_every: 0.01}}
)",
                                                                      R, b, m, m_axle, test::kG),
                                                          "wheelset");
  const double M = 2 * m + m_axle, I_axle = 2 * (m * R * R / 2);
  const double a = test::kG * std::sin(alpha) * M / (M + I_axle / (R * R));
  ASSERT_EQ(run.rows.size(), 101u);
  // Rolling on both rails: it turns about its axle (y) at v / R, and about nothing else.
  test::expect_rolls_down_from_rest(run, a, Vec3(std::cos(alpha), 0.0, -std::sin(alpha)),
                                    Vec3::UnitY(), R, M);
}

TEST(CompositeContact, ARoundPartTurnedInItsBodyMovesAsTheSameShapeAlone) {
  const std::string path = test::example("top_lands_on_its_side.yaml");
  std::string text = read_scenario_file(path);
  const std::string shape =
      "    shape: cone         # its axis, body z, from the base to the apex\n"
      "    radius: r\n"
      "    height: h\n"
      "    mass: M\n";
  const std::string turn = "    orientation: {axis: [1, 0, 0], angle: 180 deg}\n";
  text = test::replaced(text, shape,
                        "    parts:\n"
                        "      - {name: cone, shape: cone, radius: r, height: h, mass: M,\n"
                        "         orientation: {axis: [1, 0, 0], angle: 180 deg}}\n");
  text = test::replaced(text, turn, "");
  text = test::replaced(text, "    body: top\n", "    body: top\n    part: cone\n");
  const test::ScenarioRun alone = test::run_scenario(load_scenario(path, {}));
  const test::ScenarioRun part = test::run_scenario(load_scenario_text(text, path, {}));
  ASSERT_EQ(part.contact_events.size(), alone.contact_events.size());
  ASSERT_EQ(alone.contact_events.size(), 11u);
  for (std::size_t i = 0; i < alone.contact_events.size(); ++i) {
    EXPECT_EQ(part.contact_events[i].what, alone.contact_events[i].what) << i;
    EXPECT_NEAR(part.contact_events[i].t, alone.contact_events[i].t, 1e-9) << i;
  }
  ASSERT_EQ(part.rows.size(), alone.rows.size());
  for (std::size_t i = 0; i < alone.rows.size(); ++i) {
    const BodyState& a = alone.rows[i].states[0];
    const BodyState& p = part.rows[i].states[0];
    EXPECT_NEAR((p.r_G - a.r_G).norm(), 0.0, 1e-8) << "t " << alone.rows[i].t;
    EXPECT_NEAR((p.v_G - a.v_G).norm(), 0.0, 1e-8) << "t " << alone.rows[i].t;
    EXPECT_NEAR((p.omega_W - a.omega_W).norm(), 0.0, 1e-8) << "t " << alone.rows[i].t;
  }
}

TEST(CompositeContact, ADiskPartRollingUprightWobblesAtTheClosedFormsFrequency) {
  // examples/modes/rolling_disk.yaml's disk as a part away from its body's frame, turned in it.
  std::string text = read_scenario_file(test::example("modes/rolling_disk.yaml"));
  text = test::replaced(text,
                        "    shape: disk\n"
                        "    radius: r\n"
                        "    mass: M\n"
                        "    position: [0, 0, r]\n"
                        "    orientation: {axis: [1, 0, 0], angle: 90 deg}   # its axis (body z) "
                        "along -y\n",
                        "    parts:\n"
                        "      - {name: rim, shape: disk, radius: r, mass: M, position: [0.3, 0.2, "
                        "-0.1],\n"
                        "         orientation: {axis: [1, 0, 0], angle: 90 deg}}\n"
                        "    position: [-0.3, -0.2, r + 0.1]\n");
  text = test::replaced(text, "    body: wheel\n", "    body: wheel\n    part: rim\n");
  const double r = 0.3, M = 2.0, g = 9.81, Omega = 10.0;
  const double I_a = M * r * r / 2, I_d = M * r * r / 4;
  const double k = (I_a + M * r * r) * I_a * Omega * Omega / I_d - M * g * r;
  const double omega = std::sqrt(k / (I_d + M * r * r));
  const ScenarioModes modes =
      modes_of_scenario(load_scenario_text(text, test::example("modes/rolling_disk.yaml"), {}));
  ASSERT_FALSE(modes.analysis.modes.empty());
  const Mode& wobble = modes.analysis.modes.front();
  EXPECT_EQ(wobble.kind, Mode::Kind::Oscillating);
  test::expect_relative(wobble.natural_frequency, omega);
}

// A ball strikes one of a free dumbbell's two balls (sphere parts at x = +-d on a rod along x),
// head on across the bar, frictionless: each of the dumbbell's balls is a contact of its own with
// the ball (hit_a, hit_b), and the one struck takes the impulse J = (1 + e) u / (1/m + 1/M +
// d^2 / I), I about the dumbbell's COM across the bar (each ball's 2/5 m r^2 + m d^2, the rod's
// M_rod L^2 / 12), which turns it at J d / I; the other pair stays apart.
TEST(CompositeContact, ABallStrikesOneOfADumbbellsTwoBallsEachAContactOfItsOwn) {
  constexpr double m_end = 1, r_end = 0.1, d = 0.3, m_rod = 0.2, L = 0.4, m = 0.5, u = 2;
  constexpr double M = 2 * m_end + m_rod;
  const double I = 2 * (0.4 * m_end * r_end * r_end + m_end * d * d) + m_rod * L * L / 12;
  for (const double e : {1.0, 0.5}) {
    const test::ScenarioRun run = test::run_inline_scenario(fmt::format(R"yaml(tumble: 1
gravity: [0, 0, 0]
bodies:
  bell:
    parts:
      - {{name: a, shape: sphere, radius: 0.1, mass: 1, position: [-0.3, 0, 0]}}
      - {{name: b, shape: sphere, radius: 0.1, mass: 1, position: [0.3, 0, 0]}}
      - {{name: bar, shape: rod, length: 0.4, mass: 0.2}}
  ball: {{shape: sphere, radius: 0.05, mass: 0.5, position: [0.3, 0.5, 0], velocity: [0, -2, 0]}}
contacts:
  - {{name: hit, type: bodies, bodies: [ball, bell], friction: 0, restitution: {}}}
simulate: {{duration: 0.3, integrator: dop853, rtol: 1e-12, atol: 1e-14}}
)yaml",
                                                                        e),
                                                            "dumbbell");
    ASSERT_EQ(run.contacts.size(), 2u);
    EXPECT_EQ(run.contacts[0].name, "hit_a");
    EXPECT_EQ(run.contacts[1].name, "hit_b");
    ASSERT_EQ(run.contact_events.size(), 1u);
    const ContactEventRecord& strike = run.contact_events[0];
    EXPECT_EQ(strike.contact, 1u);
    // The gap 0.5 - 0.1 - 0.05 closed at u.
    EXPECT_NEAR(strike.t, 0.35 / u, 1e-12);
    const double J = (1 + e) * u / (1 / m + 1 / M + d * d / I);
    ASSERT_TRUE(strike.impact.has_value());
    EXPECT_NEAR((strike.impact->impulse_W - Vec3(0, J, 0)).norm(), 0.0, 1e-12 * m * u);
    const test::Row& last = run.rows.back();
    EXPECT_NEAR((last.states[1].v_G - Vec3(0, -u + J / m, 0)).norm(), 0.0, 1e-12 * u) << e;
    EXPECT_NEAR((last.states[0].v_G - Vec3(0, -J / M, 0)).norm(), 0.0, 1e-12 * u) << e;
    EXPECT_NEAR((last.states[0].omega_W - Vec3(0, 0, -J * d / I)).norm(), 0.0, 1e-12 * u / d) << e;
    if (e == 1.0) {
      EXPECT_NEAR(last.quantities.kinetic_energy, 0.5 * m * u * u, 1e-12 * m * u * u);
    }
  }
}

TEST(CompositeContact, TheReaderNamesTheTouchingPart) {
  const std::string head =
      "tumble: 1\n"
      "bodies:\n"
      "  bell:\n"
      "    parts:\n"
      "      - {name: a, shape: sphere, radius: 0.1, mass: 1, position: [-0.3, 0, 0]}\n"
      "      - {name: b, shape: sphere, radius: 0.1, mass: 1, position: [0.3, 0, 0]}\n"
      "      - {name: bar, shape: rod, length: 0.5, mass: 0.2}\n"
      "    position: [0, 0, 0.5]\n"
      "  ball: {shape: sphere, radius: 0.1, mass: 1, position: [2, 0, 0.5]}\n"
      "contacts:\n";
  const std::string plane = "plane: {point: [0, 0, 0], normal: [0, 0, 1]}, friction: 0.3}\n";
  const std::string simulate = "simulate: {duration: 0.1}\n";
  // Without `part:`, each part that can touch is a contact of its own, named by the contact and
  // the part; `part:` may list them.
  const std::string path = "bell.yaml";
  const Scenario every = load_scenario_text(
      head + "  - {name: floor, type: plane, body: bell, " + plane + simulate, path, {});
  ASSERT_EQ(every.contacts.size(), 2u);
  EXPECT_EQ(every.contacts[0].name, "floor_a");
  EXPECT_EQ(every.contacts[0].part, 0);
  EXPECT_EQ(every.contacts[1].name, "floor_b");
  EXPECT_EQ(every.contacts[1].part, 1);
  const Scenario listed = load_scenario_text(
      head + "  - {type: plane, body: bell, part: [b], " + plane + simulate, path, {});
  ASSERT_EQ(listed.contacts.size(), 1u);
  EXPECT_EQ(listed.contacts[0].name, "contact1");
  EXPECT_EQ(listed.contacts[0].part, 1);
  test::expect_error(head + "  - {type: plane, body: bell, part: [a, a], " + plane + simulate, 11,
                     41, "contacts[0].part[1]", "part 'a' named twice");
  test::expect_error(head + "  - {type: plane, body: bell, part: [], " + plane + simulate, 11, 37,
                     "contacts[0].part", "name at least one part");
  test::expect_error(head + "  - {name: floor, type: plane, body: bell, " + plane +
                         "  - {name: floor_a, type: plane, body: ball, " + plane + simulate,
                     12, 6, "contacts[1].name", "'floor_a' already names a contact");
  test::expect_error(head + "  - {type: plane, body: bell, part: c, " + plane + simulate, 11, 37,
                     "contacts[0].part", "body 'bell' has no part 'c'");
  test::expect_error(head + "  - {type: plane, body: bell, part: bar, " + plane + simulate, 11, 37,
                     "contacts[0].part", "part 'bar' of body 'bell' is a rod");
  test::expect_error(head + "  - {type: plane, body: ball, part: a, " + plane + simulate, 11, 37,
                     "contacts[0].part", "body 'ball' is one shape, not a composite");
}

}  // namespace
}  // namespace tumble
