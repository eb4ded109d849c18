#include "tumble/multibody/loop_rows.hpp"

#include <stdexcept>

#include "tumble/contact/contact_feature.hpp"

namespace tumble {

LoopShape loop_shape_of(const JointModel& joint) {
  LoopShape shape;
  shape.body_a = joint.body_a;
  shape.body_b = joint.body_b;
  shape.p_AJ_A = joint.p_AJ_A;
  shape.p_BJ_B = joint.p_BJ_B;
  shape.R_AB0 = joint.R_AB0;
  shape.axis_B = joint.axis_B;
  shape.axis_A =
      joint.type == JointType::Universal ? joint.axis_A : Vec3(joint.R_AB0 * joint.axis_B);
  plane_basis(shape.axis_A, shape.across1_A, shape.across2_A);
  switch (joint.type) {
    case JointType::Ball:
      shape.turn_rows = 0;
      break;
    case JointType::Hinge:
      shape.turn_rows = 2;
      break;
    case JointType::Universal:
      shape.turn_rows = 1;
      break;
    case JointType::Cylindrical:
      shape.all_point_rows = false;
      shape.turn_rows = 2;
      break;
    case JointType::Prismatic:
      shape.all_point_rows = false;
      shape.turn_rows = 3;
      break;
    case JointType::Fixed:
      shape.turn_rows = 3;
      break;
    case JointType::Distance:
      shape.rod_length = joint.rod_length;
      break;
    case JointType::Free:
      throw std::logic_error("a free joint closes no loop");
  }
  return shape;
}

}  // namespace tumble
