#pragma once
#include "tumble/dynamics/formulation.hpp"

namespace tumble {

// The chapter's own formulation (section 6.8.2, example 2), extended with the COM motion. Per
// body, 18 components:
//   y = [ r_G (3) | v_G (3) | R_WB (9, row by row, as reshape(transpose(R))) | omega_W (3) ]
// with, all in the world frame,
//   I_G = R I_G_B R^T,  alpha = I_G^-1 (M_G - omega x I_G omega),  dR/dt = W R,  W = [omega]x.
// Nothing keeps R orthonormal: its drift is part of what this formulation teaches.
class TextbookFormulation final : public Formulation {
 public:
  static constexpr Eigen::Index kPerBody = 18;
  static constexpr Eigen::Index kPosition = 0, kVelocity = 3, kRotation = 6, kOmegaWorld = 15;

  explicit TextbookFormulation(std::shared_ptr<const Model> model)
      : Formulation(std::move(model)) {}
  explicit TextbookFormulation(Model model)
      : TextbookFormulation(std::make_shared<const Model>(std::move(model))) {}
  std::unique_ptr<Formulation> new_run() const override {
    return std::make_unique<TextbookFormulation>(shared_model_);
  }

  std::string_view name() const override { return "textbook"; }
  Eigen::Index dimension() const override;
  void derivative(double t, const VecX& y, VecX& dydt) const override;
  // The chapter integrates R as nine plain numbers: no projection.
  void project(double t, VecX& y) const override;
  void pack(std::span<const BodyState> states, VecX& y) const override;
  // R_WB as integrated (not re-orthonormalised).
  BodyState unpack(const VecX& y, std::size_t body) const override;
};

}  // namespace tumble
