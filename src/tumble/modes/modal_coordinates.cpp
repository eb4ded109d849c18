#include "tumble/modes/modal_coordinates.hpp"

#include "tumble/multibody/joints/joint_kind.hpp"

namespace tumble {

namespace {

void add(ModalLayout& layout, std::size_t k, const std::string& stem,
         std::initializer_list<const char*> suffixes, const char* unit, bool is_speed) {
  for (const char* suffix : suffixes) {
    layout.coordinates.push_back({stem + "." + suffix, unit, is_speed, k});
  }
}

// The name the scenario gives a tree joint: its joint's, or for a free joint its body's.
std::string joint_stem(const ArticulatedModel& model, const TreeJoint& joint) {
  if (joint.model_joint < 0) return model.model.bodies[joint.child].name;
  return model.model.joints[static_cast<std::size_t>(joint.model_joint)].name;
}

}  // namespace

ModalLayout make_modal_layout(const ArticulatedModel& model, double t0) {
  ModalLayout layout;
  const std::size_t n = model.tree.size();
  layout.position_offset.assign(n, -1);
  layout.speed_offset.assign(n, -1);
  layout.sign.assign(n, 1.0);
  for (bool speeds : {false, true}) {
    for (std::size_t k = 0; k < n; ++k) {
      const TreeJoint& joint = model.tree[k];
      if (model.prescribed(k, t0)) continue;
      const std::string stem = joint_stem(model, joint);
      const bool has_axis = joint.type == JointType::Hinge || joint.type == JointType::Prismatic;
      if (has_axis && joint.reversed) layout.sign[k] = -1.0;
      (speeds ? layout.speed_offset : layout.position_offset)[k] = layout.size();
      switch (joint.type) {
        case JointType::Hinge:
          add(layout, k, stem, {speeds ? "rate" : "angle"}, speeds ? "rad/s" : "rad", speeds);
          break;
        case JointType::Prismatic:
          add(layout, k, stem, {speeds ? "speed" : "travel"}, speeds ? "m/s" : "m", speeds);
          break;
        case JointType::Ball:
          if (speeds) {
            add(layout, k, stem, {"wx", "wy", "wz"}, "rad/s", true);
          } else {
            add(layout, k, stem, {"rx", "ry", "rz"}, "rad", false);
          }
          break;
        case JointType::Free:
          if (speeds) {
            add(layout, k, stem, {"vx", "vy", "vz"}, "m/s", true);
            add(layout, k, stem, {"wx", "wy", "wz"}, "rad/s", true);
          } else {
            add(layout, k, stem, {"x", "y", "z"}, "m", false);
            add(layout, k, stem, {"rx", "ry", "rz"}, "rad", false);
          }
          break;
        case JointType::Fixed:
          break;
      }
    }
    if (!speeds) layout.position_count = layout.size();
  }
  return layout;
}

VecX displace_positions(const ArticulatedModel& model, const ModalLayout& layout, const VecX& y0,
                        const VecX& z) {
  VecX y = y0;
  for (std::size_t k = 0; k < model.tree.size(); ++k) {
    const Eigen::Index o = layout.position_offset[k];
    if (o < 0) continue;
    const TreeJoint& joint = model.tree[k];
    switch (joint.type) {
      case JointType::Hinge:
      case JointType::Prismatic:
        y(joint.q) += layout.sign[k] * z(o);
        break;
      case JointType::Ball:
        turn_quaternion(y, joint.q, z.segment<3>(o));
        break;
      case JointType::Free:
        y.segment<3>(joint.q) += z.segment<3>(o);
        turn_quaternion(y, joint.q + 3, z.segment<3>(o + 3));
        break;
      case JointType::Fixed:
        break;
    }
  }
  return y;
}

}  // namespace tumble
