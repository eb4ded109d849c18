#include "tumble/multibody/articulated_data.hpp"

namespace tumble {

ArticulatedData::ArticulatedData(const ArticulatedModel& model) {
  work.resize(model.tree.size());
  for (std::size_t k = 0; k < model.tree.size(); ++k) {
    const Eigen::Index nv = model.tree[k].nv;
    Workspace& w = work[k];
    w.U.resize(6, nv);
    w.D_inv.resize(nv, nv);
    w.u.resize(nv);
    w.tau.resize(nv);
    w.qdd.resize(nv);
  }
  states.resize(model.body_count());
  rates.resize(model.dimension - model.ledger);
  const std::size_t contacts = model.model.contacts.size();
  touching.reserve(model.most_contact_vertices);
  contact_now.resize(contacts);
  unknowns.resize(6 * contacts);
  const auto rows = static_cast<Eigen::Index>(6 * contacts);
  contact_matrix.resize(rows, rows);
  contact_rhs.resize(rows);
  contact_x.resize(rows);
  solve_scratch = ConstraintSolveScratch(rows);
  impact_y.resize(model.dimension);
  onset_y.resize(model.dimension);
  onset_dydt.resize(model.dimension);
}

}  // namespace tumble
