#include "tumble/dynamics/joint_type.hpp"

namespace tumble {

std::string_view joint_type_name(JointType type) {
  switch (type) {
    case JointType::Free:
      return "free";
    case JointType::Ball:
      return "ball";
    case JointType::Hinge:
      return "hinge";
    case JointType::Prismatic:
      return "prismatic";
    case JointType::Fixed:
      return "fixed";
  }
  return "?";
}

}  // namespace tumble
