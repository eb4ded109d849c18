#include "tumble/modes/modal_equations.hpp"

#include <cmath>

#include <Eigen/Eigenvalues>
#include <stdexcept>

#include "tumble/math/rotation.hpp"
#include "tumble/modes/not_steady.hpp"
#include "tumble/multibody/joints/joint_kind.hpp"

namespace tumble {

namespace {

template <typename S>
using V3 = Eigen::Matrix<S, 3, 1>;
template <typename S>
using M3 = Eigen::Matrix<S, 3, 3>;
template <typename S>
using MX = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>;
template <typename S>
using M3X = Eigen::Matrix<S, 3, Eigen::Dynamic>;

double value_of(double x) {
  return x;
}
double value_of(const Dual& x) {
  return x.value();
}

template <typename S>
M3<S> hat_of(const V3<S>& a) {
  M3<S> W;
  W << S(0.0), -a.z(), a.y(),  //
      a.z(), S(0.0), -a.x(),   //
      -a.y(), a.x(), S(0.0);
  return W;
}

// Rot(axis, angle) by Rodrigues' formula (the angle may carry derivatives, the axis does not).
template <typename S>
M3<S> rotation_about(const Vec3& axis, const S& angle) {
  using std::cos;
  using std::sin;
  const M3<S> K = hat(axis.normalized()).cast<S>();
  return M3<S>::Identity() + sin(angle) * K + (S(1.0) - cos(angle)) * K * K;
}

// R0 exp([r]x) to first order (see the header: evaluated at r = 0 only).
template <typename S>
M3<S> turned(const Mat3& R0, const V3<S>& r) {
  return R0.cast<S>() * (M3<S>::Identity() + hat_of<S>(r));
}

// The rate of a turn coordinate r (R = R0 exp([r]x)) while the body turns at omega (its axes):
// dr/dt = omega + r x omega / 2 + O(|r|^2).
template <typename S>
V3<S> turn_rate(const V3<S>& r, const V3<S>& omega) {
  return omega + S(0.5) * r.cross(omega);
}

// log(R) as a rotation vector, as log_so3 computes it, with derivatives that exist at R = 1.
template <typename S>
V3<S> rotation_vector(const M3<S>& R) {
  using std::atan2;
  using std::sqrt;
  const V3<S> s_n = S(0.5) * V3<S>(R(2, 1) - R(1, 2), R(0, 2) - R(2, 0), R(1, 0) - R(0, 1));
  const S sin_squared = s_n.squaredNorm();
  if (value_of(sin_squared) < 1e-16) return (S(1.0) + sin_squared / S(6.0)) * s_n;
  const S sin_theta = sqrt(sin_squared);
  const S cos_theta = S(0.5) * (R.trace() - S(1.0));
  return atan2(sin_theta, cos_theta) / sin_theta * s_n;
}

// The solution of M x = b, M symmetric positive definite (the mass matrix).
VecX solve_mass(const MatX& M, const VecX& b) {
  return M.ldlt().solve(b);
}
// With derivatives: x = M^-1 b, and along each seed x' = M^-1 (b' - M' x), so the factorisation is
// of plain numbers.
VecOf<Dual> solve_mass(const MX<Dual>& M, const VecOf<Dual>& b) {
  const Eigen::Index n = b.size();
  Eigen::Index seeds = 0;
  for (Eigen::Index i = 0; i < n; ++i) {
    seeds = std::max(seeds, b(i).derivatives().size());
    for (Eigen::Index j = 0; j < n; ++j) seeds = std::max(seeds, M(i, j).derivatives().size());
  }
  const auto derivatives = [seeds](const Dual& a) -> Eigen::VectorXd {
    return a.derivatives().size() == 0 ? Eigen::VectorXd::Zero(seeds) : a.derivatives();
  };
  MatX M0(n, n);
  VecX b0(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    b0(i) = b(i).value();
    for (Eigen::Index j = 0; j < n; ++j) M0(i, j) = M(i, j).value();
  }
  const Eigen::LDLT<MatX> factors(M0);
  const VecX x0 = factors.solve(b0);
  MatX rhs(n, seeds);  // column s: b' - M' x along seed s
  for (Eigen::Index i = 0; i < n; ++i) {
    Eigen::VectorXd row = derivatives(b(i));
    for (Eigen::Index j = 0; j < n; ++j) row -= derivatives(M(i, j)) * x0(j);
    rhs.row(i) = row.transpose();
  }
  const MatX dx = factors.solve(rhs);
  VecOf<Dual> x(n);
  for (Eigen::Index i = 0; i < n; ++i) x(i) = Dual(x0(i), dx.row(i).transpose());
  return x;
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
  M3<S> R_WC;
  V3<S> r_G, omega, v_G;  // world
  V3<S> alpha0, a0;       // the accelerations with every joint's speeds' rates zero
  M3X<S> G_w, G_v;        // per unit of the joint's speeds' rates: alpha and a_G of its child
  VecOf<S> u;             // the joint's speeds (tree convention)
  S angle = S(0.0);       // a hinge's angle (tree convention)
};

ModalEquations::ModalEquations(std::shared_ptr<const ArticulatedModel> model, ModalLayout layout,
                               VecX y0, double t0)
    : model_(std::move(model)), layout_(std::move(layout)), y0_(std::move(y0)), t0_(t0) {
  const std::size_t n = model_->tree.size();
  R_PC0_.resize(n);
  v_G0_W_.assign(n, Vec3::Zero());
  for (std::size_t k = 0; k < n; ++k) {
    const TreeJoint& joint = model_->tree[k];
    Vec3 p_PC_P;
    joint.kind->calc_placement(joint, y0_, R_PC0_[k], p_PC_P);
    if (joint.type == JointType::Free) {
      v_G0_W_[k] = R_PC0_[k] * y0_.segment<3>(joint.v + 3);
    }
  }
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
    contacts_ = touching_contacts(model_->model, r_G_W, R_WB);
  }
}

// Forward: poses, velocities and the velocity terms of the accelerations, parents first.
template <typename S>
std::vector<ModalKinematics<S>> ModalEquations::kinematics(const VecOf<S>& z) const {
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
    const Eigen::Index po = layout_.position_offset[k];
    const Eigen::Index so = layout_.speed_offset[k];
    const S sign(layout_.sign[k]);
    M3<S> R_PC = M3<S>::Identity();
    V3<S> p_PC_P = V3<S>::Zero();
    c.u = y0_.segment(joint.v, joint.nv).cast<S>();
    switch (joint.type) {
      case JointType::Hinge:
        c.angle = S(y0_(joint.q));
        if (po >= 0) c.angle += sign * z(po);
        R_PC = joint.R_PC0.cast<S>() * rotation_about<S>(joint.axis_C, c.angle);
        p_PC_P = joint.p_PJ_P.cast<S>() - R_PC * joint.p_CJ_C.cast<S>();
        if (so >= 0) c.u(0) += sign * z(so);
        break;
      case JointType::Prismatic: {
        S travel(y0_(joint.q));
        if (po >= 0) travel += sign * z(po);
        R_PC = joint.R_PC0.cast<S>();
        p_PC_P = joint.p_PJ_P.cast<S>() -
                 R_PC * (joint.p_CJ_C.cast<S>() - travel * joint.axis_C.cast<S>());
        if (so >= 0) c.u(0) += sign * z(so);
        break;
      }
      case JointType::Ball:
        R_PC = po >= 0 ? turned<S>(R_PC0_[k], z.template segment<3>(po)) : R_PC0_[k].cast<S>();
        p_PC_P = joint.p_PJ_P.cast<S>() - R_PC * joint.p_CJ_C.cast<S>();
        if (so >= 0) c.u += z.segment(so, 3);
        break;
      case JointType::Free:
        R_PC = po >= 0 ? turned<S>(R_PC0_[k], z.template segment<3>(po + 3)) : R_PC0_[k].cast<S>();
        p_PC_P = y0_.segment<3>(joint.q).cast<S>();
        if (po >= 0) p_PC_P += z.template segment<3>(po);
        if (so >= 0) {
          // Speeds (omega_C, v_C) in the child's axes; the modal speed is v_G in world axes.
          c.u.template head<3>() += z.template segment<3>(so + 3);
          c.u.template tail<3>() =
              R_PC.transpose() * (v_G0_W_[k].cast<S>() + z.template segment<3>(so));
        }
        break;
      case JointType::Fixed:
        R_PC = joint.R_PC0.cast<S>();
        p_PC_P = joint.p_PJ_P.cast<S>() - R_PC * joint.p_CJ_C.cast<S>();
        break;
    }
    c.R_WC = R_WP * R_PC;
    c.r_G = r_P + R_WP * p_PC_P;
    const Eigen::Index nv = joint.nv;
    c.G_w = c.R_WC * joint.S.topRows(3).cast<S>();
    c.G_v = c.R_WC * joint.S.bottomRows(3).cast<S>();
    V3<S> omega_rel = V3<S>::Zero(), v_rel = V3<S>::Zero();
    if (nv > 0) {
      omega_rel = c.G_w * c.u;
      v_rel = c.G_v * c.u;
    }
    const V3<S> d = c.r_G - r_P;
    c.omega = omega_P + omega_rel;
    c.v_G = v_P + omega_P.cross(d) + v_rel;
    // Axes fixed in the child carry S, so d/dt (R_WC S u) = omega_C x (R_WC S u) + R_WC S u'.
    c.alpha0 = alpha_P + omega_P.cross(omega_rel);
    c.a0 = a_P + alpha_P.cross(d) + omega_P.cross(omega_P.cross(d)) + omega_P.cross(v_rel) +
           c.omega.cross(v_rel);
  }
  return kin;
}

