// Directions (an orientation's axis, a joint's axis, a plane's normal, a quaternion) need not be
// unit length: they are normalised. One whose norm's square overflows ([0, 1e300, 1e300]) or
// underflows ([0, 0, 1e-310]) was read as non-finite or zero (a joint's axis of 1e300 made the
// run fail with "the state became non-finite", exit 4); each is now the unit vector it points
// along, exactly as its well-scaled twin.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "scenario_run.hpp"

namespace tumble {
namespace {

Scenario directions_scenario(const std::string& axis, const std::string& hinge,
                             const std::string& normal, const std::string& quaternion) {
  return test::load_inline_scenario(
      "tumble: 1\n"
      "bodies:\n"
      "  b: {shape: box, size: [1, 1, 1], mass: 1, position: [0, 0, 1],\n"
      "      orientation: {axis: " +
          axis +
          ", angle: 30 deg}}\n"
          "  c: {shape: box, size: [1, 1, 1], mass: 1, position: [2, 0, 1],\n"
          "      orientation: {quaternion: " +
          quaternion +
          "}}\n"
          "joints:\n"
          "  h: {type: hinge, bodies: [b, c], at: [1, 0, 1], axis: " +
          hinge +
          "}\n"
          "contacts:\n"
          "  - {name: floor, type: plane, body: b, plane: {point: [0, 0, 0], normal: " +
          normal +
          "}, friction: 0.5}\n"
          "simulate: {duration: 0.1}\n",
      "directions");
}

TEST(ScenarioDirections, HugeAndTinyDirectionsAreTheUnitVectorsTheyPointAlong) {
  const Scenario huge = directions_scenario("[0, 0, 1e300]", "[0, 1e300, 1e300]", "[0, 0, 1e-310]",
                                            "[1e300, 0, 0, 1e300]");
  const Scenario plain = directions_scenario("[0, 0, 1]", "[0, 1, 1]", "[0, 0, 1]", "[1, 0, 0, 1]");
  EXPECT_TRUE(huge.bodies[0].R_WB.isApprox(plain.bodies[0].R_WB, 1e-15));
  EXPECT_TRUE(huge.bodies[1].R_WB.isApprox(plain.bodies[1].R_WB, 1e-15));
  EXPECT_TRUE(huge.joints[0].axis_W.isApprox(Vec3(0, 1, 1) / std::sqrt(2.0), 1e-15));
  EXPECT_EQ(huge.contacts[0].plane_normal_W, Vec3(0, 0, 1));
  // The quaternion [1, 0, 0, 1], normalised: a quarter turn about z.
  EXPECT_NEAR(huge.bodies[1].R_WB(0, 1), -1.0, 1e-15);
  // And it runs: its rotations stay rotations.
  const test::ScenarioRun run = test::run_scenario(huge);
  EXPECT_LT(run.result.conservation.max_orthonormality_error, 1e-12);
}

}  // namespace
}  // namespace tumble
