#include "tumble/modes/modal_coordinates.hpp"

#include "tumble/multibody/joints/joint_kind.hpp"

namespace tumble {

namespace {

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
      if (has_axis(joint.type) && joint.reversed) layout.sign[k] = -1.0;
      (speeds ? layout.speed_offset : layout.position_offset)[k] = layout.size();
      const JointKind& kind = *joint.kind;
      for (const CoordinateName& name : speeds ? kind.modal_speeds() : kind.modal_positions()) {
        layout.coordinates.push_back(
            {stem + "." + std::string(name.suffix), std::string(name.unit), speeds, k});
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
    const auto count = static_cast<Eigen::Index>(joint.kind->modal_positions().size());
    joint.kind->displace_modal(joint, z.segment(o, count), layout.sign[k], y);
  }
  return y;
}

}  // namespace tumble