template <typename S>
VecOf<S> ModalEquations::evaluate(const VecOf<S>& z, std::vector<Vec3>* contact_forces_W) const {
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
    const ModalKinematics<S>& c = slot(static_cast<int>(load.body));
    const V3<S> value_W =
        load.body_frame ? V3<S>(c.R_WC * load.value.cast<S>()) : V3<S>(load.value.cast<S>());
    if (load.kind == AppliedLoad::Kind::Torque) {
      M[load.body] += value_W;
    } else {
      F[load.body] += value_W;
      M[load.body] += (c.R_WC * load.p_GP_B.cast<S>()).cross(value_W);
    }
  }
  const auto add = [&](int body, const V3<S>& force, const V3<S>& moment) {
    if (body == kGround) return;
    F[static_cast<std::size_t>(body)] += force;
    M[static_cast<std::size_t>(body)] += moment;
  };
  // A point of a body (or of ground, a world point): its offset from the COM and its velocity.
  const auto point = [&](int body, const Vec3& p_B, V3<S>& r_W, V3<S>& p_W, V3<S>& v_W) {
    if (body == kGround) {
      r_W = p_B.cast<S>();
      p_W = V3<S>::Zero();
      v_W = V3<S>::Zero();
      return;
    }
    const ModalKinematics<S>& c = slot(body);
    p_W = c.R_WC * p_B.cast<S>();
    r_W = c.r_G + p_W;
    v_W = c.v_G + c.omega.cross(p_W);
  };
  for (const LinearSpring& spring : model.springs) {
    V3<S> r_a, p_a, v_a, r_b, p_b, v_b;
    point(spring.body_a, spring.p_A_A, r_a, p_a, v_a);
    point(spring.body_b, spring.p_B_B, r_b, p_b, v_b);
    const V3<S> d = r_b - r_a;
    using std::sqrt;
    const S length = sqrt(d.squaredNorm());
    if (value_of(length) == 0.0) continue;  // no direction: no force (force_elements.hpp)
    const V3<S> u = d / length;
    const S tension =
        spring.stiffness * (length - spring.rest_length) + spring.damping * u.dot(v_b - v_a);
    add(spring.body_b, -tension * u, p_b.cross(-tension * u));
    add(spring.body_a, tension * u, p_a.cross(tension * u));
  }
  for (const TorsionalSpring& spring : model.torsional_springs) {
    const auto omega_of = [&](int body) {
      return body == kGround ? V3<S>(V3<S>::Zero()) : slot(body).omega;
    };
    const auto rotation_of = [&](int body) {
      return body == kGround ? M3<S>(M3<S>::Identity()) : slot(body).R_WC;
    };
    V3<S> M_b;
    if (spring.hinge >= 0) {
      const auto k =
          static_cast<std::size_t>(m.slot_of_joint[static_cast<std::size_t>(spring.hinge)]);
      const TreeJoint& joint = m.tree[k];
      V3<S> axis_W = kin[k].R_WC * joint.axis_C.cast<S>();
      if (joint.reversed) axis_W = -axis_W;
      M_b =
          -(spring.stiffness * (kin[k].angle - spring.rest_angle) + spring.damping * kin[k].u(0)) *
          axis_W;
    } else {
      const V3<S> theta_n =
          rotation_vector<S>(rotation_of(spring.body_b) * spring.R_AB_rest.transpose().cast<S>() *
                             rotation_of(spring.body_a).transpose());
      M_b = -spring.stiffness * theta_n -
            spring.damping * (omega_of(spring.body_b) - omega_of(spring.body_a));
    }
    add(spring.body_b, V3<S>::Zero(), M_b);
    add(spring.body_a, V3<S>::Zero(), -M_b);
  }

  // Newton-Euler projected onto the unknown speeds' rates: M(q) u' = generalised forces.
  MX<S> mass = MX<S>::Zero(unknowns, unknowns);
  VecOf<S> force = VecOf<S>::Zero(unknowns);
  for (std::size_t k = 0; k < n; ++k) {
    const TreeJoint& joint = m.tree[k];
    if (unknown[k] < 0 || joint.model_joint < 0) continue;
    const JointMotor& motor = model.joints[static_cast<std::size_t>(joint.model_joint)].motor;
    if (motor.kind == JointMotor::Kind::Effort && motor.active_at(t0_)) {
      force(unknown[k]) += S(motor.value);
    }
  }
  std::vector<M3X<S>> J_v(n), J_w(n);
  for (std::size_t kb = 0; kb < n; ++kb) {
    const ModalKinematics<S>& c = kin[kb];
    const RigidBody& body = model.bodies[m.tree[kb].child];
    J_v[kb] = M3X<S>::Zero(3, unknowns);
    J_w[kb] = M3X<S>::Zero(3, unknowns);
    for (std::size_t k = kb;;) {
      const TreeJoint& joint = m.tree[k];
      if (unknown[k] >= 0) {
        for (Eigen::Index i = 0; i < joint.nv; ++i) {
          J_w[kb].col(unknown[k] + i) = kin[k].G_w.col(i);
          J_v[kb].col(unknown[k] + i) =
              kin[k].G_w.col(i).cross(c.r_G - kin[k].r_G) + kin[k].G_v.col(i);
        }
      }
      if (joint.parent == kGround) break;
      k = m.slot_of_body[static_cast<std::size_t>(joint.parent)];
    }
    const M3<S> I_W = c.R_WC * body.I_G_B.cast<S>() * c.R_WC.transpose();
    const std::size_t b = m.tree[kb].child;
    mass += body.mass * J_v[kb].transpose() * J_v[kb] + J_w[kb].transpose() * I_W * J_w[kb];
    force += J_v[kb].transpose() * (F[b] - body.mass * c.a0) +
             J_w[kb].transpose() * (M[b] - I_W * c.alpha0 - c.omega.cross(I_W * c.omega));
  }
  VecOf<S> u_dot = unknowns > 0 ? solve_mass(mass, force) : VecOf<S>(0);

  // The contacts' forces lambda hold their rows: G u' + kappa = 0, G the rows' velocity per unit
  // of the unknown speeds (the body's point: J_v - [p]x J_w) and kappa their acceleration with
  // u' = 0 (a_G + alpha x p + omega x p'). With u' = M^-1 (Q + G^T lambda):
  // G M^-1 G^T lambda = -kappa - G M^-1 Q.
  Eigen::Index rows = 0;
  for (const ModalContact& contact : contacts_) rows += contact.rows();
  if (rows > 0) {
    MX<S> G = MX<S>::Zero(rows, unknowns);
    VecOf<S> kappa(rows);
    Eigen::Index row = 0;
    for (const ModalContact& held : contacts_) {
      const PlaneContact& contact = model.contacts[held.contact];
      const auto kb = static_cast<std::size_t>(m.slot_of_body[contact.body]);
      const ModalKinematics<S>& c = kin[kb];
      V3<S> p_GP_W, p_GP_rate_W;
      contact_offset<S>(held, contact.normal_W, c.R_WC, c.omega, p_GP_W, p_GP_rate_W);
      // The body's point P at the contact: its velocity per unit of the speeds (world), and its
      // acceleration with u' = 0.
      const M3X<S> J_P = J_v[kb] - hat_of<S>(p_GP_W) * J_w[kb];
      const V3<S> a_P0 = c.a0 + c.alpha0.cross(p_GP_W) + c.omega.cross(p_GP_rate_W);
      if (held.rolls) {
        G.middleRows(row, 3) = J_P;
        kappa.template segment<3>(row) = a_P0;
      } else {
        const V3<S> n_W = contact.normal_W.cast<S>();
        G.row(row) = n_W.transpose() * J_P;
        kappa(row) = n_W.dot(a_P0);
      }
      row += held.rows();
    }
    MX<S> response(unknowns, rows);  // M^-1 G^T
    for (Eigen::Index j = 0; j < rows; ++j) {
      response.col(j) = solve_mass(mass, VecOf<S>(G.row(j).transpose()));
    }
    const MX<S> schur = G * response;
    // Rows the joints already hold (a point on a hinge's axis) leave it singular.
    const Eigen::SelfAdjointEigenSolver<MatX> definite(values_of(schur));
    if (definite.eigenvalues()(0) <= 1e-12 * definite.eigenvalues()(rows - 1)) {
      throw NotSteady(
          "contacts: a touching point's motion is already held by the joints (or by another "
          "contact): its force is not determined, and a linearisation needs it");
    }
    const VecOf<S> lambda = solve_mass(schur, VecOf<S>(-kappa - G * u_dot));
    u_dot += response * lambda;
    if (contact_forces_W != nullptr) {
      contact_forces_W->clear();
      row = 0;
      for (const ModalContact& held : contacts_) {
        const Vec3& n_W = model.contacts[held.contact].normal_W;
        contact_forces_W->push_back(
            held.rolls
                ? Vec3(value_of(lambda(row)), value_of(lambda(row + 1)), value_of(lambda(row + 2)))
                : Vec3(value_of(lambda(row)) * n_W));
        row += held.rows();
      }
    }
  }

  VecOf<S> z_dot(z.size());
  for (std::size_t k = 0; k < n; ++k) {
    const Eigen::Index po = layout_.position_offset[k];
    const Eigen::Index so = layout_.speed_offset[k];
    if (po < 0) continue;
    const ModalKinematics<S>& c = kin[k];
    const S sign(layout_.sign[k]);
    const auto rates_of = [&](Eigen::Index count) { return u_dot.segment(unknown[k], count); };
    switch (m.tree[k].type) {
      case JointType::Hinge:
      case JointType::Prismatic:
        z_dot(po) = sign * c.u(0);
        z_dot(so) = sign * rates_of(1)(0);
        break;
      case JointType::Ball:
        z_dot.template segment<3>(po) = turn_rate<S>(z.template segment<3>(po), c.u);
        z_dot.template segment<3>(so) = rates_of(3);
        break;
      case JointType::Free:
        z_dot.template segment<3>(po) = c.v_G;
        z_dot.template segment<3>(po + 3) =
            turn_rate<S>(z.template segment<3>(po + 3), V3<S>(c.u.template head<3>()));
        z_dot.template segment<3>(so) = c.a0 + J_v[k] * u_dot;
        z_dot.template segment<3>(so + 3) = rates_of(3);
        break;
      case JointType::Fixed:
        break;
    }
  }
  return z_dot;
}

