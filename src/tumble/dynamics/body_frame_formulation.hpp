#pragma once
#include <vector>

#include "tumble/dynamics/formulation.hpp"

namespace tumble {

// The production formulation. Per body, 13 components:
//   y = [ r_G (3, world) | q_WB (4: w, x, y, z) | v_G (3, world) | omega_B (3, body axes) ]
// with
//   dr_G/dt = v_G,                 dq_WB/dt = q_WB (x) (0, omega_B) / 2,
//   M dv_G/dt = M g + F_W,         I_G_B domega_B/dt = M_G_B - omega_B x I_G_B omega_B,
// Euler's equations in principal-or-not body axes, where I_G_B is constant, so no tensor is
// rotated or inverted during a step (the chapter's world-frame form rotates and inverts I every
// evaluation). M_G_B = R_WB^T M_G_W is the moment about the COM in body axes.
class BodyFrameFormulation final : public Formulation {
 public:
  static constexpr Eigen::Index kPerBody = 13;
  static constexpr Eigen::Index kPosition = 0, kQuaternion = 3, kVelocity = 7, kOmegaBody = 10;

  explicit BodyFrameFormulation(std::shared_ptr<const Model> model);
  explicit BodyFrameFormulation(Model model)
      : BodyFrameFormulation(std::make_shared<const Model>(std::move(model))) {}
  std::unique_ptr<Formulation> new_run() const override {
    return std::make_unique<BodyFrameFormulation>(shared_model_);
  }

  std::string_view name() const override { return "body"; }
  Eigen::Index dimension() const override;
  void derivative(double t, const VecX& y, VecX& dydt) const override;
  std::span<const Eigen::Index> unit_quaternion_offsets() const override {
    return quaternion_offsets_;
  }
  void pack(std::span<const BodyState> states, VecX& y) const override;
  BodyState unpack(const VecX& y, std::size_t body) const override;

 private:
  std::vector<Eigen::Index> quaternion_offsets_;
};

}  // namespace tumble
