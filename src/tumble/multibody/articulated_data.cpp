#include "tumble/multibody/articulated_data.hpp"

#include "tumble/multibody/joints/joint_kind.hpp"

namespace tumble {

ArticulatedData::ArticulatedData(const ArticulatedModel& model) {
  work.resize(model.tree.size());
  reuse_inertia.assign(model.tree.size(), 0);
  for (std::size_t k = 0; k < model.tree.size(); ++k) {
    const Eigen::Index nv = model.tree[k].nv;
    Workspace& w = work[k];
    w.U.resize(6, nv);
    w.D_inv.resize(nv, nv);
    w.u.resize(nv);
    w.tau.resize(nv);
    w.qdd.resize(nv);
    if (model.tree[k].kind->moving_subspace()) {
      w.moving = static_cast<int>(moving.size());
      moving.push_back({model.tree[k].S, Vec6::Zero()});
    }
  }
  states.resize(model.body_count());
  rates.resize(model.dimension - model.ledger);
}

}  // namespace tumble