template <typename S>
VecOf<S> ModalEquations::rates(const VecOf<S>& z) const {
  return evaluate<S>(z, nullptr);
}

std::vector<Vec3> ModalEquations::contact_forces() const {
  std::vector<Vec3> forces;
  evaluate<double>(VecX::Zero(layout_.size()), &forces);
  return forces;
}

template <typename S>
VecOf<S> ModalEquations::constraints(const VecOf<S>& z) const {
  const ArticulatedModel& m = *model_;
  const std::vector<ModalKinematics<S>> kin = kinematics<S>(z);
  Eigen::Index rows = 0;
  for (const ModalContact& contact : contacts_) rows += 1 + contact.rows();
  VecOf<S> values(rows);
  Eigen::Index row = 0;
  for (const ModalContact& held : contacts_) {
    const PlaneContact& contact = m.model.contacts[held.contact];
    const ModalKinematics<S>& c = kin[static_cast<std::size_t>(m.slot_of_body[contact.body])];
    V3<S> p_GP_W, p_GP_rate_W;
    contact_offset<S>(held, contact.normal_W, c.R_WC, c.omega, p_GP_W, p_GP_rate_W);
    const V3<S> n_W = contact.normal_W.cast<S>();
    values(row++) = n_W.dot(c.r_G + p_GP_W - contact.point_W.cast<S>());
    const V3<S> v_P = c.v_G + c.omega.cross(p_GP_W);
    if (held.rolls) {
      values.template segment<3>(row) = v_P;
    } else {
      values(row) = n_W.dot(v_P);
    }
    row += held.rows();
  }
  return values;
}

