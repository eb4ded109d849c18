#include "tumble/modes/modal_equations.hpp"

#include <cmath>

#include <Eigen/Eigenvalues>
#include <stdexcept>

#include "tumble/dynamics/force_elements.hpp"
#include "tumble/math/dual.hpp"
#include "tumble/math/rotation.hpp"
#include "tumble/modes/modal_pair.hpp"
#include "tumble/modes/not_steady.hpp"
#include "tumble/multibody/joints/joint_kind.hpp"

namespace tumble {

namespace {

template <typename S>
using V3 = Vec3Of<S>;
template <typename S>
using M3 = Mat3Of<S>;
template <typename S>
using MX = MatXOf<S>;
template <typename S>
using M3X = Eigen::Matrix<S, 3, Eigen::Dynamic>;

// The solution of M x = b, M symmetric positive definite (the mass matrix), and of A x = b for
// a general A (with a sliding contact's friction, the complement is not symmetric).
VecX solve_mass(const MatX& M, const VecX& b) {
  return M.ldlt().solve(b);
}
VecX solve_general(const MatX& A, const VecX& b) {
  return A.partialPivLu().solve(b);
}
// With derivatives: x = M^-1 b, and along each seed x' = M^-1 (b' - M' x), so the factorisation is
// of plain numbers (Factors: Eigen's LDLT or PartialPivLU).
template <typename Factors>
VecXOf<Dual> solve_factored(const MX<Dual>& M, const VecXOf<Dual>& b) {
  const Eigen::Index n = b.size();
  Eigen::Index seeds = 0;
  for (Eigen::Index i = 0; i < n; ++i) {
    seeds = std::max(seeds, b(i).derivatives().size());
    for (Eigen::Index j = 0; j < n; ++j) seeds = std::max(seeds, M(i, j).derivatives().size());
  }
  const auto derivatives = [seeds](const Dual& a) -> DualDerivatives {
    return a.derivatives().size() == 0 ? DualDerivatives::Zero(seeds) : a.derivatives();
  };
  MatX M0(n, n);
  VecX b0(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    b0(i) = b(i).value();
    for (Eigen::Index j = 0; j < n; ++j) M0(i, j) = M(i, j).value();
  }
  const Factors factors(M0);
  const VecX x0 = factors.solve(b0);
  MatX rhs(n, seeds);  // column s: b' - M' x along seed s
  for (Eigen::Index i = 0; i < n; ++i) {
    DualDerivatives row = derivatives(b(i));
    for (Eigen::Index j = 0; j < n; ++j) row -= derivatives(M(i, j)) * x0(j);
    rhs.row(i) = row.transpose();
  }
  const MatX dx = factors.solve(rhs);
  VecXOf<Dual> x(n);
  for (Eigen::Index i = 0; i < n; ++i) x(i) = Dual(x0(i), dx.row(i).transpose());
  return x;
}
VecXOf<Dual> solve_mass(const MX<Dual>& M, const VecXOf<Dual>& b) {
  return solve_factored<Eigen::LDLT<MatX>>(M, b);
}
VecXOf<Dual> solve_general(const MX<Dual>& A, const VecXOf<Dual>& b) {
  return solve_factored<Eigen::PartialPivLU<MatX>>(A, b);
}

// The values of a matrix without their derivatives.
MatX values_of(const MatX& A) {
  return A;
}
MatX values_of(const MX<Dual>& A) {
  return A.unaryExpr([](const Dual& x) { return x.value(); });
}

}  // namespace

// Per tree joint: its child's pose and motion.
template <typename S>
struct ModalKinematics {
  JointMotionOf<S> joint;  // what its joint's coordinates say of the child (its speeds u, ...)
  M3<S> R_WC;
  V3<S> r_G, omega, v_G;  // world
  V3<S> alpha0, a0;       // the accelerations with every joint's speeds' rates zero
  M3X<S> G_w, G_v;        // per unit of the joint's speeds' rates: alpha and a_G of its child
};

ModalEquations::ModalEquations(std::shared_ptr<const ArticulatedModel> model, ModalLayout layout,
                               VecX y0, double t0)
    : model_(std::move(model)), layout_(std::move(layout)), y0_(std::move(y0)), t0_(t0) {
  set_up(nullptr);
}

ModalEquations::ModalEquations(std::shared_ptr<const ArticulatedModel> model, ModalLayout layout,
                               VecX y0, double t0, std::span<const ContactHold> holds)
    : model_(std::move(model)), layout_(std::move(layout)), y0_(std::move(y0)), t0_(t0) {
  set_up(&holds);
}

void ModalEquations::set_up(const std::span<const ContactHold>* holds) {
  const std::size_t n = model_->tree.size();
  // Unknown accelerations: the speeds of the joints that are neither held nor driven.
  unknown_.assign(n, -1);
  for (std::size_t k = 0; k < n; ++k) {
    if (model_->prescribed(k, t0_)) continue;
    unknown_[k] = unknowns_;
    unknowns_ += model_->tree[k].nv;
  }
  if (!model_->model.contacts.empty()) {
    const std::vector<ModalKinematics<double>> kin = kinematics<double>(VecX::Zero(layout_.size()));
    const std::size_t bodies = model_->model.bodies.size();
    std::vector<Vec3> r_G_W(bodies, Vec3::Zero());
    std::vector<Mat3> R_WB(bodies, Mat3::Identity());
    for (std::size_t k = 0; k < n; ++k) {
      r_G_W[model_->tree[k].child] = kin[k].r_G;
      R_WB[model_->tree[k].child] = kin[k].R_WC;
    }
    contacts_ = holds != nullptr ? held_contacts(model_->model, *holds, r_G_W, R_WB)
                                 : touching_contacts(model_->model, r_G_W, R_WB);
  }
  drops_dependent_rows_ = holds != nullptr;
  for (const JointModel& joint : model_->model.joints) {
    if (joint.closes_loop) loops_.push_back(loop_shape_of(joint));
  }
  for (const LoopShape& loop : loops_) loop_rows_ += loop.rows();
  if (loop_rows_ > 0) select_loop_rows();
}

void ModalEquations::select_loop_rows() {
  const std::vector<ModalKinematics<double>> kin = kinematics<double>(VecX::Zero(layout_.size()));
  std::vector<M3X<double>> J_v, J_w;
  calc_body_jacobians<double>(kin, J_v, J_w);
  MatX G(loop_rows_, unknowns_);
  VecX kappa(loop_rows_);
  calc_loop_rows<double>(kin, J_v, J_w, G, kappa);
  // A row is kept where it moves the speeds along a direction the rows before it do not: what is
  // left of it off their span (an orthonormal basis, grown as rows are kept) is more than
  // round-off against the row itself. A row the tree already holds (none of it moves) is left.
  const double largest = G.rowwise().norm().maxCoeff();
  MatX basis(unknowns_, 0);
  for (Eigen::Index i = 0; i < loop_rows_; ++i) {
    const VecX g = G.row(i).transpose();
    const VecX off = g - basis * (basis.transpose() * g);
    if (g.norm() <= 1e-12 * largest || off.norm() <= 1e-9 * g.norm()) continue;
    basis.conservativeResize(Eigen::NoChange, basis.cols() + 1);
    basis.col(basis.cols() - 1) = off / off.norm();
    loop_rows_held_.push_back(i);
  }
}

template <typename S>
ModalJointPoint<S> ModalEquations::point_of(std::size_t k, const VecXOf<S>& z) const {
  const JointKind& kind = *model_->tree[k].kind;
  const auto positions = static_cast<Eigen::Index>(kind.modal_positions().size());
  const auto speeds = static_cast<Eigen::Index>(kind.modal_speeds().size());
  const Eigen::Index po = layout_.position_offset[k];
  const Eigen::Index so = layout_.speed_offset[k];
  ModalJointPoint<S> at{y0_, VecXOf<S>::Zero(positions), VecXOf<S>::Zero(speeds), layout_.sign[k]};
  if (po >= 0) at.z_q = z.segment(po, positions);
  if (so >= 0) at.z_u = z.segment(so, speeds);
  return at;
}

// Forward: poses, velocities and the velocity terms of the accelerations, parents first.
template <typename S>
std::vector<ModalKinematics<S>> ModalEquations::kinematics(const VecXOf<S>& z) const {
  const ArticulatedModel& m = *model_;
  const std::size_t n = m.tree.size();
  std::vector<ModalKinematics<S>> kin(n);
  for (std::size_t k = 0; k < n; ++k) {
    const TreeJoint& joint = m.tree[k];
    ModalKinematics<S>& c = kin[k];
    M3<S> R_WP = M3<S>::Identity();
    V3<S> r_P = V3<S>::Zero(), omega_P = V3<S>::Zero(), v_P = V3<S>::Zero();
    V3<S> alpha_P = V3<S>::Zero(), a_P = V3<S>::Zero();
    if (joint.parent != kGround) {
      const ModalKinematics<S>& p = kin[m.slot_of_body[static_cast<std::size_t>(joint.parent)]];
      R_WP = p.R_WC;
      r_P = p.r_G;
      omega_P = p.omega;
      v_P = p.v_G;
      alpha_P = p.alpha0;
      a_P = p.a0;
    }
    joint.kind->calc_modal_motion(joint, point_of<S>(k, z), c.joint);
    c.R_WC = R_WP * c.joint.R_PC;
    c.r_G = r_P + R_WP * c.joint.p_PC_P;
    const Eigen::Index nv = joint.nv;
    c.G_w = c.R_WC * c.joint.S_C.topRows(3);
    c.G_v = c.R_WC * c.joint.S_C.bottomRows(3);
    V3<S> omega_rel = V3<S>::Zero(), v_rel = V3<S>::Zero();
    if (nv > 0) {
      omega_rel = c.G_w * c.joint.u;
      v_rel = c.G_v * c.joint.u;
    }
    const V3<S> d = c.r_G - r_P;
    c.omega = omega_P + omega_rel;
    c.v_G = v_P + omega_P.cross(d) + v_rel;
    // S turns with the child's axes, so d/dt (R_WC S u) = omega_C x (R_WC S u) + R_WC S u' (and
    // R_WC (dS/dt) u where S turns in them too).
    c.alpha0 = alpha_P + omega_P.cross(omega_rel);
    c.a0 = a_P + alpha_P.cross(d) + omega_P.cross(omega_P.cross(d)) + omega_P.cross(v_rel) +
           c.omega.cross(v_rel);
    if (c.joint.S_moves) {
      c.alpha0 += c.R_WC * c.joint.S_rate_u.template head<3>();
      c.a0 += c.R_WC * c.joint.S_rate_u.template tail<3>();
    }
  }
  return kin;
}

void ModalEquations::calc_body_velocities(const VecX& z, std::span<BodyState> states) const {
  const std::vector<ModalKinematics<double>> kin = kinematics<double>(z);
  for (std::size_t k = 0; k < kin.size(); ++k) {
    BodyState& s = states[static_cast<std::size_t>(model_->tree[k].child)];
    s.v_G = kin[k].v_G;
    s.omega_W = kin[k].omega;
  }
}

template <typename S>
void ModalEquations::calc_body_jacobians(const std::vector<ModalKinematics<S>>& kin,
                                         std::vector<M3X<S>>& J_v, std::vector<M3X<S>>& J_w) const {
  const ArticulatedModel& m = *model_;
  const std::size_t n = m.tree.size();
  J_v.assign(n, M3X<S>::Zero(3, unknowns_));
  J_w.assign(n, M3X<S>::Zero(3, unknowns_));
  for (std::size_t kb = 0; kb < n; ++kb) {
    const ModalKinematics<S>& c = kin[kb];
    for (std::size_t k = kb;;) {
      const TreeJoint& joint = m.tree[k];
      if (unknown_[k] >= 0) {
        for (Eigen::Index i = 0; i < joint.nv; ++i) {
          J_w[kb].col(unknown_[k] + i) = kin[k].G_w.col(i);
          J_v[kb].col(unknown_[k] + i) =
              kin[k].G_w.col(i).cross(c.r_G - kin[k].r_G) + kin[k].G_v.col(i);
        }
      }
      if (joint.parent == kGround) break;
      k = m.slot_of_body[static_cast<std::size_t>(joint.parent)];
    }
  }
}

template <typename S>
BodyStateOf<S> ModalEquations::loop_side(const std::vector<ModalKinematics<S>>& kin,
                                         int body) const {
  BodyStateOf<S> side;
  if (body == kGround) return side;
  const ModalKinematics<S>& c = kin[model_->slot_of_body[static_cast<std::size_t>(body)]];
  side.R_WB = c.R_WC;
  side.r_G = c.r_G;
  side.omega_W = c.omega;
  side.v_G = c.v_G;
  return side;
}

template <typename S>
void ModalEquations::calc_loop_rows(const std::vector<ModalKinematics<S>>& kin,
                                    const std::vector<M3X<S>>& J_v, const std::vector<M3X<S>>& J_w,
                                    MX<S>& G, VecXOf<S>& kappa) const {
  const ArticulatedModel& m = *model_;
  Eigen::Index row = 0;
  for (const LoopShape& loop : loops_) {
    const BodyStateOf<S> a = loop_side<S>(kin, loop.body_a);
    const BodyStateOf<S> b = loop_side<S>(kin, loop.body_b);
    const V3<S> p_W = loop_point_W(loop, b);
    // A body's point at p_W: its velocity per unit of the unknown speeds, its angular velocity's,
    // and its point's and its angular acceleration with their rates zero (ground: none).
    struct Point {
      M3X<S> J_p, J_w;
      V3<S> a0, alpha0;
    };
    const auto point_of_body = [&](int body) {
      Point point{M3X<S>::Zero(3, unknowns_), M3X<S>::Zero(3, unknowns_), V3<S>::Zero(),
                  V3<S>::Zero()};
      if (body == kGround) return point;
      const std::size_t k = m.slot_of_body[static_cast<std::size_t>(body)];
      const ModalKinematics<S>& c = kin[k];
      const V3<S> p = p_W - c.r_G;
      point.J_p = J_v[k] - hat<S>(p) * J_w[k];
      point.J_w = J_w[k];
      point.a0 = c.a0 + c.alpha0.cross(p) + c.omega.cross(V3<S>(c.omega.cross(p)));
      point.alpha0 = c.alpha0;
      return point;
    };
    const Point on_a = point_of_body(loop.body_a);
    const Point on_b = point_of_body(loop.body_b);
    for_each_loop_row<S>(loop, a, b, [&](const LoopRowOf<S>& held) {
      const V3<S>& d = held.direction_W;
      const S response = held.turn ? d.dot(on_b.alpha0 - on_a.alpha0) : d.dot(on_b.a0 - on_a.a0);
      G.row(row) =
          held.turn ? d.transpose() * (on_b.J_w - on_a.J_w) : d.transpose() * (on_b.J_p - on_a.J_p);
      kappa(row) = loop_row_acceleration(loop, held, a, b, response);
      ++row;
    });
  }
}

// A held contact's rows: the point P where it touches, as a point of its body (of each body, for
// a pair, the other's taken away).
template <typename S>
struct ContactRowsOf {
  S gap = S(0.0);       // m: P's height over the plane, or the pair's gap
  V3<S> n_W, n_rate_W;  // the normal (towards the contact's body) and how fast it turns
  V3<S> v_P;            // P's velocity (relative, for a pair), world
  M3X<S> J_P;           // v_P per unit of the unknown speeds
  V3<S> a_P0;           // P's acceleration with those speeds' rates zero
};

template <typename S>
ContactRowsOf<S> ModalEquations::contact_rows(const ModalContact& held,
                                              const std::vector<ModalKinematics<S>>& kin,
                                              const std::vector<M3X<S>>& J_v,
                                              const std::vector<M3X<S>>& J_w) const {
  const ArticulatedModel& m = *model_;
  const PlaneContact& contact = m.model.contacts[held.contact];
  const auto kb = static_cast<std::size_t>(m.slot_of_body[contact.body]);
  const ModalKinematics<S>& c = kin[kb];
  const bool moving = !J_v.empty();
  ContactRowsOf<S> at;
  if (!held.pair) {
    V3<S> p_GP_W, p_GP_rate_W;
    calc_contact_offset<S>(held.point, contact.normal_W, c.R_WC, c.omega, p_GP_W, p_GP_rate_W);
    at.n_W = contact.normal_W.cast<S>();
    at.n_rate_W = V3<S>::Zero();
    at.gap = at.n_W.dot(c.r_G + p_GP_W - contact.point_W.cast<S>());
    at.v_P = c.v_G + c.omega.cross(p_GP_W);
    if (moving) {
      at.J_P = J_v[kb] - hat<S>(p_GP_W) * J_w[kb];
      at.a_P0 = c.a0 + c.alpha0.cross(p_GP_W) + c.omega.cross(p_GP_rate_W);
    }
    return at;
  }
  // Two bodies: each one's point at O, O moving over both (modal_pair.hpp).
  const auto ko = static_cast<std::size_t>(m.slot_of_body[contact.other_body]);
  const ModalKinematics<S>& o = kin[ko];
  const ModalPairPointOf<S> pair =
      modal_pair_point<S>(contact, loop_side<S>(kin, static_cast<int>(contact.body)),
                          loop_side<S>(kin, static_cast<int>(contact.other_body)));
  at.gap = pair.gap;
  at.n_W = pair.n_W;
  at.n_rate_W = pair.n_rate_W;
  const V3<S> p_a = pair.O_W - c.r_G, p_b = pair.O_W - o.r_G;
  at.v_P = (c.v_G + c.omega.cross(p_a)) - (o.v_G + o.omega.cross(p_b));
  if (moving) {
    at.J_P = (J_v[kb] - hat<S>(p_a) * J_w[kb]) - (J_v[ko] - hat<S>(p_b) * J_w[ko]);
    at.a_P0 = (c.a0 + c.alpha0.cross(p_a) + c.omega.cross(V3<S>(pair.O_rate_W - c.v_G))) -
              (o.a0 + o.alpha0.cross(p_b) + o.omega.cross(V3<S>(pair.O_rate_W - o.v_G)));
  }
  return at;
}

template <typename S>
VecXOf<S> ModalEquations::evaluate(const VecXOf<S>& z, std::vector<Vec3>* contact_forces_W) const {
  const ArticulatedModel& m = *model_;
  const Model& model = m.model;
  const std::size_t n = m.tree.size();
  const std::vector<ModalKinematics<S>> kin = kinematics<S>(z);
  const std::vector<Eigen::Index>& unknown = unknown_;
  const Eigen::Index unknowns = unknowns_;

  // Loads on each body: force at the COM and moment about it, world axes.
  const std::size_t bodies = model.bodies.size();
  std::vector<V3<S>> F(bodies, V3<S>::Zero()), M(bodies, V3<S>::Zero());
  const auto slot = [&](int body) -> const ModalKinematics<S>& {
    return kin[m.slot_of_body[static_cast<std::size_t>(body)]];
  };
  for (std::size_t b = 0; b < bodies; ++b) {
    F[b] += model.bodies[b].mass * model.gravity_W.cast<S>();
  }
  for (const AppliedLoad& load : model.loads) {
    if (!load.active_at(t0_)) continue;
    const LoadOnBodyOf<S> on_body =
        calc_load_on_body<S>(load, slot(static_cast<int>(load.body)).R_WC);
    F[load.body] += on_body.F_W;
    M[load.body] += on_body.M_G_W;
  }
  // The force elements by the laws a run evaluates (force_elements.hpp), on the bodies' states.
  std::vector<BodyStateOf<S>> states(bodies);
  for (std::size_t k = 0; k < n; ++k) {
    BodyStateOf<S>& state = states[m.tree[k].child];
    state.r_G = kin[k].r_G;
    state.R_WB = kin[k].R_WC;
    state.v_G = kin[k].v_G;
    state.omega_W = kin[k].omega;
  }
  const auto add = [&](int body, const V3<S>& force, const V3<S>& moment) {
    if (body == kGround) return;
    F[static_cast<std::size_t>(body)] += force;
    M[static_cast<std::size_t>(body)] += moment;
  };
  const auto add_element = [&](int body_a, int body_b, const ElementLoadOf<S>& load) {
    add(body_b, load.F_b_W, load.M_b_W);
    add(body_a, load.F_a_W, load.M_a_W);
  };
  for (const LinearSpring& spring : model.springs) {
    add_element(spring.body_a, spring.body_b,
                calc_spring_load<S>(spring, std::span<const BodyStateOf<S>>(states)));
  }
  for (const TorsionalSpring& spring : model.torsional_springs) {
    // Across a hinge: its angle and rate, about its axis as the scenario states it.
    S angle(0.0), rate(0.0);
    V3<S> axis_W = V3<S>::UnitZ();
    if (spring.hinge >= 0) {
      const auto k =
          static_cast<std::size_t>(m.slot_of_joint[static_cast<std::size_t>(spring.hinge)]);
      const TreeJoint& joint = m.tree[k];
      angle = kin[k].joint.coordinates(0);
      rate = kin[k].joint.u(0);
      axis_W = kin[k].R_WC * joint.axis_C.cast<S>();
      if (joint.reversed) axis_W = -axis_W;
    }
    add_element(spring.body_a, spring.body_b,
                calc_torsional_spring_load<S>(spring, std::span<const BodyStateOf<S>>(states),
                                              angle, rate, axis_W));
  }
  // A motor's effort across a loop's closing joint, a load on its bodies (as a run applies it).
  for (const JointModel& joint : model.joints) {
    if (!joint.closes_loop || joint.motor.kind != JointMotor::Kind::Effort ||
        !joint.motor.active_at(t0_)) {
      continue;
    }
    add_element(joint.body_a, joint.body_b,
                calc_loop_motor_load<S>(joint, std::span<const BodyStateOf<S>>(states)));
  }

  // Newton-Euler projected onto the unknown speeds' rates: M(q) u' = generalised forces.
  MX<S> mass = MX<S>::Zero(unknowns, unknowns);
  VecXOf<S> force = VecXOf<S>::Zero(unknowns);
  for (std::size_t k = 0; k < n; ++k) {
    const TreeJoint& joint = m.tree[k];
    if (unknown[k] < 0 || joint.model_joint < 0) continue;
    const JointMotor& motor = model.joints[static_cast<std::size_t>(joint.model_joint)].motor;
    if (motor.kind == JointMotor::Kind::Effort && motor.active_at(t0_)) {
      force(unknown[k] + motor.freedom) += S(motor.value);
    }
  }
  std::vector<M3X<S>> J_v, J_w;
  calc_body_jacobians<S>(kin, J_v, J_w);
  for (std::size_t kb = 0; kb < n; ++kb) {
    const ModalKinematics<S>& c = kin[kb];
    const RigidBody& body = model.bodies[m.tree[kb].child];
    const M3<S> I_W = c.R_WC * body.I_G_B.cast<S>() * c.R_WC.transpose();
    const std::size_t b = m.tree[kb].child;
    mass += body.mass * J_v[kb].transpose() * J_v[kb] + J_w[kb].transpose() * I_W * J_w[kb];
    force += J_v[kb].transpose() * (F[b] - body.mass * c.a0) +
             J_w[kb].transpose() * (M[b] - I_W * c.alpha0 - c.omega.cross(I_W * c.omega));
  }
  VecXOf<S> u_dot = unknowns > 0 ? solve_mass(mass, force) : VecXOf<S>(0);

  // The contacts' forces lambda hold their rows: G u' + kappa = 0, G the rows' velocity per unit
  // of the unknown speeds (the body's point: J_v - [p]x J_w) and kappa their acceleration with
  // u' = 0 (a_G + alpha x p + omega x p'). With u' = M^-1 (Q + G^T lambda):
  // G M^-1 G^T lambda = -kappa - G M^-1 Q.
  // The loops' rows are held the same way, those independent at t0 (the others follow).
  Eigen::Index rows = static_cast<Eigen::Index>(loop_rows_held_.size());
  bool slides = false;  // with friction on a sliding contact's push: D differs from G
  for (const ModalContact& contact : contacts_) {
    rows += contact.rows();
    slides = slides || (!contact.rolls && contact.sliding.friction > 0.0);
  }
  if (rows > 0) {
    MX<S> G = MX<S>::Zero(rows, unknowns);
    MX<S> D = MX<S>::Zero(slides ? rows : 0, unknowns);  // the forces' directions (G^T's, D^T)
    std::vector<Vec3> push_W(contacts_.size());          // per contact: a unit push's force, world
    VecXOf<S> kappa(rows);
    Eigen::Index row = 0;
    std::size_t index = 0;
    for (const ModalContact& held : contacts_) {
      const ContactRowsOf<S> at = contact_rows<S>(held, kin, J_v, J_w);
      const M3X<S>& J_P = at.J_P;
      if (held.rolls) {
        G.middleRows(row, 3) = J_P;
        kappa.template segment<3>(row) = at.a_P0;
        if (slides) D.middleRows(row, 3) = J_P;
      } else {
        const V3<S>& n_W = at.n_W;
        G.row(row) = n_W.transpose() * J_P;
        // (A pair's normal turns: its row's rate gains n' . v, v the points' relative velocity.)
        kappa(row) = n_W.dot(at.a_P0) + at.n_rate_W.dot(at.v_P);
        V3<S> push = n_W;
        if (held.sliding.friction > 0.0) {
          // Coulomb's friction rides on the push: -mu N along the slip of the body's point
          // there, or along the direction a slip not yet grown is held to.
          V3<S> slide = held.sliding.slide_W.cast<S>();
          if (held.sliding.follows_slip) {
            using std::sqrt;
            const V3<S> slip = at.v_P - n_W * n_W.dot(at.v_P);
            slide = slip / sqrt(slip.squaredNorm());
          }
          push -= held.sliding.friction * slide;
        }
        if (slides) D.row(row) = push.transpose() * J_P;
        push_W[index] = push.unaryExpr([](const S& x) { return value_of(x); });
      }
      row += held.rows();
      ++index;
    }
    if (!loop_rows_held_.empty()) {
      MX<S> G_loops(loop_rows_, unknowns);
      VecXOf<S> kappa_loops(loop_rows_);
      calc_loop_rows<S>(kin, J_v, J_w, G_loops, kappa_loops);
      for (const Eigen::Index held : loop_rows_held_) {
        G.row(row) = G_loops.row(held);
        if (slides) D.row(row) = G_loops.row(held);
        kappa(row++) = kappa_loops(held);
      }
    }
    const MX<S>& forces = slides ? D : G;
    MX<S> response(unknowns, rows);  // M^-1 D^T
    for (Eigen::Index j = 0; j < rows; ++j) {
      response.col(j) = solve_mass(mass, VecXOf<S>(forces.row(j).transpose()));
    }
    const MX<S> schur = G * response;
    // Rows the joints already hold (a point on a hinge's axis) leave G M^-1 G^T singular.
    MatX held_rows = values_of(schur);
    if (slides) {
      const MatX G0 = values_of(G);
      held_rows = G0 * values_of(mass).ldlt().solve(MatX(G0.transpose()));
    }
    const Eigen::SelfAdjointEigenSolver<MatX> definite(held_rows);
    const bool dependent = definite.eigenvalues()(0) <= 1e-12 * definite.eigenvalues()(rows - 1);
    // (`tumble modes` holds no contact sliding, whose friction would ride on a push the rows
    // leave open; a run's Jacobian takes one of the pushes.)
    if (dependent && !drops_dependent_rows_ && !loops_.empty()) {
      throw NotSteady(
          "joints: the loops' rows lose their independence here (a dead centre or a change "
          "point): the motion is not determined, and a linearisation needs it");
    }
    const VecXOf<S> rhs = -kappa - G * u_dot;
    // The forces reported, where rows repeat what the joints or other rows hold (an edge mill's
    // ball joint takes any force along the line from it to the stone's contact): of those that
    // hold them, the one with the least friction, as a run's solve takes it
    // (contact/contact_forces.cpp).
    VecX lambda_reported;
    if (dependent) {
      // The rows that the others do not already hold (at the values: the same rows for every
      // seed), in order; the accelerations that hold them hold the rest.
      Eigen::ColPivHouseholderQR<MatX> pivoted(held_rows);
      pivoted.setThreshold(1e-9);
      std::vector<Eigen::Index> kept(pivoted.colsPermutation().indices().data(),
                                     pivoted.colsPermutation().indices().data() + pivoted.rank());
      std::sort(kept.begin(), kept.end());
      if (!kept.empty()) {
        const MX<S> schur_kept = schur(kept, kept);
        const VecXOf<S> rhs_kept = rhs(kept);
        const VecXOf<S> lambda =
            slides ? solve_general(schur_kept, rhs_kept) : solve_mass(schur_kept, rhs_kept);
        u_dot += MX<S>(response(Eigen::all, kept)) * lambda;
      }
      // The rows left out hold too where they repeat the others; where they would ask for
      // another acceleration (a point the joints move otherwise than the contact holds it),
      // nothing holds them both, and `tumble modes` refuses the state.
      const VecX residual = (G * u_dot + kappa).unaryExpr([](const S& x) { return value_of(x); });
      const VecX asked = rhs.unaryExpr([](const S& x) { return value_of(x); });
      if (!drops_dependent_rows_ && residual.lpNorm<Eigen::Infinity>() >
                                        1e-9 * std::max(asked.lpNorm<Eigen::Infinity>(), 1e-300)) {
        throw NotSteady(
            "contacts: a touching point's motion is held by the joints (or by another contact) "
            "otherwise than the contact would hold it: no force holds both");
      }
      if (contact_forces_W != nullptr) {
        lambda_reported = least_friction_forces(
            held_rows, definite, VecX(rhs.unaryExpr([](const S& x) { return value_of(x); })));
      }
    } else {
      const VecXOf<S> lambda = slides ? solve_general(schur, rhs) : solve_mass(schur, rhs);
      u_dot += response * lambda;
      if (contact_forces_W != nullptr) {
        lambda_reported = lambda.unaryExpr([](const S& x) { return value_of(x); });
      }
    }
    if (contact_forces_W != nullptr) {
      contact_forces_W->clear();
      row = 0;
      for (std::size_t i = 0; i < contacts_.size(); ++i) {
        const ModalContact& held = contacts_[i];
        contact_forces_W->push_back(held.rolls ? Vec3(lambda_reported.segment<3>(row))
                                               : Vec3(lambda_reported(row) * push_W[i]));
        row += held.rows();
      }
    }
  }

  return z_rates_of(kin, J_v, u_dot, z);
}

VecX ModalEquations::least_friction_forces(const MatX& schur,
                                           const Eigen::SelfAdjointEigenSolver<MatX>& eigen,
                                           const VecX& rhs) const {
  // Every solution: one of them, plus any combination of the rows whose forces the joints and
  // the other rows take (schur's null space, N). Of those, the least friction: the forces'
  // tangential parts (T, the contacts' rolling rows less their normal parts) least in norm.
  const VecX particular = Eigen::CompleteOrthogonalDecomposition<MatX>(schur).solve(rhs);
  const Eigen::Index rows = schur.rows();
  const VecX& eigenvalues = eigen.eigenvalues();
  Eigen::Index nulls = 0;
  while (nulls < rows && eigenvalues(nulls) <= 1e-12 * eigenvalues(rows - 1)) ++nulls;
  const MatX null_space = eigen.eigenvectors().leftCols(nulls);
  MatX tangential = MatX::Zero(rows, rows);
  Eigen::Index row = 0;
  for (const ModalContact& held : contacts_) {
    if (held.rolls) {
      const Vec3& n = held.normal_W;
      tangential.block<3, 3>(row, row) = Mat3::Identity() - n * n.transpose();
    }
    row += held.rows();
  }
  const MatX TN = tangential * null_space;
  const VecX shift =
      Eigen::CompleteOrthogonalDecomposition<MatX>(TN).solve(VecX(-tangential * particular));
  return particular + null_space * shift;
}

template <typename S>
VecXOf<S> ModalEquations::z_rates_of(const std::vector<ModalKinematics<S>>& kin,
                                     const std::vector<M3X<S>>& J_v, const VecXOf<S>& u_dot,
                                     const VecXOf<S>& z) const {
  const ArticulatedModel& m = *model_;
  VecXOf<S> z_dot(z.size());
  for (std::size_t k = 0; k < m.tree.size(); ++k) {
    const Eigen::Index po = layout_.position_offset[k];
    const Eigen::Index so = layout_.speed_offset[k];
    if (po < 0) continue;
    const TreeJoint& joint = m.tree[k];
    const ModalKinematics<S>& c = kin[k];
    const ModalJointPoint<S> at = point_of<S>(k, z);
    VecXOf<S> z_q_rate(at.z_q.size()), z_u_rate(at.z_u.size());
    const V3<S> a_G = c.a0 + J_v[k] * u_dot;
    joint.kind->calc_modal_rates(joint, at, c.joint,
                                 VecXOf<S>(u_dot.segment(unknown_[k], joint.nv)), c.v_G, a_G,
                                 z_q_rate, z_u_rate);
    z_dot.segment(po, z_q_rate.size()) = z_q_rate;
    z_dot.segment(so, z_u_rate.size()) = z_u_rate;
  }
  return z_dot;
}

template <typename S>
VecXOf<S> ModalEquations::rates(const VecXOf<S>& z) const {
  return evaluate<S>(z, nullptr);
}

std::vector<Vec3> ModalEquations::contact_forces() const {
  std::vector<Vec3> forces;
  evaluate<double>(VecX::Zero(layout_.size()), &forces);
  return forces;
}

template <typename S>
VecXOf<S> ModalEquations::constraints(const VecXOf<S>& z) const {
  const std::vector<ModalKinematics<S>> kin = kinematics<S>(z);
  Eigen::Index rows = 2 * loop_rows_;
  for (const ModalContact& contact : contacts_) rows += 1 + contact.rows();
  VecXOf<S> values(rows);
  Eigen::Index row = 0;
  std::vector<M3X<S>> J_v, J_w;  // (the rows' velocities only: no Jacobians)
  for (const ModalContact& held : contacts_) {
    const ContactRowsOf<S> at = contact_rows<S>(held, kin, J_v, J_w);
    values(row++) = at.gap;
    if (held.rolls) {
      values.template segment<3>(row) = at.v_P;
    } else {
      values(row) = at.n_W.dot(at.v_P);
    }
    row += held.rows();
  }
  for (const LoopShape& loop : loops_) {
    const BodyStateOf<S> a = loop_side<S>(kin, loop.body_a);
    const BodyStateOf<S> b = loop_side<S>(kin, loop.body_b);
    for_each_loop_row<S>(loop, a, b, [&](const LoopRowOf<S>& held) {
      values(row) = held.error;
      values(row + loop_rows_) = loop_row_velocity(loop, held, a, b);
      ++row;
    });
  }
  return values;
}

template <typename S>
VecXOf<S> ModalEquations::symmetry_field(const Symmetry& symmetry, const VecXOf<S>& z) const {
  const ArticulatedModel& m = *model_;
  VecXOf<S> field = VecXOf<S>::Zero(z.size());
  for (std::size_t k = 0; k < m.tree.size(); ++k) {
    const TreeJoint& joint = m.tree[k];
    const Eigen::Index po = layout_.position_offset[k];
    const Eigen::Index so = layout_.speed_offset[k];
    if (po < 0) continue;
    const bool body_spin = symmetry.kind == Symmetry::Kind::BodySpin;
    if (body_spin ? k != symmetry.tree_joint || !joint.kind->turns_freely()
                  : joint.parent != kGround) {
      continue;  // a turn of the whole moves the tree below with its root
    }
    const ModalJointPoint<S> at = point_of<S>(k, z);
    VecXOf<S> z_q_field = VecXOf<S>::Zero(at.z_q.size());
    VecXOf<S> z_u_field = VecXOf<S>::Zero(at.z_u.size());
    if (body_spin) {
      joint.kind->calc_modal_body_turn(joint, at, symmetry.axis, z_q_field, z_u_field);
    } else {
      joint.kind->calc_modal_world_turn(joint, at, symmetry.axis, z_q_field, z_u_field);
    }
    field.segment(po, z_q_field.size()) = z_q_field;
    field.segment(so, z_u_field.size()) = z_u_field;
  }
  return field;
}

template VecXOf<double> ModalEquations::rates<double>(const VecXOf<double>&) const;
template VecXOf<Dual> ModalEquations::rates<Dual>(const VecXOf<Dual>&) const;
template VecXOf<double> ModalEquations::constraints<double>(const VecXOf<double>&) const;
template VecXOf<Dual> ModalEquations::constraints<Dual>(const VecXOf<Dual>&) const;
template VecXOf<double> ModalEquations::symmetry_field<double>(const Symmetry&,
                                                               const VecXOf<double>&) const;
template VecXOf<Dual> ModalEquations::symmetry_field<Dual>(const Symmetry&,
                                                           const VecXOf<Dual>&) const;

}  // namespace tumble
