#include "tumble/multibody/articulated_formulation.hpp"

#include <cmath>
#include <stdexcept>

#include "tumble/math/rotation.hpp"

namespace tumble {

namespace {

Mat3 rotation_at(const VecX& y, Eigen::Index o) {
  return Quat(y(o), y(o + 1), y(o + 2), y(o + 3)).normalized().toRotationMatrix();
}

// q' = q (x) (0, omega) / 2 for q = (w, x, y, z) stored at o: linear in q, as the OdeSystem
// contract asks.
void write_quaternion_rate(const VecX& y, Eigen::Index o, const Vec3& omega, VecX& dydt) {
  const Vec3 q_vec = y.segment<3>(o + 1);
  dydt(o) = -0.5 * q_vec.dot(omega);
  dydt.segment<3>(o + 1) = 0.5 * (y(o) * omega + q_vec.cross(omega));
}

void write_quaternion(const Mat3& R, Eigen::Index o, VecX& y) {
  Quat q(R);
  q.normalize();
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();
  y.segment<4>(o) << q.w(), q.x(), q.y(), q.z();
}

// The inverse of a joint's symmetric positive definite S^T I^A S (1, 3 or 6 freedoms) through
// fixed-size types, so nothing is allocated.
template <typename Matrix>
void invert_joint_inertia(const Matrix& D, Matrix& D_inv) {
  switch (D.rows()) {
    case 1:
      D_inv(0, 0) = 1.0 / D(0, 0);
      break;
    case 3:
      D_inv = Mat3(D).inverse();
      break;
    case 6:
      D_inv = Mat6(D).ldlt().solve(Mat6::Identity());
      break;
    default:
      throw std::logic_error("a joint has 0, 1, 3 or 6 freedoms");
  }
}

}  // namespace

ArticulatedFormulation::ArticulatedFormulation(Model model)
    : Formulation(std::move(model)), tree_(build_kinematic_tree(model_)) {
  slot_of_body_.assign(body_count(), 0);
  slot_of_joint_.assign(model_.joints.size(), -1);
  Eigen::Index coordinates = 0, speeds = 0;
  for (std::size_t k = 0; k < tree_.size(); ++k) {
    const TreeJoint& joint = tree_[k];
    slot_of_body_[joint.child] = k;
    if (joint.model_joint >= 0)
      slot_of_joint_[static_cast<std::size_t>(joint.model_joint)] = static_cast<int>(k);
    if (joint.type == TreeJoint::Type::Free) quaternion_offsets_.push_back(joint.q + 3);
    if (joint.type == TreeJoint::Type::Ball) quaternion_offsets_.push_back(joint.q);
    coordinates += joint.nq;
    speeds += joint.nv;
  }
  for (std::size_t j = 0; j < model_.joints.size(); ++j) {
    const JointModel& joint = model_.joints[j];
    const bool hinge = joint.type == JointModel::Type::Hinge;
    if (joint.motor.kind != HingeMotor::Kind::None) {
      if (!hinge) throw std::logic_error("a motor needs a hinge; the reader checks this");
      motor_joints_.push_back(j);
    }
    if (std::isfinite(joint.lock_at)) {
      if (!hinge) throw std::logic_error("a lock needs a hinge; the reader checks this");
      lock_joints_.push_back(j);
    }
  }
  speeds_ = coordinates;
  ledger_ = coordinates + speeds;
  const auto entries = static_cast<Eigen::Index>(element_names().size());
  dimension_ = ledger_ + entries;

  work_.resize(tree_.size());
  for (std::size_t k = 0; k < tree_.size(); ++k) {
    const Eigen::Index nv = tree_[k].nv;
    Workspace& w = work_[k];
    w.U.resize(6, nv);
    w.D_inv.resize(nv, nv);
    w.u.resize(nv);
    w.tau.resize(nv);
    w.qdd.resize(nv);
  }
  has_children_.assign(tree_.size(), false);
  tree_root_.assign(tree_.size(), 0);
  for (std::size_t k = 0; k < tree_.size(); ++k) {  // parents come before their children
    const TreeJoint& joint = tree_[k];
    if (joint.parent == kGround) {
      tree_root_[k] = k;
    } else {
      const std::size_t parent = slot_of_body_[static_cast<std::size_t>(joint.parent)];
      has_children_[parent] = true;
      tree_root_[k] = tree_root_[parent];
    }
  }
  states_.resize(body_count());
  rates_.resize(entries);
  set_up_contacts();
}

std::vector<std::string> ArticulatedFormulation::element_names() const {
  std::vector<std::string> names;
  for (const AppliedLoad& load : model_.loads) names.push_back(load.name);
  for (const LinearSpring& spring : model_.springs) names.push_back(spring.name);
  for (const TorsionalSpring& spring : model_.torsional_springs) names.push_back(spring.name);
  for (const std::size_t j : motor_joints_) names.push_back(model_.joints[j].name + ".motor");
  for (const ImpulseLoad& impulse : model_.impulses) names.push_back(impulse.name);
  for (const std::size_t j : lock_joints_) names.push_back(model_.joints[j].name + ".lock");
  for (const PlaneContact& contact : model_.contacts) names.push_back(contact.name);
  return names;
}

bool ArticulatedFormulation::prescribed(std::size_t k, double mode_time) const {
  const TreeJoint& joint = tree_[k];
  if (joint.nv == 0) return true;
  if (joint.model_joint < 0) return false;
  const JointModel& model_joint = model_.joints[static_cast<std::size_t>(joint.model_joint)];
  if (mode_time >= model_joint.lock_at) return true;
  return model_joint.motor.kind == HingeMotor::Kind::Speed &&
         model_joint.motor.active_at(mode_time);
}

void ArticulatedFormulation::calc_kinematics(const VecX& y, bool with_velocities) const {
  for (std::size_t k = 0; k < tree_.size(); ++k) {
    const TreeJoint& joint = tree_[k];
    Workspace& w = work_[k];
    Mat3 R_WP = Mat3::Identity();
    Vec3 r_P_W = Vec3::Zero();
    Vec6 v_P = Vec6::Zero();
    if (joint.parent != kGround) {
      const Workspace& parent = work_[slot_of_body_[static_cast<std::size_t>(joint.parent)]];
      R_WP = parent.R_WC;
      r_P_W = parent.r_G_W;
      v_P = parent.velocity;
    }
    Mat3 R_PC = joint.R_PC0;
    switch (joint.type) {
      case TreeJoint::Type::Free:
        R_PC = rotation_at(y, joint.q + 3);
        break;
      case TreeJoint::Type::Ball:
        R_PC = rotation_at(y, joint.q);
        break;
      case TreeJoint::Type::Hinge:
        R_PC = joint.R_PC0 * rotation_from_axis_angle(joint.axis_C, y(joint.q));
        break;
      case TreeJoint::Type::Fixed:
        R_PC = joint.R_PC0;
        break;
    }
    w.X.E = R_PC.transpose();
    // The child's COM from the parent's, parent axes: out to the joint point, back to the COM.
    w.X.r = joint.type == TreeJoint::Type::Free ? Vec3(y.segment<3>(joint.q))
                                                : Vec3(joint.p_PJ_P - R_PC * joint.p_CJ_C);
    w.R_WC = R_WP * R_PC;
    w.r_G_W = r_P_W + R_WP * w.X.r;
    BodyState& s = states_[joint.child];
    s.r_G = w.r_G_W;
    s.R_WB = w.R_WC;
    if (!with_velocities) continue;
    Vec6 v_joint = Vec6::Zero();
    if (joint.nv > 0) v_joint.noalias() = joint.S * y.segment(joint.v, joint.nv);
    w.velocity = w.X.apply_motion(v_P) + v_joint;
    w.bias = cross_motion(w.velocity, v_joint);
    s.omega_W = w.R_WC * w.velocity.head<3>();
    s.v_G = w.R_WC * w.velocity.tail<3>();
  }
}

void ArticulatedFormulation::accumulate_element_loads(const VecX& y, double mode_time, VecX& rates,
                                                      Eigen::Index offset,
                                                      double* elastic_energy) const {
  for (Workspace& w : work_) w.external.setZero();
  const auto add = [&](int body, const Vec3& F_W, const Vec3& M_G_W) {
    if (body == kGround) return;
    Workspace& w = work_[slot_of_body_[static_cast<std::size_t>(body)]];
    w.external.head<3>() += w.R_WC.transpose() * M_G_W;
    w.external.tail<3>() += w.R_WC.transpose() * F_W;
  };
  double elastic = 0.0;
  Eigen::Index slot = offset;
  for (const AppliedLoad& load : model_.loads) {
    double power = 0.0;
    if (load.active_at(mode_time)) {
      const BodyState& s = states_[load.body];
      const LoadOnBody on_body = calc_load_on_body(load, s.R_WB);
      add(static_cast<int>(load.body), on_body.F_W, on_body.M_G_W);
      // F . v_P + M_G . omega with M_G = p_GP x F: the force's power at its point.
      power = on_body.F_W.dot(s.v_G) + on_body.M_G_W.dot(s.omega_W);
    }
    rates(slot++) = power;
  }
  for (const LinearSpring& spring : model_.springs) {
    const ElementLoad e = calc_spring_load(spring, states_);
    add(spring.body_a, e.F_a_W, e.M_a_W);
    add(spring.body_b, e.F_b_W, e.M_b_W);
    elastic += e.energy;
    rates(slot++) = e.power;
  }
  for (const TorsionalSpring& spring : model_.torsional_springs) {
    double angle = 0.0, rate = 0.0;
    Vec3 axis_W = Vec3::UnitZ();
    if (spring.hinge >= 0) {
      const auto j = static_cast<std::size_t>(spring.hinge);
      const std::size_t k = static_cast<std::size_t>(slot_of_joint_[j]);
      angle = hinge_angle(y, j);
      rate = hinge_rate(y, j);
      axis_W = work_[k].R_WC * tree_[k].axis_C;
      if (tree_[k].reversed) axis_W = -axis_W;
    }
    const ElementLoad e = calc_torsional_spring_load(spring, states_, angle, rate, axis_W);
    add(spring.body_a, e.F_a_W, e.M_a_W);
    add(spring.body_b, e.F_b_W, e.M_b_W);
    elastic += e.energy;
    rates(slot++) = e.power;
  }
  if (elastic_energy != nullptr) *elastic_energy = elastic;
}

void ArticulatedFormulation::solve(double mode_time, bool impulsive, std::size_t only_tree) const {
  const auto skipped = [&](std::size_t k) {
    return only_tree != kEveryTree && tree_root_[k] != only_tree;
  };
  // Pass 1: each body alone.
  for (std::size_t k = 0; k < tree_.size(); ++k) {
    if (skipped(k)) continue;
    const TreeJoint& joint = tree_[k];
    const RigidBody& body = model_.bodies[joint.child];
    Workspace& w = work_[k];
    w.IA = spatial_inertia_about_com(body.mass, body.I_G_B);
    w.pA = -w.external;
    if (!impulsive) {
      w.pA += cross_force(w.velocity, apply_inertia_about_com(body.mass, body.I_G_B, w.velocity));
    }
    w.known = prescribed(k, mode_time);
    if (joint.nv == 0) continue;
    w.tau.setZero();
    if (w.known && !impulsive) w.qdd.setZero();  // locks and speed motors hold their rate
    if (!impulsive && joint.model_joint >= 0) {
      const HingeMotor& motor = model_.joints[static_cast<std::size_t>(joint.model_joint)].motor;
      if (motor.kind == HingeMotor::Kind::Torque && motor.active_at(mode_time) && !w.known) {
        w.tau(0) = motor.value;
      }
    }
  }
  // Pass 2: articulated inertias and bias forces, from the leaves in.
  for (std::size_t k = tree_.size(); k-- > 0;) {
    if (skipped(k)) continue;
    const TreeJoint& joint = tree_[k];
    Workspace& w = work_[k];
    const Vec6 c = impulsive ? Vec6::Zero() : w.bias;
    Mat6 Ia;
    Vec6 pa;
    if (joint.type == TreeJoint::Type::Free && !w.known) {
      // A free joint's S is the identity and its parent is ground: U = D = I^A, and nothing
      // passes on. A body with nothing hung from it has I^A = diag(I_G, M): inverted in closed
      // form.
      w.U = w.IA;
      if (has_children_[k]) {
        invert_joint_inertia(SpeedMatrix(w.IA), w.D_inv);
      } else {
        const RigidBody& body = model_.bodies[joint.child];
        w.D_inv.setZero();
        w.D_inv.topLeftCorner(3, 3) = body.I_G_B_inv;
        w.D_inv.bottomRightCorner(3, 3) = Mat3::Identity() / body.mass;
      }
      w.u = w.tau - w.pA;
      continue;
    }
    if (w.known) {
      Vec6 a_joint = c;
      if (joint.nv > 0) a_joint.noalias() += joint.S * w.qdd;
      Ia = w.IA;
      pa = w.pA + w.IA * a_joint;
    } else {
      w.U.noalias() = w.IA * joint.S;
      const SpeedMatrix D = joint.S.transpose() * w.U;
      invert_joint_inertia(D, w.D_inv);
      w.u = w.tau;
      w.u.noalias() -= joint.S.transpose() * w.pA;
      Ia = w.IA;
      Ia.noalias() -= w.U * (w.D_inv * w.U.transpose());
      pa = w.pA + Ia * c;
      pa.noalias() += w.U * (w.D_inv * w.u);
    }
    if (joint.parent == kGround) continue;
    Workspace& parent = work_[slot_of_body_[static_cast<std::size_t>(joint.parent)]];
    const Mat6 X = w.X.matrix();
    parent.IA.noalias() += X.transpose() * Ia * X;
    parent.pA += w.X.transpose_apply_force(pa);
  }
  // Pass 3: accelerations from ground out; ground accelerates at -g so that gravity needs no
  // force of its own (and the joint forces below include the weight they carry).
  Vec6 a_ground = Vec6::Zero();
  if (!impulsive) a_ground.tail<3>() = -model_.gravity_W;
  for (std::size_t k = 0; k < tree_.size(); ++k) {
    if (skipped(k)) continue;
    const TreeJoint& joint = tree_[k];
    Workspace& w = work_[k];
    const Vec6& a_P =
        joint.parent == kGround
            ? a_ground
            : work_[slot_of_body_[static_cast<std::size_t>(joint.parent)]].acceleration;
    Vec6 a = w.X.apply_motion(a_P);
    if (!impulsive) a += w.bias;
    if (w.known) {
      if (joint.nv > 0) {
        a.noalias() += joint.S * w.qdd;
        const Vec6 f = w.IA * a + w.pA;
        w.tau.noalias() = joint.S.transpose() * f;
      }
    } else {
      w.qdd.noalias() = w.D_inv * (w.u - w.U.transpose() * a);
      a.noalias() += joint.S * w.qdd;
    }
    w.acceleration = a;
  }
}

void ArticulatedFormulation::derivative(double t, const VecX& y, VecX& dydt) const {
  time_now_ = t;
  calc_kinematics(y, true);
  accumulate_element_loads(y, schedule_time_, dydt, ledger_, nullptr);
  solve_with_contacts(schedule_time_);
  for (std::size_t k = 0; k < tree_.size(); ++k) {
    const TreeJoint& joint = tree_[k];
    const Workspace& w = work_[k];
    switch (joint.type) {
      case TreeJoint::Type::Free:
        dydt.segment<3>(joint.q) = states_[joint.child].v_G;
        write_quaternion_rate(y, joint.q + 3, y.segment<3>(joint.v), dydt);
        break;
      case TreeJoint::Type::Ball:
        write_quaternion_rate(y, joint.q, y.segment<3>(joint.v), dydt);
        break;
      case TreeJoint::Type::Hinge:
        dydt(joint.q) = y(joint.v);
        break;
      case TreeJoint::Type::Fixed:
        break;
    }
    if (joint.nv > 0) dydt.segment(joint.v, joint.nv) = w.qdd;
  }
  write_joint_powers(y, dydt, ledger_);
  write_contact_powers(dydt, ledger_);
}

Eigen::Index ArticulatedFormulation::first_motor_entry() const {
  return static_cast<Eigen::Index>(model_.loads.size() + model_.springs.size() +
                                   model_.torsional_springs.size());
}

void ArticulatedFormulation::write_joint_powers(const VecX& y, VecX& rates,
                                                Eigen::Index offset) const {
  // Motors work at tau theta'; impulses and locks act only at their instants (and contacts' entries
  // are written by write_contact_powers).
  Eigen::Index entry = offset + first_motor_entry();
  for (const std::size_t j : motor_joints_) {
    const std::size_t k = static_cast<std::size_t>(slot_of_joint_[j]);
    rates(entry++) = work_[k].tau(0) * y(tree_[k].v);
  }
  for (; entry < rates.size(); ++entry) rates(entry) = 0.0;
}

void ArticulatedFormulation::pack(std::span<const BodyState> states, VecX& y) const {
  y.setZero();
  for (const TreeJoint& joint : tree_) {
    const BodyState& child = states[joint.child];
    const BodyState& parent = state_or_ground(states, joint.parent);
    const Mat3 R_PC = parent.R_WB.transpose() * child.R_WB;
    const Vec3 omega_rel_C = child.R_WB.transpose() * (child.omega_W - parent.omega_W);
    switch (joint.type) {
      case TreeJoint::Type::Free:
        y.segment<3>(joint.q) = child.r_G;
        write_quaternion(child.R_WB, joint.q + 3, y);
        y.segment<3>(joint.v) = child.R_WB.transpose() * child.omega_W;
        y.segment<3>(joint.v + 3) = child.R_WB.transpose() * child.v_G;
        break;
      case TreeJoint::Type::Ball:
        write_quaternion(R_PC, joint.q, y);
        y.segment<3>(joint.v) = omega_rel_C;
        break;
      case TreeJoint::Type::Hinge:
        y(joint.q) = joint.axis_C.dot(log_so3(joint.R_PC0.transpose() * R_PC));
        y(joint.v) = joint.axis_C.dot(omega_rel_C);
        break;
      case TreeJoint::Type::Fixed:
        break;
    }
  }
}

void ArticulatedFormulation::unpack_all(const VecX& y, std::span<BodyState> states) const {
  calc_kinematics(y, true);
  for (std::size_t i = 0; i < states.size(); ++i) states[i] = states_[i];
}

BodyState ArticulatedFormulation::unpack(const VecX& y, std::size_t body) const {
  calc_kinematics(y, true);
  return states_[body];
}

double ArticulatedFormulation::hinge_angle(const VecX& y, std::size_t joint) const {
  return y(tree_[static_cast<std::size_t>(slot_of_joint_[joint])].q);
}

double ArticulatedFormulation::hinge_rate(const VecX& y, std::size_t joint) const {
  return y(tree_[static_cast<std::size_t>(slot_of_joint_[joint])].v);
}

double ArticulatedFormulation::kinetic_energy() const {
  double T = 0.0;
  for (std::size_t k = 0; k < tree_.size(); ++k) {
    const RigidBody& body = model_.bodies[tree_[k].child];
    const Vec6& v = work_[k].velocity;
    T += 0.5 * v.dot(apply_inertia_about_com(body.mass, body.I_G_B, v));
  }
  return T;
}

Vec3 ArticulatedFormulation::angular_momentum_about_origin() const {
  Vec3 L = Vec3::Zero();
  for (std::size_t i = 0; i < body_count(); ++i) {
    L += calc_angular_momentum_about_point_W(model_.bodies[i], states_[i], Vec3::Zero());
  }
  return L;
}

JointReaction ArticulatedFormulation::reaction_of(std::size_t model_joint) const {
  const std::size_t k = static_cast<std::size_t>(slot_of_joint_[model_joint]);
  const TreeJoint& joint = tree_[k];
  const Workspace& w = work_[k];
  // What the parent exerts on the child's subtree across the joint: I^A a + p^A, child axes,
  // about the child's COM; moved to the joint point.
  const Vec6 f = w.IA * w.acceleration + w.pA;
  const Vec3 F_C = f.tail<3>();
  const Vec3 M_J_C = f.head<3>() - joint.p_CJ_C.cross(F_C);
  const double sign = joint.reversed ? -1.0 : 1.0;
  return {sign * (w.R_WC * F_C), sign * (w.R_WC * M_J_C)};
}

void ArticulatedFormulation::calc_row_extras(double t, const VecX& y, RowExtras& extras) const {
  time_now_ = t;
  calc_kinematics(y, true);
  accumulate_element_loads(y, schedule_time_, rates_, 0, &extras.elastic_energy);
  solve_with_contacts(schedule_time_);
  extras.joints.resize(model_.joints.size());
  for (std::size_t j = 0; j < model_.joints.size(); ++j) extras.joints[j] = reaction_of(j);
  extras.contacts.resize(model_.contacts.size());
  for (std::size_t c = 0; c < model_.contacts.size(); ++c) {
    const ContactNow& now = contact_now_[c];
    ContactOutput& out = extras.contacts[c];
    out.mode = static_cast<int>(contact_status_[c].mode);
    out.normal_force = now.normal_force;
    out.friction_W = now.friction_W;
    out.slip_speed = now.slip_W.norm();
  }
  write_joint_powers(y, rates_, 0);
  write_contact_powers(rates_, 0);
  extras.elements.resize(static_cast<std::size_t>(rates_.size()));
  for (Eigen::Index i = 0; i < rates_.size(); ++i) {
    extras.elements[static_cast<std::size_t>(i)] = {rates_(i), y(ledger_ + i)};
  }
}

void ArticulatedFormulation::begin(double t0, const VecX& y) {
  Formulation::begin(t0, y);
  time_now_ = t0;
  jumps_.clear();
  begin_contacts(t0, y);
}

void ArticulatedFormulation::at_breakpoint(double t, VecX& y) {
  schedule_time_ = t;
  time_now_ = t;
  apply_jumps_at(t, y);
  reclassify_contacts(t, y);
}

void ArticulatedFormulation::apply_jumps_at(double t, VecX& y) {
  calc_kinematics(y, true);
  for (Workspace& w : work_) w.external.setZero();

  // Impulses now: on the body, about its COM, child axes.
  std::string what;
  const auto note = [&](const std::string& item) { what += (what.empty() ? "" : ", ") + item; };
  for (const ImpulseLoad& impulse : model_.impulses) {
    if (impulse.time != t) continue;
    Workspace& w = work_[slot_of_body_[impulse.body]];
    const Vec3 J_W = impulse.body_frame ? Vec3(w.R_WC * impulse.value) : impulse.value;
    w.external.head<3>() += w.R_WC.transpose() * (w.R_WC * impulse.p_GP_B).cross(J_W);
    w.external.tail<3>() += w.R_WC.transpose() * J_W;
    note("impulse " + impulse.name);
  }
  // Hinges that lock or whose speed motor starts now jump to their rate; the other prescribed
  // joints keep theirs.
  for (std::size_t k = 0; k < tree_.size(); ++k) {
    const TreeJoint& joint = tree_[k];
    Workspace& w = work_[k];
    if (joint.nv == 0 || !prescribed(k, t)) continue;
    w.qdd.setZero();
    const JointModel& model_joint = model_.joints[static_cast<std::size_t>(joint.model_joint)];
    const double rate = y(joint.v);
    if (model_joint.lock_at == t) {
      w.qdd(0) = -rate;
      note("lock " + model_joint.name);
    } else if (t < model_joint.lock_at && model_joint.motor.kind == HingeMotor::Kind::Speed &&
               model_joint.motor.from == t) {
      w.qdd(0) = model_joint.motor.value - rate;
      note("motor " + model_joint.name + " starts");
    }
  }
  if (what.empty()) return;

  JumpRecord record;
  record.t = t;
  record.what = what;
  record.kinetic_energy_before = kinetic_energy();
  record.angular_momentum_before_W = angular_momentum_about_origin();
  std::vector<BodyState> before(states_);
  solve(t, true);
  for (std::size_t j = 0; j < model_.joints.size(); ++j) {
    record.reaction_impulses.push_back(reaction_of(j));
  }
  // Work at an instant: the impulse times the mean of the velocities before and after it, for
  // impulses on body points and for the angular impulses of locks and starting motors alike.
  std::vector<double> rate_before(tree_.size(), 0.0);
  for (std::size_t k = 0; k < tree_.size(); ++k) {
    const TreeJoint& joint = tree_[k];
    if (joint.nv == 0) continue;
    if (joint.type == TreeJoint::Type::Hinge) rate_before[k] = y(joint.v);
    y.segment(joint.v, joint.nv) += work_[k].qdd;
  }
  calc_kinematics(y, true);
  record.kinetic_energy_after = kinetic_energy();
  record.angular_momentum_after_W = angular_momentum_about_origin();

  Eigen::Index slot = ledger_ + first_motor_entry();
  for (const std::size_t j : motor_joints_) {
    const std::size_t k = static_cast<std::size_t>(slot_of_joint_[j]);
    const JointModel& joint = model_.joints[j];
    if (joint.motor.kind == HingeMotor::Kind::Speed && joint.motor.from == t && t < joint.lock_at) {
      y(slot) += work_[k].tau(0) * 0.5 * (rate_before[k] + y(tree_[k].v));
    }
    ++slot;
  }
  for (const ImpulseLoad& impulse : model_.impulses) {
    if (impulse.time == t) {
      const BodyState& b0 = before[impulse.body];
      const BodyState& b1 = states_[impulse.body];
      const Vec3 J_W = impulse.body_frame ? Vec3(b0.R_WB * impulse.value) : impulse.value;
      const Vec3 p_W = b0.R_WB * impulse.p_GP_B;
      y(slot) += J_W.dot(0.5 * (velocity_of_point(b0.v_G, b0.omega_W, p_W) +
                                velocity_of_point(b1.v_G, b1.omega_W, p_W)));
    }
    ++slot;
  }
  for (const std::size_t j : lock_joints_) {
    const std::size_t k = static_cast<std::size_t>(slot_of_joint_[j]);
    if (model_.joints[j].lock_at == t) y(slot) += work_[k].tau(0) * 0.5 * rate_before[k];
    ++slot;
  }
  jumps_.push_back(std::move(record));
}

}  // namespace tumble