template <typename S>
VecOf<S> ModalEquations::symmetry_field(const Symmetry& symmetry, const VecOf<S>& z) const {
  const ArticulatedModel& m = *model_;
  VecOf<S> field = VecOf<S>::Zero(z.size());
  for (std::size_t k = 0; k < m.tree.size(); ++k) {
    const TreeJoint& joint = m.tree[k];
    const Eigen::Index po = layout_.position_offset[k];
    const Eigen::Index so = layout_.speed_offset[k];
    if (po < 0) continue;
    const bool turns_body = joint.type == JointType::Ball || joint.type == JointType::Free;
    const Eigen::Index turn = joint.type == JointType::Free ? po + 3 : po;
    const Eigen::Index spin = joint.type == JointType::Free ? so + 3 : so;
    if (symmetry.kind == Symmetry::Kind::BodySpin) {
      if (k != symmetry.tree_joint || !turns_body) continue;
      // R -> R exp(beta [e]x): the turn grows along e, the speeds in its axes turn back.
      const V3<S> e = symmetry.axis.cast<S>();
      const V3<S> r = z.template segment<3>(turn);
      field.template segment<3>(turn) = turn_rate<S>(r, e);
      const V3<S> omega = y0_.segment<3>(joint.v).cast<S>() + z.template segment<3>(spin);
      field.template segment<3>(spin) = -e.cross(omega);
      continue;
    }
    if (joint.parent != kGround) continue;  // the tree below turns with its root
    const V3<S> k_W = symmetry.axis.cast<S>();
    if (turns_body) {
      // R_WC -> exp(beta [k]x) R_WC: in the body's axes a turn about R_WC^T k.
      const V3<S> r = z.template segment<3>(turn);
      const M3<S> R_WC = turned<S>(R_PC0_[k], r);
      field.template segment<3>(turn) = turn_rate<S>(r, V3<S>(R_WC.transpose() * k_W));
      if (joint.type == JointType::Free) {
        const V3<S> r_G = y0_.segment<3>(joint.q).cast<S>() + z.template segment<3>(po);
        field.template segment<3>(po) = k_W.cross(r_G);
        const V3<S> v_G = v_G0_W_[k].cast<S>() + z.template segment<3>(so);
        field.template segment<3>(so) = k_W.cross(v_G);
      }
    } else if (joint.type == JointType::Hinge) {
      const Vec3 axis_W = R_PC0_[k] * joint.axis_C;
      if (axis_W.cross(symmetry.axis).norm() < 1e-12) {
        field(po) = S(layout_.sign[k] * axis_W.dot(symmetry.axis));
      }
    }
  }
  return field;
}

template VecOf<double> ModalEquations::rates<double>(const VecOf<double>&) const;
template VecOf<Dual> ModalEquations::rates<Dual>(const VecOf<Dual>&) const;
template VecOf<double> ModalEquations::constraints<double>(const VecOf<double>&) const;
template VecOf<Dual> ModalEquations::constraints<Dual>(const VecOf<Dual>&) const;
template VecOf<double> ModalEquations::symmetry_field<double>(const Symmetry&,
                                                              const VecOf<double>&) const;
template VecOf<Dual> ModalEquations::symmetry_field<Dual>(const Symmetry&,
                                                          const VecOf<Dual>&) const;

}  // namespace tumble
