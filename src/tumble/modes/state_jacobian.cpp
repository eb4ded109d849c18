#include "tumble/modes/state_jacobian.hpp"

#include <stdexcept>

#include "tumble/modes/linearisation.hpp"
#include "tumble/modes/modal_equations.hpp"

namespace tumble {

void calc_modal_tangent(const ArticulatedModel& model, const ModalLayout& layout, const VecX& y,
                        MatX& E, MatX& P) {
  E.setZero(y.size(), layout.size());
  P.setZero(layout.size(), y.size());
  for (std::size_t k = 0; k < model.tree.size(); ++k) {
    model.tree[k].kind->add_modal_tangent(model.tree[k], y, layout.sign[k],
                                          layout.position_offset[k], layout.speed_offset[k], E, P);
  }
}

bool calc_state_jacobian(const std::shared_ptr<const ArticulatedModel>& model, double t,
                         const VecX& y, std::span<const ContactHold> holds, MatX& dfdy) {
  if (holds.size() != model->model.contacts.size()) {
    throw std::invalid_argument("calc_state_jacobian: one hold per contact");
  }
  dfdy.setZero();
  ModalLayout layout = make_modal_layout(*model, t);
  const Eigen::Index n = layout.size();
  if (n == 0) return true;  // every joint held or driven: nothing depends on the state
  MatX E, P;
  calc_modal_tangent(*model, layout, y, E, P);
  const ModalEquations equations(model, std::move(layout), y, t, holds);
  VecX z_rate;  // z' at z = 0, the value the dual numbers carry
  const MatX rates_jacobian =
      jacobian_at_zero([&](const VecXOf<Dual>& z) { return equations.rates<Dual>(z); }, n, &z_rate);
  // dy'/dz: E (dz'/dz), and where y is curved in z, (d^2 y / dz^2)[., z']
  // (JointKind::add_modal_curvature).
  MatX y_rate_by_z = E * rates_jacobian;
  const ModalLayout& modal = equations.layout();
  for (std::size_t k = 0; k < model->tree.size(); ++k) {
    model->tree[k].kind->add_modal_curvature(model->tree[k], y, modal.position_offset[k],
                                             modal.speed_offset[k], z_rate, y_rate_by_z);
  }
  dfdy.noalias() = y_rate_by_z * P;
  return true;
}

}  // namespace tumble
